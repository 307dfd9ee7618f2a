// Morton keys of points on the octree's 2^21 grid laid over their bounding
// box: the space-filling-curve order of the Delaunay insertion rounds and
// of the tets handed to the optimizer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/octree.hpp"

namespace partet {

class BoxMorton {
 public:
  // The bounding box of the points `xyz` (3 per point; none: the unit box).
  explicit BoxMorton(const std::vector<double>& xyz) {
    for (int k = 0; k < 3; ++k) lo_[k] = 0, hi_[k] = 1;
    for (size_t i = 0; i < xyz.size(); ++i) {
      const int k = static_cast<int>(i % 3);
      lo_[k] = i < 3 ? xyz[i] : std::min(lo_[k], xyz[i]);
      hi_[k] = i < 3 ? xyz[i] : std::max(hi_[k], xyz[i]);
    }
    for (int k = 0; k < 3; ++k) scale_[k] = hi_[k] > lo_[k] ? (kGridSize - 1) / (hi_[k] - lo_[k]) : 0;
  }
  // The box's corners.
  const double* lo() const { return lo_; }
  const double* hi() const { return hi_; }
  // The key of the grid cell holding x (clamped to the box).
  uint64_t key(const double* x) const {
    uint32_t g[3];
    for (int k = 0; k < 3; ++k)
      g[k] = static_cast<uint32_t>(std::clamp((x[k] - lo_[k]) * scale_[k], 0.0, double{kGridSize - 1}));
    return morton_key(g[0], g[1], g[2]);
  }

 private:
  double lo_[3], hi_[3], scale_[3];
};

}  // namespace partet
