// Deepest kernel point of oriented triangles by a linear program (see kernel_point.hpp).
#include "core/kernel_point.hpp"

#include <algorithm>
#include <cmath>

#include "core/linear_program.hpp"

namespace partet {

KernelPoint deepest_kernel_point(const std::vector<double>& triangles, const double* lift) {
  KernelPoint r;
  const size_t n = triangles.size() / 9;
  if (n == 0) return r;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = INFINITY;
    hi[k] = -INFINITY;
  }
  for (size_t i = 0; i < 3 * n; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], triangles[3 * i + k]);
      hi[k] = std::max(hi[k], triangles[3 * i + k]);
    }
  if (lift)
    for (int k = 0; k < 3; ++k) {
      lo[k] += std::min(lift[k], 0.0);
      hi[k] += std::max(lift[k], 0.0);
    }
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if (!(diagonal > 0)) return r;
  // Variables y = q - lo >= 0 and s = depth + shift >= 0, with shift larger
  // than any distance inside the box, so y = 0, s = 0 is feasible.
  // Triangle with unit normal u through point a: u·(q - a) >= depth, i.e.
  // -u·y + s <= u·(lo - a) + shift.
  const double shift = 2 * diagonal;
  std::vector<double> a, b;
  a.reserve(4 * (n + 4));
  b.reserve(n + 4);
  for (size_t i = 0; i < n; ++i) {
    const double *p0 = &triangles[9 * i], *p1 = p0 + 3, *p2 = p0 + 6;
    const double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    double u[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (!(length > 0)) continue;
    for (double& x : u) x /= length;
    a.insert(a.end(), {-u[0], -u[1], -u[2], 1.0});
    b.push_back(std::max(0.0, u[0] * (lo[0] - p0[0]) + u[1] * (lo[1] - p0[1]) + u[2] * (lo[2] - p0[2]) + shift));
  }
  for (int k = 0; k < 3; ++k) {
    double row[4] = {0, 0, 0, 0};
    row[k] = 1;
    a.insert(a.end(), row, row + 4);
    b.push_back(hi[k] - lo[k]);
  }
  a.insert(a.end(), {0, 0, 0, 1});
  b.push_back(2 * shift);
  const LpResult lp = maximise_lp(a, b, {0, 0, 0, 1});
  if (lp.status != LpStatus::kOptimal) return r;
  r.found = true;
  for (int k = 0; k < 3; ++k) r.point[k] = std::clamp(lo[k] + lp.x[k], lo[k], hi[k]);
  r.depth = lp.x[3] - shift;
  return r;
}

}  // namespace partet
