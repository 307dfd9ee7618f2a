// The deepest kernel point (core/kernel_point.hpp) of front faces, each
// looking into the unmeshed side: a point that sees every face can be
// coned to them all.
#pragma once

#include <cstdint>
#include <vector>

#include "core/kernel_point.hpp"
#include "front/front.hpp"

namespace partet {

// Faces: alive front faces. The search box is the faces' bounding box,
// swept by `lift` when given (core/kernel_point.hpp).
KernelPoint deepest_kernel_point(const Front& front, const std::vector<uint32_t>& faces,
                                 const double* lift = nullptr);

}  // namespace partet
