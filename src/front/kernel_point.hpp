// The deepest kernel point (core/kernel_point.hpp) of front faces, each
// looking into the unmeshed side: a point that sees every face can be
// coned to them all.
#pragma once

#include <cstdint>
#include <vector>

#include "core/kernel_point.hpp"
#include "front/front.hpp"

namespace partet {

// Faces: alive front faces. The search box is the faces' bounding box.
KernelPoint deepest_kernel_point(const Front& front, const std::vector<uint32_t>& faces);

}  // namespace partet
