// A small dense linear program solver (simplex method in dictionary form)
// for geometric helpers with few variables: maximise c·x subject to
// A x <= b and x >= 0, with b >= 0 (so x = 0 is feasible and no first phase
// is needed). The dictionary keeps one row per constraint and one column
// per original variable, so a pivot costs O(m n) and memory is O(m n).
// Bland's rule (lowest variable id enters and leaves) rules out cycling; an
// iteration cap guards against round-off loops anyway. Doubles throughout:
// callers must verify any geometric decision made from the result exactly.
#pragma once

#include <cstddef>
#include <vector>

namespace partet {

enum class LpStatus { kOptimal, kUnbounded, kIterationLimit };

struct LpResult {
  LpStatus status = LpStatus::kIterationLimit;
  std::vector<double> x;  // n values (meaningful when optimal)
  double objective = 0;
  size_t pivots = 0;
};

// a: m rows of n coefficients (row-major), b: m right-hand sides (>= 0),
// c: n objective coefficients.
LpResult maximise_lp(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c);

}  // namespace partet
