// The deepest point of the kernel of a set of oriented triangles: the point
// q of their bounding box that maximises the smallest signed distance from q
// to the triangles' planes, measured on the side each triangle looks into
// (where orient3d(a, b, c, q) > 0). A positive depth means that q sees
// every triangle: when they bound a region, it is star-shaped from q and
// coning them to q fills it (the "Chebyshev centre" of the kernel). Solved
// as a 4-variable linear program in doubles (core/linear_program.hpp);
// callers decide on q with exact orient3d.
//
// The search box is the triangles' bounding box, swept by an optional
// `lift` vector (the box of the triangles and of the triangles moved by
// lift). Triangles that bound a region have their kernel inside their box;
// an open patch has an unbounded kernel, and its own box clips it to the
// patch's thickness: a nearly flat patch's deepest point would lie almost
// on it. Lifting the box along the patch's normal lets the point rise.
#pragma once

#include <vector>

namespace partet {

struct KernelPoint {
  bool found = false;  // false when the linear program did not finish
  double point[3] = {0, 0, 0};
  double depth = 0;  // smallest signed distance to the triangles' planes
};

// `triangles`: 9 coordinates each, a then b then c. Triangles whose plane is
// undefined in doubles (zero normal) are ignored. `lift`: 3 coordinates, or
// null for the plain bounding box.
KernelPoint deepest_kernel_point(const std::vector<double>& triangles, const double* lift = nullptr);

}  // namespace partet
