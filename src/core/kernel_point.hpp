// The deepest point of the kernel of a set of oriented triangles: the point
// q of their bounding box that maximises the smallest signed distance from q
// to the triangles' planes, measured on the side each triangle looks into
// (where orient3d(a, b, c, q) > 0). A positive depth means that q sees
// every triangle: when they bound a region, it is star-shaped from q and
// coning them to q fills it (the "Chebyshev centre" of the kernel). Solved
// as a 4-variable linear program in doubles (core/linear_program.hpp);
// callers decide on q with exact orient3d.
#pragma once

#include <vector>

namespace partet {

struct KernelPoint {
  bool found = false;  // false when the linear program did not finish
  double point[3] = {0, 0, 0};
  double depth = 0;  // smallest signed distance to the triangles' planes
};

// `triangles`: 9 coordinates each, a then b then c. Triangles whose plane is
// undefined in doubles (zero normal) are ignored.
KernelPoint deepest_kernel_point(const std::vector<double>& triangles);

}  // namespace partet
