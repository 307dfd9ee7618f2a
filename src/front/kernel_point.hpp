// The deepest point of a front component's kernel: the point q of a box
// that maximises the smallest signed distance from q to the planes of the
// given front faces, measured on the side each face looks into (the
// unmeshed side, where orient3d(a, b, c, q) > 0). A positive depth means
// that q sees every face: the faces are then the boundary of a region that
// is star-shaped from q, and coning them to q fills it (the "Chebyshev
// centre" of the kernel). Solved as a 4-variable linear program in doubles
// (core/linear_program.hpp); callers decide on q with exact orient3d.
#pragma once

#include <cstdint>
#include <vector>

#include "front/front.hpp"

namespace partet {

struct KernelPoint {
  bool found = false;  // false when the linear program did not finish
  double point[3] = {0, 0, 0};
  double depth = 0;  // smallest signed distance to the faces' planes
};

// Faces: alive front faces. The search box is the faces' bounding box.
// Faces whose plane is undefined in doubles (zero normal) are ignored.
KernelPoint deepest_kernel_point(const Front& front, const std::vector<uint32_t>& faces);

}  // namespace partet
