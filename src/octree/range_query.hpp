// Range queries on a complete linear octree: the leaves overlapping a box of
// grid cells, without scanning the leaves.
//
// Method. The box is covered by at most 2 x 2 x 2 octants of the deepest
// level whose edge is not below the box's largest extent. Each of them lies
// inside one leaf (found by locating its anchor) or is split, and then its
// leaves are the contiguous run of keys [key, key + span), descended child
// by child with binary searches inside the parent's run (short runs are
// scanned). Locating a key uses a table over the octants of one level (about
// as many as there are leaves): the first leaf at or after each of them, so
// a search only bisects the few leaves of one table cell. Restricted to a
// LeafSet, a run with no member is skipped whole and a short run's members
// are listed from the set's bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/leaf_set.hpp"
#include "octree/octree.hpp"

namespace partet {

// Grid cells [lo, hi] (inclusive, clamped to the root cube) that cover the
// closed space box [blo, bhi] with one cell of padding on every side, so that
// every leaf whose closed box meets [blo, bhi] contains one of the cells
// despite rounding in the conversion to grid units.
void grid_range(const RootCube& root, const double* blo, const double* bhi, uint32_t* lo, uint32_t* hi);

// The grid cells (as grid_range) over triangle (a, b, c)'s bounding box
// grown by `reach` on every side.
void triangle_grid_range(const RootCube& root, const double* a, const double* b, const double* c, double reach,
                         uint32_t* lo, uint32_t* hi);

class LeafRangeQuery {
 public:
  // Keeps a reference to `tree` (complete), which must not change while the
  // query object is used; builds the decoded anchors of its leaves and the
  // search table.
  explicit LeafRangeQuery(const LinearOctree& tree);

  // Replaces `out` with the indices, ascending, of the leaves that contain
  // at least one grid cell of [lo, hi] (inclusive ranges).
  void leaves_in_range(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out) const;
  // The same restricted to the members of `only` (same order): on a front
  // that has been near few of the leaves, a fraction of the work.
  void leaves_in_range(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out, const LeafSet& only) const;

  // Index of the leaf containing grid point (x, y, z), as
  // LinearOctree::locate.
  size_t locate(uint32_t x, uint32_t y, uint32_t z) const;
  // The same, galloping from leaf `hint` then bisecting: faster when the
  // answer is near the hint in Morton order (e.g. a neighbour of the hint).
  size_t locate_near(size_t hint, uint32_t x, uint32_t y, uint32_t z) const;

  // The grid cells [lo, hi] (inclusive) of leaf `leaf`.
  void leaf_cells(size_t leaf, uint32_t* lo, uint32_t* hi) const {
    const uint32_t h = octant_edge(tree_->level[leaf]) - 1;
    for (int i = 0; i < 3; ++i) {
      lo[i] = anchor_[3 * leaf + i];
      hi[i] = lo[i] + h;
    }
  }
  // The closed space box of leaf `leaf` (as leaf_box in octree.hpp, from
  // the stored anchor instead of decoding the key).
  void leaf_box(const RootCube& root, size_t leaf, double* lo, double* hi) const {
    const uint32_t* a = &anchor_[3 * leaf];
    octant_box(root, a[0], a[1], a[2], tree_->level[leaf], lo, hi);
  }

 private:
  // First leaf whose key is above `key` (the leaf containing it is the one
  // before).
  size_t upper_bound(uint64_t key) const;
  // The leaves of `only` (every leaf, or a LeafSet) in range.
  template <class Only>
  void collect(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out, const Only& only) const;
  template <class Only>
  void descend(uint64_t key, const uint32_t* a, int level, size_t b, size_t e, const uint32_t* lo,
               const uint32_t* hi, std::vector<size_t>& out, const Only& only) const;

  const LinearOctree* tree_;  // a pointer: the query is assignable
  std::vector<uint32_t> anchor_;  // 3 grid coordinates per leaf
  int table_shift_ = 0;           // key >> table_shift_ = table cell
  std::vector<uint32_t> table_;   // per cell, plus one: first leaf with key >= the cell's first key
};

// The leaves over the bounding box of triangle (a, b, c): a superset of the
// leaves the closed triangle meets.
void leaves_over_triangle_box(const LeafRangeQuery& query, const RootCube& root, const double* a, const double* b,
                              const double* c, std::vector<size_t>& out);

}  // namespace partet
