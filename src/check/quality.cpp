// Tet shape quality (see quality.hpp). For a tet p0..p3 with edge vectors
// a = p1-p0, b = p2-p0, c = p3-p0, the face normals (twice the area, all
// pointing to the same side, inward for a positive tet) are
//   n0 = (c-a)x(b-a), n1 = bxc, n2 = cxa, n3 = axb   (n_k opposite p_k),
// D = a.(bxc) = 6 * signed volume, and the circumcentre relative to p0 is
//   (|a|^2 n1 + |b|^2 n2 + |c|^2 n3) / (2D)
// (Shewchuk, "Lecture notes on geometric robustness"): only differences of
// input points and no cancelling sums of squares. With S = |n0|+..+|n3|
// (twice the total face area), inradius r = |D|/S and circumradius
// R = |N|/(2|D|), so 3r/R = 6 D^2 / (S |N|).
// The dihedral angle at the edge shared by the faces opposite p_k and p_l is
// atan2(|n_k x n_l|, -n_k.n_l): accurate for angles near 0 and 180 alike.
#include "check/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "check/compensated_sum.hpp"

namespace partet {
namespace {

struct V3 {
  double x, y, z;
};
V3 sub(const double* p, const double* q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
V3 sub(V3 p, V3 q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
V3 cross(V3 u, V3 v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double dot(V3 u, V3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
double norm(V3 u) { return std::sqrt(dot(u, u)); }
V3 axpy(double s, V3 u, V3 v) { return {s * u.x + v.x, s * u.y + v.y, s * u.z + v.z}; }

// The six dihedral angles as pairs of opposite-face indices.
constexpr int kFacePairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

double dihedral(V3 nk, V3 nl) { return std::atan2(norm(cross(nk, nl)), -dot(nk, nl)); }

// Edge vectors from p0, the face normals of the file comment and their
// lengths.
struct TetFrame {
  V3 a, b, c, n[4];
  double len[4];
  TetFrame(const double* p0, const double* p1, const double* p2, const double* p3)
      : a(sub(p1, p0)),
        b(sub(p2, p0)),
        c(sub(p3, p0)),
        n{cross(sub(c, a), sub(b, a)), cross(b, c), cross(c, a), cross(a, b)},
        len{norm(n[0]), norm(n[1]), norm(n[2]), norm(n[3])} {}
};

// The kFacePairs indices of the smallest (lo) and largest (hi) dihedral
// angle and their cosines (no trigonometry); false when a face has zero
// area.
struct ExtremeDihedrals {
  int lo = 0, hi = 0;
  double cos_lo = -2, cos_hi = 2;
};
bool extreme_dihedrals(const TetFrame& f, ExtremeDihedrals& x) {
  const double* len = f.len;
  if (!(len[0] > 0 && len[1] > 0 && len[2] > 0 && len[3] > 0)) return false;
  for (int e = 0; e < 6; ++e) {
    const int k = kFacePairs[e][0], l = kFacePairs[e][1];
    const double cosine = -dot(f.n[k], f.n[l]) / (len[k] * len[l]);
    if (cosine > x.cos_lo) x.cos_lo = cosine, x.lo = e;
    if (cosine < x.cos_hi) x.cos_hi = cosine, x.hi = e;
  }
  return true;
}

double radius_ratio_of(const TetFrame& f) {
  const V3 &a = f.a, &b = f.b, &c = f.c;
  const V3(&n)[4] = f.n;
  const double d = dot(a, n[1]);
  const double area_sum = f.len[0] + f.len[1] + f.len[2] + f.len[3];
  const double aa = dot(a, a), bb = dot(b, b), cc = dot(c, c);
  // 6 V times the circumcentre (relative to p0), doubled.
  const V3 centre2d = axpy(aa, n[1], axpy(bb, n[2], V3{cc * n[3].x, cc * n[3].y, cc * n[3].z}));
  const double denominator = area_sum * norm(centre2d);
  return (d != 0 && denominator > 0) ? std::min(1.0, 6 * d * d / denominator) : 0.0;
}

double edge_ratio_of(const TetFrame& f) {
  const V3 &a = f.a, &b = f.b, &c = f.c;
  const double edges[6] = {dot(a, a), dot(b, b), dot(c, c), dot(sub(b, a), sub(b, a)), dot(sub(c, a), sub(c, a)),
                           dot(sub(c, b), sub(c, b))};
  auto [shortest, longest] = std::minmax_element(edges, edges + 6);
  return *shortest > 0 ? std::sqrt(*longest / *shortest) : std::numeric_limits<double>::infinity();
}

bool finite_point(const double* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Share of tets under 10 degrees, as the fraction under / tets.
bool share_no_higher(const QualityStats& x, const QualityStats& y) {
  return x.dihedral_under_10 * y.tets <= y.dihedral_under_10 * x.tets;
}

}  // namespace

double tet_radius_ratio(const double* p0, const double* p1, const double* p2, const double* p3) {
  return radius_ratio_of(TetFrame(p0, p1, p2, p3));
}

TetShape tet_shape(const double* p0, const double* p1, const double* p2, const double* p3) {
  TetShape s;
  const TetFrame f(p0, p1, p2, p3);
  s.volume = dot(f.a, f.n[1]) / 6;
  ExtremeDihedrals x;
  if (extreme_dihedrals(f, x)) {
    s.min_dihedral_rad = dihedral(f.n[kFacePairs[x.lo][0]], f.n[kFacePairs[x.lo][1]]);
    s.max_dihedral_rad = dihedral(f.n[kFacePairs[x.hi][0]], f.n[kFacePairs[x.hi][1]]);
  } else {
    s.min_dihedral_rad = 0;
    s.max_dihedral_rad = std::numbers::pi;
  }
  s.radius_ratio = radius_ratio_of(f);
  s.edge_ratio = edge_ratio_of(f);
  return s;
}

double tet_min_dihedral(const double* p0, const double* p1, const double* p2, const double* p3) {
  const TetFrame f(p0, p1, p2, p3);
  ExtremeDihedrals x;
  if (!extreme_dihedrals(f, x)) return 0;
  return dihedral(f.n[kFacePairs[x.lo][0]], f.n[kFacePairs[x.lo][1]]);
}

bool widest_dihedral_faces(const double* p0, const double* p1, const double* p2, const double* p3, int& k,
                           int& l) {
  const TetFrame f(p0, p1, p2, p3);
  ExtremeDihedrals x;
  if (!extreme_dihedrals(f, x)) return false;
  k = kFacePairs[x.hi][0];
  l = kFacePairs[x.hi][1];
  return true;
}

QualityStats measure_quality(const TetMesh& mesh) {
  QualityStats q;
  const size_t num_vertices = mesh.num_vertices();
  const size_t num_tets = mesh.num_tets();
  std::vector<double> radius_ratio;
  radius_ratio.reserve(num_tets);

  // A tet's smallest dihedral angle is under d degrees exactly when the
  // cosine of it exceeds cos(d): the angles are taken (atan2) only for the
  // mesh's smallest and largest, at the end.
  const double cos5 = std::cos(5 / kDegreesPerRadian), cos10 = std::cos(10 / kDegreesPerRadian),
               cos20 = std::cos(20 / kDegreesPerRadian);
  double cos_min_angle = -2, cos_max_angle = 2;
  V3 min_pair[2] = {}, max_pair[2] = {};
  bool flat = false;  // a tet with a zero-area face: angles 0 and 180
  double rr_min = 1, edge_ratio_max = 0;
  double rr_sum = 0, edge_ratio_sum = 0;
  CompensatedSum volume;
  for (size_t t = 0; t < num_tets; ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    if (v[0] >= num_vertices || v[1] >= num_vertices || v[2] >= num_vertices ||
        v[3] >= num_vertices)
      continue;
    const double* p[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
    if (!finite_point(p[0]) || !finite_point(p[1]) || !finite_point(p[2]) || !finite_point(p[3]))
      continue;
    const TetFrame f(p[0], p[1], p[2], p[3]);
    ExtremeDihedrals x;
    if (extreme_dihedrals(f, x)) {
      q.dihedral_under_5 += x.cos_lo > cos5;
      q.dihedral_under_10 += x.cos_lo > cos10;
      q.dihedral_under_20 += x.cos_lo > cos20;
      if (x.cos_lo > cos_min_angle) {
        cos_min_angle = x.cos_lo;
        min_pair[0] = f.n[kFacePairs[x.lo][0]];
        min_pair[1] = f.n[kFacePairs[x.lo][1]];
      }
      if (x.cos_hi < cos_max_angle) {
        cos_max_angle = x.cos_hi;
        max_pair[0] = f.n[kFacePairs[x.hi][0]];
        max_pair[1] = f.n[kFacePairs[x.hi][1]];
      }
    } else {
      flat = true;
      ++q.dihedral_under_5;
      ++q.dihedral_under_10;
      ++q.dihedral_under_20;
    }
    const double rr = radius_ratio_of(f);
    rr_min = std::min(rr_min, rr);
    rr_sum += rr;
    radius_ratio.push_back(rr);
    const double edge_ratio = edge_ratio_of(f);
    edge_ratio_max = std::max(edge_ratio_max, edge_ratio);
    edge_ratio_sum += edge_ratio;
    volume.add(dot(f.a, f.n[1]) / 6);
  }

  q.tets = radius_ratio.size();
  if (q.tets == 0) return q;
  q.min_dihedral_deg = flat || cos_min_angle == -2 ? 0 : dihedral(min_pair[0], min_pair[1]) * kDegreesPerRadian;
  q.max_dihedral_deg = flat || cos_max_angle == 2 ? 180 : dihedral(max_pair[0], max_pair[1]) * kDegreesPerRadian;
  q.radius_ratio_min = rr_min;
  q.radius_ratio_mean = rr_sum / static_cast<double>(q.tets);
  // The 1st percentile: the value at rank floor(0.01 (n-1)) in ascending order.
  auto rank = radius_ratio.begin() + static_cast<std::ptrdiff_t>((q.tets - 1) / 100);
  std::nth_element(radius_ratio.begin(), rank, radius_ratio.end());
  q.radius_ratio_p01 = *rank;
  q.edge_ratio_max = edge_ratio_max;
  q.edge_ratio_mean = edge_ratio_sum / static_cast<double>(q.tets);
  q.volume = volume.value();
  return q;
}

void to_json(nlohmann::json& j, const QualityStats& q) {
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  j = nlohmann::json{{"tets", q.tets},
                     {"min_dihedral_deg", number(q.min_dihedral_deg)},
                     {"max_dihedral_deg", number(q.max_dihedral_deg)},
                     {"radius_ratio_min", number(q.radius_ratio_min)},
                     {"radius_ratio_mean", number(q.radius_ratio_mean)},
                     {"radius_ratio_p01", number(q.radius_ratio_p01)},
                     {"dihedral_under_5", q.dihedral_under_5},
                     {"dihedral_under_10", q.dihedral_under_10},
                     {"dihedral_under_20", q.dihedral_under_20},
                     {"edge_ratio_max", number(q.edge_ratio_max)},
                     {"edge_ratio_mean", number(q.edge_ratio_mean)},
                     {"volume", number(q.volume)}};
}

bool better_quality(const QualityStats& x, const QualityStats& y) {
  if (x.tets == 0 || y.tets == 0) return false;
  const bool no_worse = x.min_dihedral_deg >= y.min_dihedral_deg && share_no_higher(x, y) &&
                        x.radius_ratio_mean >= y.radius_ratio_mean - kRadiusRatioSlack;
  const bool gains = x.min_dihedral_deg > y.min_dihedral_deg || !share_no_higher(y, x) ||
                     x.radius_ratio_mean > y.radius_ratio_mean;
  return no_worse && gains;
}

}  // namespace partet
