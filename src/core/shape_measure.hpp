// The volume-length shape measure of a tet, in doubles: a heuristic for
// choosing among valid tets (validity is always exact orient3d).
#pragma once

#include <cmath>

#include "core/predicates.hpp"

namespace partet {

// q = √2 det / l_rms³ for tet (a, b, c, p), det = orient3d_value (6 times
// the signed volume) and l_rms the root mean square of the six edge
// lengths: 1 for the regular tet, 0 when flat, negative when inverted.
inline double shape_measure(const double* a, const double* b, const double* c, const double* p) {
  auto squared_distance = [](const double* x, const double* y) {
    const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
    return dx * dx + dy * dy + dz * dz;
  };
  const double sum = squared_distance(a, b) + squared_distance(b, c) + squared_distance(c, a) +
                     squared_distance(a, p) + squared_distance(b, p) + squared_distance(c, p);
  const double rms = std::sqrt(sum / 6);
  return std::sqrt(2.0) * orient3d_value(a, b, c, p) / (rms * rms * rms);
}

}  // namespace partet
