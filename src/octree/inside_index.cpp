// Ray parity with triangles binned by their projection along the ray (see
// inside_index.hpp).
#include "octree/inside_index.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/intersections.hpp"
#include "core/predicates.hpp"
#include "surface/shell_nesting.hpp"

namespace partet {

namespace {

// The ray direction: not along an axis or a simple diagonal (the first of
// shell_nesting's directions).
constexpr double kDir[3] = {1.0, 0.3183098861837907, 0.2718281828459045};

enum class Crossing { kNone, kProper, kDegenerate };

// How the segment pq meets the closed triangle abc, exactly: through its
// interior (proper), through its boundary or in its plane (degenerate), or not.
Crossing crossing(const double* p, const double* q, const double* a, const double* b, const double* c) {
  const int s1 = orient3d(a, b, c, p), s2 = orient3d(a, b, c, q);
  if (s1 == s2 && s1 != 0) return Crossing::kNone;
  if (s1 == 0 || s2 == 0) return segment_triangle_intersect(p, q, a, b, c) ? Crossing::kDegenerate : Crossing::kNone;
  const int t1 = orient3d(p, q, a, b), t2 = orient3d(p, q, b, c), t3 = orient3d(p, q, c, a);
  const bool pos = t1 > 0 || t2 > 0 || t3 > 0;
  const bool neg = t1 < 0 || t2 < 0 || t3 < 0;
  if (pos && neg) return Crossing::kNone;
  if (t1 != 0 && t2 != 0 && t3 != 0) return Crossing::kProper;
  return Crossing::kDegenerate;
}

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void normalize(double* a) {
  const double n = std::sqrt(dot(a, a));
  for (int i = 0; i < 3; ++i) a[i] /= n;
}

uint32_t cell_of(double x, double x0, double size, uint32_t count) {
  const double c = std::floor((x - x0) / size);
  return c <= 0 ? 0u : (c >= count - 1 ? count - 1 : static_cast<uint32_t>(c));
}

}  // namespace

RayParityIndex::RayParityIndex(const SurfaceMesh& s) : surface_(s) {
  const size_t nt = s.num_triangles();
  std::fill(lo_, lo_ + 3, HUGE_VAL);
  std::fill(hi_, hi_ + 3, -HUGE_VAL);
  double magnitude = 0;
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    for (int i = 0; i < 3; ++i) {
      lo_[i] = std::min(lo_[i], s.point(v)[i]);
      hi_[i] = std::max(hi_[i], s.point(v)[i]);
      magnitude = std::max(magnitude, std::fabs(s.point(v)[i]));
    }
  }
  if (nt == 0) return;
  reach_ = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]});
  // u = d x z, v = d x u, both normalised: a basis of the plane orthogonal
  // to d (up to rounding, which the margin covers).
  u_[0] = kDir[1];
  u_[1] = -kDir[0];
  u_[2] = 0;
  normalize(u_);
  v_[0] = kDir[1] * u_[2] - kDir[2] * u_[1];
  v_[1] = kDir[2] * u_[0] - kDir[0] * u_[2];
  v_[2] = kDir[0] * u_[1] - kDir[1] * u_[0];
  normalize(v_);
  // Rounding in a projection is a few ulps of the coordinates' magnitude;
  // the margin is 2^-30 of it (and of the query region's size).
  const double margin = std::ldexp(magnitude + 4 * reach_, -30);

  std::vector<double> rect(4 * nt);  // per triangle: u min, u max, v min, v max
  double umin = HUGE_VAL, umax = -HUGE_VAL, vmin = HUGE_VAL, vmax = -HUGE_VAL;
  for (size_t t = 0; t < nt; ++t) {
    double* r = &rect[4 * t];
    r[0] = r[2] = HUGE_VAL;
    r[1] = r[3] = -HUGE_VAL;
    for (int k = 0; k < 3; ++k) {
      const double* p = s.point(s.tris[3 * t + k]);
      const double pu = dot(u_, p), pv = dot(v_, p);
      r[0] = std::min(r[0], pu - margin);
      r[1] = std::max(r[1], pu + margin);
      r[2] = std::min(r[2], pv - margin);
      r[3] = std::max(r[3], pv + margin);
    }
    umin = std::min(umin, r[0]);
    umax = std::max(umax, r[1]);
    vmin = std::min(vmin, r[2]);
    vmax = std::max(vmax, r[3]);
  }
  const uint32_t cells = static_cast<uint32_t>(std::clamp(std::sqrt(static_cast<double>(nt)), 1.0, 2048.0));
  cells_u_ = cells_v_ = cells;
  u0_ = umin;
  v0_ = vmin;
  cell_u_ = (umax - umin) / cells;
  cell_v_ = (vmax - vmin) / cells;
  first_.assign(size_t{cells} * cells + 1, 0);
  const auto for_cells = [&](size_t t, auto&& fn) {
    const double* r = &rect[4 * t];
    const uint32_t u1 = cell_of(r[0], u0_, cell_u_, cells_u_), u2 = cell_of(r[1], u0_, cell_u_, cells_u_);
    const uint32_t v1 = cell_of(r[2], v0_, cell_v_, cells_v_), v2 = cell_of(r[3], v0_, cell_v_, cells_v_);
    for (uint32_t cv = v1; cv <= v2; ++cv)
      for (uint32_t cu = u1; cu <= u2; ++cu) fn(size_t{cv} * cells_u_ + cu);
  };
  for (size_t t = 0; t < nt; ++t) for_cells(t, [&](size_t cell) { ++first_[cell + 1]; });
  for (size_t c = 0; c + 1 < first_.size(); ++c) first_[c + 1] += first_[c];
  tris_.resize(first_.back());
  std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
  for (size_t t = 0; t < nt; ++t)
    for_cells(t, [&](size_t cell) { tris_[fill[cell]++] = static_cast<uint32_t>(t); });
}

bool RayParityIndex::inside_slow(const double* p) const {
  std::vector<uint32_t> all(surface_.num_triangles());
  std::iota(all.begin(), all.end(), 0u);
  double far = 1;
  for (int i = 0; i < 3; ++i) far += 2 * std::max(std::fabs(p[i] - lo_[i]), std::fabs(p[i] - hi_[i]));
  return point_inside_shell(surface_, all, p, far);
}

bool RayParityIndex::inside(const double* p) const {
  if (surface_.num_triangles() == 0) return false;
  for (int i = 0; i < 3; ++i)
    if (p[i] < lo_[i] - reach_ || p[i] > hi_[i] + reach_) return inside_slow(p);
  // A segment long enough to leave the bounding box from anywhere in the
  // query region (|d| >= 1).
  const double far = 8 * reach_ + 1;
  const double q[3] = {p[0] + far * kDir[0], p[1] + far * kDir[1], p[2] + far * kDir[2]};
  const size_t cell = size_t{cell_of(dot(v_, p), v0_, cell_v_, cells_v_)} * cells_u_ +
                      cell_of(dot(u_, p), u0_, cell_u_, cells_u_);
  size_t crossings = 0;
  for (uint32_t k = first_[cell]; k < first_[cell + 1]; ++k) {
    const uint32_t* v = &surface_.tris[3 * size_t{tris_[k]}];
    const Crossing x = crossing(p, q, surface_.point(v[0]), surface_.point(v[1]), surface_.point(v[2]));
    if (x == Crossing::kDegenerate) return inside_slow(p);
    if (x == Crossing::kProper) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace partet
