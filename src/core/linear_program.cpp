// Simplex method in dictionary form with Bland's rule (see linear_program.hpp).
#include "core/linear_program.hpp"

#include <cmath>
#include <cstdint>

#include "core/error.hpp"

namespace partet {

LpResult maximise_lp(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c) {
  const size_t n = c.size(), m = b.size();
  PARTET_ASSERT(a.size() == m * n, "linear program matrix size");
  const size_t w = n + 1;
  // Row i: basic[i] = d[i*w] + sum_j d[i*w + 1 + j] * nonbasic[j].
  std::vector<double> d(m * w);
  std::vector<double> z(w, 0.0);  // objective row, same layout
  std::vector<size_t> basic(m), nonbasic(n);
  for (size_t i = 0; i < m; ++i) {
    PARTET_ASSERT(b[i] >= 0, "linear program needs b >= 0");
    d[i * w] = b[i];
    for (size_t j = 0; j < n; ++j) d[i * w + 1 + j] = -a[i * n + j];
    basic[i] = n + i;
  }
  for (size_t j = 0; j < n; ++j) {
    z[1 + j] = c[j];
    nonbasic[j] = j;
  }
  LpResult r;
  constexpr double kTiny = 1e-12;
  const size_t limit = 50 * (n + m) + 100;
  for (;; ++r.pivots) {
    if (r.pivots >= limit) return r;
    // Entering: the lowest-id non-basic variable that improves z.
    size_t enter = SIZE_MAX;
    for (size_t j = 0; j < n; ++j)
      if (z[1 + j] > kTiny && (enter == SIZE_MAX || nonbasic[j] < nonbasic[enter])) enter = j;
    if (enter == SIZE_MAX) break;
    // Leaving: minimum ratio, ties by lowest id.
    size_t leave = SIZE_MAX;
    double best = 0;
    for (size_t i = 0; i < m; ++i) {
      const double coef = d[i * w + 1 + enter];
      if (coef >= -kTiny) continue;
      const double ratio = std::max(d[i * w], 0.0) / -coef;
      if (leave == SIZE_MAX || ratio < best || (ratio == best && basic[i] < basic[leave])) {
        leave = i;
        best = ratio;
      }
    }
    if (leave == SIZE_MAX) {
      r.status = LpStatus::kUnbounded;
      return r;
    }
    // Solve row `leave` for the entering variable and substitute.
    double* row = &d[leave * w];
    const double pivot = row[1 + enter];
    for (size_t k = 0; k < w; ++k) row[k] /= -pivot;
    row[1 + enter] = 1.0 / pivot;  // coefficient of the leaving variable
    // The entering variable's column becomes f times the leaving one's
    // coefficient (0 + f * row, as if cleared first); written after the
    // row's update, not cleared before it: a scalar store followed by a
    // wide load over it stalled store forwarding on every row.
    auto substitute = [&](double* other) {
      const double f = other[1 + enter];
      if (f == 0) return;
      for (size_t k = 0; k < w; ++k) other[k] += f * row[k];
      other[1 + enter] = 0.0 + f * row[1 + enter];
    };
    for (size_t i = 0; i < m; ++i)
      if (i != leave) substitute(&d[i * w]);
    substitute(z.data());
    std::swap(basic[leave], nonbasic[enter]);
  }
  r.status = LpStatus::kOptimal;
  r.objective = z[0];
  r.x.assign(n, 0.0);
  for (size_t i = 0; i < m; ++i)
    if (basic[i] < n) r.x[basic[i]] = d[i * w];
  return r;
}

}  // namespace partet
