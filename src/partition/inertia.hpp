// Principal axes of inertia of weighted point sets, several sets at once
// (one per "slot"), for RIB and MROB.
//
// Contract: collective over `comm`. Point i belongs to slot slot[i] in
// [0, slots), or to none when slot[i] < 0. Weights are integers whose sum
// over all ranks stays below 2^62. Coordinates are quantised to 20 bits in
// each slot's bounding box and every moment is summed exactly in integers,
// so the axes are the same on every rank and do not depend on how the points
// are spread over the ranks or ordered. The axis of a slot is the unit
// eigenvector of the largest eigenvalue of the weighted covariance (the
// direction of largest spread), signed so that its largest component (the
// first on ties) is positive; valid[s] is 0 when the slot's points have no
// spread or no weight, and its axis is then (0, 0, 0).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

struct InertiaAxes {
  std::vector<double> axis;    // 3 per slot
  std::vector<uint8_t> valid;  // 1 per slot
};

InertiaAxes principal_axes(const Comm& comm, const double* xyz, const uint64_t* weight, const int32_t* slot,
                           size_t n, size_t slots);

// The eigenvector of the largest eigenvalue of the symmetric matrix
// cov = {xx, yy, zz, xy, xz, yz} (cyclic Jacobi), signed as above. Returns
// false, with axis (0, 0, 0), when that eigenvalue is not positive.
bool principal_axis_of_covariance(const double cov[6], double axis[3]);

// The coordinate axis (0, 1, 2) closest in direction to `axis`: the largest
// |component|, the first on ties.
int closest_coordinate_axis(const double axis[3]);

}  // namespace partet
