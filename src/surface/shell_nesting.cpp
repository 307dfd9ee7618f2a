// shell_depths: bounding-box pre-filter, then exact ray parity per pair.
#include "surface/shell_nesting.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/intersections.hpp"
#include "core/predicates.hpp"

namespace partet {

namespace {

enum class Crossing { kNone, kProper, kDegenerate };

// How the segment pq meets the closed triangle abc, exactly.
Crossing classify(const double* p, const double* q, const double* a, const double* b, const double* c) {
  int s1 = orient3d(a, b, c, p), s2 = orient3d(a, b, c, q);
  if (s1 == s2 && s1 != 0) return Crossing::kNone;
  if (s1 == 0 || s2 == 0)
    return segment_triangle_intersect(p, q, a, b, c) ? Crossing::kDegenerate : Crossing::kNone;
  int t1 = orient3d(p, q, a, b), t2 = orient3d(p, q, b, c), t3 = orient3d(p, q, c, a);
  bool pos = t1 > 0 || t2 > 0 || t3 > 0;
  bool neg = t1 < 0 || t2 < 0 || t3 < 0;
  if (pos && neg) return Crossing::kNone;
  if (t1 != 0 && t2 != 0 && t3 != 0) return Crossing::kProper;
  return Crossing::kDegenerate;  // through an edge or a vertex
}

// Deterministic ray directions, none along an axis or a simple diagonal.
constexpr std::array<std::array<double, 3>, 8> kDirections{{
    {1.0, 0.3183098861837907, 0.2718281828459045},
    {-0.41421356237309503, 1.0, 0.7320508075688772},
    {0.5772156649015329, -0.6931471805599453, 1.0},
    {-1.0, -0.6180339887498949, 0.1414213562373095},
    {0.2360679774997897, 1.0, -0.8862269254527580},
    {0.7071067811865476, -0.9189385332046727, -0.3678794411714423},
    {-0.1253314137315500, -0.4342944819032518, -1.0},
    {0.9159655941772190, 0.5641895835477563, -0.2026423672846756},
}};

}  // namespace

bool point_inside_shell(const SurfaceMesh& s, const std::vector<uint32_t>& tris, const double* p, double far) {
  for (const auto& dir : kDirections) {
    double q[3] = {p[0] + far * dir[0], p[1] + far * dir[1], p[2] + far * dir[2]};
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(p[i], q[i]);
      hi[i] = std::max(p[i], q[i]);
    }
    size_t crossings = 0;
    bool degenerate = false;
    for (uint32_t t : tris) {
      const double* a = s.point(s.tris[3 * size_t{t}]);
      const double* b = s.point(s.tris[3 * size_t{t} + 1]);
      const double* c = s.point(s.tris[3 * size_t{t} + 2]);
      bool apart = false;
      for (int i = 0; i < 3 && !apart; ++i)
        apart = std::max({a[i], b[i], c[i]}) < lo[i] || std::min({a[i], b[i], c[i]}) > hi[i];
      if (apart) continue;
      Crossing x = classify(p, q, a, b, c);
      if (x == Crossing::kDegenerate) {
        degenerate = true;
        break;
      }
      if (x == Crossing::kProper) ++crossings;
    }
    if (!degenerate) return crossings % 2 == 1;
  }
  PARTET_ASSERT(false, "every ray direction grazes an edge or a vertex of the shell");
  return false;
}

std::vector<uint32_t> shell_depths(const SurfaceMesh& s, const std::vector<uint32_t>& shell_of_triangle,
                                   uint32_t shell_count) {
  std::vector<uint32_t> depth(shell_count, 0);
  if (shell_count < 2) return depth;

  std::vector<std::vector<uint32_t>> tris(shell_count);
  std::vector<std::array<double, 6>> box(shell_count, {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL});
  std::vector<uint32_t> probe(shell_count, UINT32_MAX);
  double all_lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, all_hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (uint32_t t = 0; t < shell_of_triangle.size(); ++t) {
    uint32_t sh = shell_of_triangle[t];
    tris[sh].push_back(t);
    if (probe[sh] == UINT32_MAX) probe[sh] = s.tris[3 * size_t{t}];
    for (int k = 0; k < 3; ++k) {
      const double* v = s.point(s.tris[3 * size_t{t} + k]);
      for (int i = 0; i < 3; ++i) {
        box[sh][i] = std::min(box[sh][i], v[i]);
        box[sh][3 + i] = std::max(box[sh][3 + i], v[i]);
        all_lo[i] = std::min(all_lo[i], v[i]);
        all_hi[i] = std::max(all_hi[i], v[i]);
      }
    }
  }
  double far = 1.0;
  for (int i = 0; i < 3; ++i) far += 4.0 * (all_hi[i] - all_lo[i]);

  for (uint32_t a = 0; a < shell_count; ++a) {
    for (uint32_t b = 0; b < shell_count; ++b) {
      if (a == b) continue;
      bool inside_box = true;
      for (int i = 0; i < 3; ++i)
        inside_box = inside_box && box[a][i] >= box[b][i] && box[a][3 + i] <= box[b][3 + i];
      if (inside_box && point_inside_shell(s, tris[b], s.point(probe[a]), far)) ++depth[a];
    }
  }
  return depth;
}

}  // namespace partet
