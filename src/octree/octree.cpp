// Morton keys, leaf location by binary search, and the root cube placement.
#include "octree/octree.hpp"

#include <algorithm>
#include <cmath>

namespace partet {

namespace {

// Spreads the low 21 bits of v so that bit i moves to bit 3i.
uint64_t spread(uint32_t v) {
  uint64_t x = v & 0x1FFFFFu;
  x = (x | x << 32) & 0x1F00000000FFFFull;
  x = (x | x << 16) & 0x1F0000FF0000FFull;
  x = (x | x << 8) & 0x100F00F00F00F00Full;
  x = (x | x << 4) & 0x10C30C30C30C30C3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

uint32_t compact(uint64_t x) {
  x &= 0x1249249249249249ull;
  x = (x ^ (x >> 2)) & 0x10C30C30C30C30C3ull;
  x = (x ^ (x >> 4)) & 0x100F00F00F00F00Full;
  x = (x ^ (x >> 8)) & 0x1F0000FF0000FFull;
  x = (x ^ (x >> 16)) & 0x1F00000000FFFFull;
  x = (x ^ (x >> 32)) & 0x1FFFFFull;
  return static_cast<uint32_t>(x);
}

}  // namespace

uint64_t morton_key(uint32_t x, uint32_t y, uint32_t z) { return spread(x) | spread(y) << 1 | spread(z) << 2; }

void morton_decode(uint64_t key, uint32_t& x, uint32_t& y, uint32_t& z) {
  x = compact(key);
  y = compact(key >> 1);
  z = compact(key >> 2);
}

size_t LinearOctree::locate(uint32_t x, uint32_t y, uint32_t z) const {
  uint64_t k = morton_key(x, y, z);
  auto it = std::upper_bound(key.begin(), key.end(), k);
  return static_cast<size_t>(it - key.begin()) - 1;
}

RootCube make_root_cube(const double* bbox) {
  double extent = 0;
  for (int i = 0; i < 3; ++i) extent = std::max(extent, bbox[3 + i] - bbox[i]);
  if (!(extent > 0)) extent = 1;
  double wanted = extent * (1.0 + 2.0 / 16.0);
  RootCube root;
  // Smallest power-of-two edge that holds the enlarged box.
  int e = 0;
  std::frexp(wanted, &e);
  double edge = std::ldexp(1.0, e);
  root.unit = edge / kGridSize;
  double half_unit = 0.5 * root.unit;
  for (int i = 0; i < 3; ++i) {
    double centre = 0.5 * (bbox[i] + bbox[3 + i]);
    root.origin[i] = std::floor((centre - 0.5 * edge) / half_unit) * half_unit;
    // Rounding the origin down may shift the box towards the far side by
    // less than half a unit; the 1/16 margin absorbs it.
  }
  return root;
}

void octant_box(const RootCube& root, uint32_t x, uint32_t y, uint32_t z, int level, double* lo, double* hi) {
  const uint32_t h = octant_edge(level);
  root.lattice_point(2 * x, 2 * y, 2 * z, lo);
  root.lattice_point(2 * (x + h), 2 * (y + h), 2 * (z + h), hi);
}

void leaf_box(const LinearOctree& tree, const RootCube& root, size_t i, double* lo, double* hi) {
  uint32_t x, y, z;
  tree.anchor(i, x, y, z);
  octant_box(root, x, y, z, tree.level[i], lo, hi);
}

}  // namespace partet
