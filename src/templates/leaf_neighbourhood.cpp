// Galloping leaf search and the homes of leaf lattice points (see
// leaf_neighbourhood.hpp). Coordinates: grid units for leaves, lattice
// units (doubled grid) for points, so that leaf centres of the deepest
// level are integers too.
#include "templates/leaf_neighbourhood.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace partet {

size_t seek_leaf(const LinearOctree& tree, size_t hint, uint64_t key) {
  const uint64_t* k = tree.key.data();
  const size_t n = tree.size();
  size_t lo, hi;  // k[lo] <= key, and hi == n or k[hi] > key
  if (k[hint] <= key) {
    lo = hint;
    size_t step = 1;
    for (;;) {
      if (step >= n - lo || k[lo + step] > key) {
        hi = step >= n - lo ? n : lo + step;
        break;
      }
      lo += step;
      step *= 2;
    }
  } else {
    hi = hint;
    size_t step = 1;
    for (;;) {
      if (step > hi) {
        lo = 0;  // a complete tree starts at key 0
        break;
      }
      if (k[hi - step] <= key) {
        lo = hi - step;
        break;
      }
      hi -= step;
      step *= 2;
    }
  }
  return static_cast<size_t>(std::upper_bound(k + lo + 1, k + hi, key) - k) - 1;
}

size_t seek_leaf_near(const LinearOctree& tree, size_t i, uint64_t key) {
  const int shift = 3 * (kMaxLevel - tree.level[i]);
  const uint64_t here = tree.key[i];
  size_t start;
  if (key >= here) {
    start = std::min(i + static_cast<size_t>((key - here) >> shift), tree.size() - 1);
  } else {
    const uint64_t back = (here - key) >> shift;
    start = back >= i ? 0 : i - static_cast<size_t>(back);
  }
  return seek_leaf(tree, start, key);
}

uint32_t leaf_across(const LinearOctree& tree, size_t i, int f, int q) {
  const int axis = f >> 1, u = (axis + 1) % 3, v = (axis + 2) % 3;
  const uint32_t edge = octant_edge(tree.level[i]);
  uint32_t p[3];
  tree.anchor(i, p[0], p[1], p[2]);
  if (f & 1) {
    if (p[axis] + edge >= kGridSize) return kAbsentLeaf;
    p[axis] += edge;
  } else {
    if (p[axis] == 0) return kAbsentLeaf;
    p[axis] -= 1;
  }
  p[u] += (q & 1) * (edge / 2);
  p[v] += (q >> 1 & 1) * (edge / 2);
  return static_cast<uint32_t>(seek_leaf_near(tree, i, morton_key(p[0], p[1], p[2])));
}

void LeafNeighbourhood::move_to(size_t i) {
  leaf_ = i;
  level_ = tree_.level[i];
  edge_ = octant_edge(level_);
  tree_.anchor(i, anchor_[0][0], anchor_[0][1], anchor_[0][2]);
  up_[0] = static_cast<uint32_t>(i);
  up_level_[0] = level_;
}

// Levels and anchors of the upper cells' leaves: a leaf of edge e holding
// the cell anchor p has anchor p rounded down to a multiple of e.
void LeafNeighbourhood::describe_upper_cells() {
  const uint32_t* a = anchor_[0];
  for (int d = 1; d < 8; ++d) {
    const uint32_t j = up_[d];
    if (j == kAbsentLeaf) continue;
    up_level_[d] = tree_.level[j];
    const uint32_t round = ~(octant_edge(up_level_[d]) - 1);
    for (int k = 0; k < 3; ++k) anchor_[d][k] = (a[k] + (d >> k & 1) * edge_) & round;
    // Face (one axis) and edge (two axes) neighbours differ by one level at most.
    PARTET_ASSERT(d == 7 || (up_level_[d] <= level_ + 1 && up_level_[d] >= level_ - 1),
                  "octree not 2:1 balanced: leaf " + std::to_string(leaf_) + " (level " +
                      std::to_string(level_) + ") is next to leaf " + std::to_string(j) +
                      " (level " + std::to_string(up_level_[d]) + ")");
  }
}

void LeafNeighbourhood::reset(size_t i) {
  move_to(i);
  const uint32_t* a = anchor_[0];
  const int e = kMaxLevel - level_;
  // Keys of the upper cells' anchors, built axis by axis.
  uint64_t cell_key[8] = {tree_.key[i]};
  bool inside[8] = {true};
  for (int k = 0; k < 3; ++k) {
    const bool fits = a[k] + edge_ < kGridSize;
    for (int d = 0; d < (1 << k); ++d) {
      inside[d | 1 << k] = inside[d] && fits;
      cell_key[d | 1 << k] = fits ? morton_step(cell_key[d], k, e) : 0;
    }
  }
  for (int d = 1; d < 8; ++d)
    up_[d] = inside[d] ? static_cast<uint32_t>(seek_leaf_near(tree_, i, cell_key[d])) : kAbsentLeaf;
  describe_upper_cells();
}

void LeafNeighbourhood::reset(size_t i, const uint32_t* upper_cells) {
  move_to(i);
  for (int d = 1; d < 8; ++d) up_[d] = upper_cells[d - 1];
  describe_upper_cells();
}

// Home of a point in an upper cell that is past the root, coarser or finer.
PointHome LeafNeighbourhood::home_elsewhere(int p) const {
  const int t[3] = {p % 3, p / 3 % 3, p / 9};
  const int d = kPointCodes[p].cell;
  const uint32_t j = up_[d];
  if (j == kAbsentLeaf) return {kAbsentLeaf, 0};
  const uint32_t* a = anchor_[0];
  const uint32_t* aj = anchor_[d];
  uint32_t q[3];  // lattice coordinates of the point
  for (int k = 0; k < 3; ++k) q[k] = 2 * a[k] + edge_ * static_cast<uint32_t>(t[k]);
  if (up_level_[d] <= level_) {
    // The cell's leaf contains the whole cell; the point must sit on its
    // child-anchor lattice, whose step is the leaf's edge in lattice units.
    const uint32_t half = octant_edge(up_level_[d]);
    uint8_t child = 0;
    for (int k = 0; k < 3; ++k) {
      const uint32_t off = q[k] - 2 * aj[k];
      if (off == half)
        child |= static_cast<uint8_t>(1 << k);
      else if (off != 0)
        return {kAbsentLeaf, 0};
    }
    return {j, child};
  }
  // A refined cell: its leaves touching the current leaf have the next level
  // (2:1), so the point is the anchor of one of them (the cell's first leaf
  // when the point is the cell's anchor). The current edge is at least 2.
  if (q[0] == 2 * aj[0] && q[1] == 2 * aj[1] && q[2] == 2 * aj[2]) return {j, 0};
  uint64_t key = tree_.key[j];
  for (int k = 0; k < 3; ++k)
    if (t[k] == 1) key = morton_step(key, k, kMaxLevel - level_ - 1);
  const size_t m = seek_leaf(tree_, j, key);
  PARTET_ASSERT(tree_.key[m] == key,
                "octree not 2:1 balanced around leaf " + std::to_string(leaf_));
  return {static_cast<uint32_t>(m), 0};
}

}  // namespace partet
