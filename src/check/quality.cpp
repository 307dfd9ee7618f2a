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
#include <memory>
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

namespace {

// measure_quality's tets go through blocks of this many, their corners by
// coordinate, so that one loop the compiler vectorizes takes each tet's
// measures (the expressions of TetFrame, extreme_dihedrals,
// radius_ratio_of and edge_ratio_of in the same order: the same bits) and
// a second adds them up in tet order.
constexpr size_t kShapeBlock = 256;

struct ShapeBlock {
  size_t n = 0;
  double corner[12][kShapeBlock];  // coordinate i of corner j at 3 j + i
  double cos_lo[kShapeBlock], cos_hi[kShapeBlock], lo[kShapeBlock], hi[kShapeBlock], faces[kShapeBlock];
  double radius_ratio[kShapeBlock], edge_ratio[kShapeBlock], six_volume[kShapeBlock];
  const double* points[kShapeBlock][4];  // the tet's corners, for the mesh's extreme angles
};

void measure_block(ShapeBlock& s) {
  const double* __restrict x0 = s.corner[0];
  const double* __restrict y0 = s.corner[1];
  const double* __restrict z0 = s.corner[2];
  const double* __restrict x1 = s.corner[3];
  const double* __restrict y1 = s.corner[4];
  const double* __restrict z1 = s.corner[5];
  const double* __restrict x2 = s.corner[6];
  const double* __restrict y2 = s.corner[7];
  const double* __restrict z2 = s.corner[8];
  const double* __restrict x3 = s.corner[9];
  const double* __restrict y3 = s.corner[10];
  const double* __restrict z3 = s.corner[11];
  double* __restrict cos_lo = s.cos_lo;
  double* __restrict cos_hi = s.cos_hi;
  double* __restrict lo = s.lo;
  double* __restrict hi = s.hi;
  double* __restrict faces = s.faces;
  double* __restrict radius_ratio = s.radius_ratio;
  double* __restrict edge_ratio = s.edge_ratio;
  double* __restrict six_volume = s.six_volume;
  for (size_t k = 0; k < s.n; ++k) {
    const double ax = x1[k] - x0[k], ay = y1[k] - y0[k], az = z1[k] - z0[k];
    const double bx = x2[k] - x0[k], by = y2[k] - y0[k], bz = z2[k] - z0[k];
    const double cx = x3[k] - x0[k], cy = y3[k] - y0[k], cz = z3[k] - z0[k];
    const double ux = cx - ax, uy = cy - ay, uz = cz - az;  // c - a
    const double wx = bx - ax, wy = by - ay, wz = bz - az;  // b - a
    const double n[4][3] = {{uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx},
                            {by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx},
                            {cy * az - cz * ay, cz * ax - cx * az, cx * ay - cy * ax},
                            {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx}};
    double len[4];
    for (int f = 0; f < 4; ++f) len[f] = std::sqrt(n[f][0] * n[f][0] + n[f][1] * n[f][1] + n[f][2] * n[f][2]);
    faces[k] = (len[0] > 0) & (len[1] > 0) & (len[2] > 0) & (len[3] > 0) ? 1.0 : 0.0;
    double low = -2, high = 2, low_pair = 0, high_pair = 0;
    for (int e = 0; e < 6; ++e) {
      const int f = kFacePairs[e][0], g = kFacePairs[e][1];
      const double cosine = -(n[f][0] * n[g][0] + n[f][1] * n[g][1] + n[f][2] * n[g][2]) / (len[f] * len[g]);
      low_pair = cosine > low ? e : low_pair;
      low = cosine > low ? cosine : low;
      high_pair = cosine < high ? e : high_pair;
      high = cosine < high ? cosine : high;
    }
    cos_lo[k] = low, cos_hi[k] = high, lo[k] = low_pair, hi[k] = high_pair;
    const double d = ax * n[1][0] + ay * n[1][1] + az * n[1][2];
    six_volume[k] = d;
    const double area_sum = len[0] + len[1] + len[2] + len[3];
    const double aa = ax * ax + ay * ay + az * az, bb = bx * bx + by * by + bz * bz, cc = cx * cx + cy * cy + cz * cz;
    const double ix = bb * n[2][0] + cc * n[3][0], iy = bb * n[2][1] + cc * n[3][1], iz = bb * n[2][2] + cc * n[3][2];
    const double sx = aa * n[1][0] + ix, sy = aa * n[1][1] + iy, sz = aa * n[1][2] + iz;
    const double denominator = area_sum * std::sqrt(sx * sx + sy * sy + sz * sz);
    const double ratio = 6 * d * d / denominator;
    radius_ratio[k] = (d != 0 && denominator > 0) ? (ratio < 1.0 ? ratio : 1.0) : 0.0;
    const double ex = bx - ax, ey = by - ay, ez = bz - az;  // b - a
    const double fx = cx - ax, fy = cy - ay, fz = cz - az;  // c - a
    const double gx = cx - bx, gy = cy - by, gz = cz - bz;  // c - b
    const double edges[6] = {aa, bb, cc, ex * ex + ey * ey + ez * ez, fx * fx + fy * fy + fz * fz,
                             gx * gx + gy * gy + gz * gz};
    double shortest = edges[0], longest = edges[0];
    for (int e = 1; e < 6; ++e) {
      shortest = edges[e] < shortest ? edges[e] : shortest;
      longest = edges[e] > longest ? edges[e] : longest;
    }
    edge_ratio[k] = shortest > 0 ? std::sqrt(longest / shortest) : std::numeric_limits<double>::infinity();
  }
}

// Puts a tet's corners in the block's next column; true when that fills it.
bool add_to_block(ShapeBlock& s, const double* const p[4]) {
  for (int j = 0; j < 4; ++j) {
    s.points[s.n][j] = p[j];
    for (int i = 0; i < 3; ++i) s.corner[3 * j + i][s.n] = p[j][i];
  }
  return ++s.n == kShapeBlock;
}

}  // namespace

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
  const auto block = std::make_unique<ShapeBlock>();
  ShapeBlock& s = *block;
  const auto add_up = [&] {
    measure_block(s);
    for (size_t k = 0; k < s.n; ++k) {
      if (s.faces[k] != 0) {
        q.dihedral_under_5 += s.cos_lo[k] > cos5;
        q.dihedral_under_10 += s.cos_lo[k] > cos10;
        q.dihedral_under_20 += s.cos_lo[k] > cos20;
        if (s.cos_lo[k] > cos_min_angle || s.cos_hi[k] < cos_max_angle) {
          const double* const* p = s.points[k];
          const TetFrame f(p[0], p[1], p[2], p[3]);
          if (s.cos_lo[k] > cos_min_angle) {
            cos_min_angle = s.cos_lo[k];
            const int e = static_cast<int>(s.lo[k]);
            min_pair[0] = f.n[kFacePairs[e][0]];
            min_pair[1] = f.n[kFacePairs[e][1]];
          }
          if (s.cos_hi[k] < cos_max_angle) {
            cos_max_angle = s.cos_hi[k];
            const int e = static_cast<int>(s.hi[k]);
            max_pair[0] = f.n[kFacePairs[e][0]];
            max_pair[1] = f.n[kFacePairs[e][1]];
          }
        }
      } else {
        flat = true;
        ++q.dihedral_under_5;
        ++q.dihedral_under_10;
        ++q.dihedral_under_20;
      }
      const double rr = s.radius_ratio[k];
      rr_min = std::min(rr_min, rr);
      rr_sum += rr;
      radius_ratio.push_back(rr);
      edge_ratio_max = std::max(edge_ratio_max, s.edge_ratio[k]);
      edge_ratio_sum += s.edge_ratio[k];
      volume.add(s.six_volume[k] / 6);
    }
    s.n = 0;
  };
  for (size_t t = 0; t < num_tets; ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    if (v[0] >= num_vertices || v[1] >= num_vertices || v[2] >= num_vertices ||
        v[3] >= num_vertices)
      continue;
    const double* p[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
    if (!finite_point(p[0]) || !finite_point(p[1]) || !finite_point(p[2]) || !finite_point(p[3]))
      continue;
    if (add_to_block(s, p)) add_up();
  }
  add_up();

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

std::vector<uint8_t> tets_under_angle(const TetMesh& mesh, double degrees) {
  const double cos_limit = std::cos(degrees / kDegreesPerRadian);
  std::vector<uint8_t> under(mesh.num_tets(), 0);
  const auto block = std::make_unique<ShapeBlock>();
  ShapeBlock& s = *block;
  size_t first = 0;  // the block's first tet: every tet goes in, in order
  const auto mark = [&] {
    measure_block(s);
    for (size_t k = 0; k < s.n; ++k) under[first + k] = s.faces[k] == 0 || s.cos_lo[k] > cos_limit;
    first += s.n;
    s.n = 0;
  };
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    const double* p[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
    if (add_to_block(s, p)) mark();
  }
  mark();
  return under;
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
