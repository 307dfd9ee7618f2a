// The leaves around one leaf of a complete, 2:1 balanced linear octree
// (octree.hpp): the leaves across its faces, and the homes of the points of
// its lattice. No stored adjacency: galloping searches in the sorted key
// array, started where the neighbour would be if the leaves in between had
// the leaf's size (exact in uniform regions, close in graded ones), so a
// search costs a few comparisons on cached keys.
//
// Homes. Every point of a leaf's 3x3x3 lattice (face_rule.hpp) lies in the
// half-open box of exactly one leaf, its home: the leaf itself when no
// coordinate is at the upper end (t_i < 2), else the leaf of the "upper
// cell" d (d_i = 1 where t_i = 2) of the same size as the leaf, or a leaf
// inside that cell when it is refined. The template numbering stores each
// vertex at its home, as one of the home's 8 child anchors
// (anchor + edge/2 * b, b in {0,1}^3): a corner of an interior leaf, an
// edge midpoint in V or a face centre of a fanned face always is one,
// because the leaves touching it across a face or an edge are at most one
// level apart (face_rule.hpp); a corner-only neighbour may be coarser by
// more, but then the point is its anchor. A lattice point that is not a
// child anchor of its home cannot be in V, and `home` says so.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "octree/octree.hpp"

namespace partet {

constexpr uint32_t kAbsentLeaf = 0xFFFFFFFFu;

// Index of the leaf whose half-open box contains the grid point with Morton
// key `key`, searching outward from leaf `hint`; the cost is logarithmic in
// the distance between `hint` and the answer. The tree must be complete.
size_t seek_leaf(const LinearOctree& tree, size_t hint, uint64_t key);

// seek_leaf from a guess made at leaf i: as many places away from i as
// there are cells of leaf i's size between the two keys, which is exact
// when the leaves in between have that size.
size_t seek_leaf_near(const LinearOctree& tree, size_t i, uint64_t key);

// The leaf just across face f of leaf i at in-face quadrant q (bit 0: upper
// u half, bit 1: upper v half): the leaf containing the grid point one unit
// beyond the face at the quadrant's lower corner. A neighbour of leaf i's
// size or larger is the answer for every quadrant. kAbsentLeaf past the
// root cube.
uint32_t leaf_across(const LinearOctree& tree, size_t i, int f, int q);

struct PointHome {
  uint32_t leaf;  // kAbsentLeaf: no child anchor of any leaf (or past the root cube)
  uint8_t child;  // which child anchor of `leaf`, b = x | y << 1 | z << 2
};

// Number of set bits of each byte value.
inline constexpr std::array<uint8_t, 256> kByteBits = [] {
  std::array<uint8_t, 256> bits{};
  for (int b = 1; b < 256; ++b) bits[b] = static_cast<uint8_t>((b & 1) + bits[b >> 1]);
  return bits;
}();

// Vertex index of a point at its home, given per-leaf masks of the child
// anchors that are vertices and the prefix sums of their popcounts.
inline uint32_t home_vertex(PointHome h, const uint8_t* mask, const uint32_t* first_vertex) {
  return first_vertex[h.leaf] + kByteBits[mask[h.leaf] & ((1u << h.child) - 1u)];
}

// Morton key of the grid point with key `key` moved up by 2^e along `axis`
// (a dilated-integer add; the result must stay inside the root cube).
inline uint64_t morton_step(uint64_t key, int axis, int e) {
  const uint64_t m = uint64_t{0x1249249249249249} << axis;
  return (key & ~m) | (((key | ~m) + (uint64_t{1} << (3 * e + axis))) & m);
}

class LeafNeighbourhood {
 public:
  explicit LeafNeighbourhood(const LinearOctree& tree) : tree_(tree) {}

  // Moves to leaf i: finds the leaves containing the anchors of its 7 upper
  // cells (kAbsentLeaf past the root's far faces). Throws InternalError when a
  // face or edge neighbour found this way breaks the 2:1 balance.
  void reset(size_t i);
  // Moves to leaf i with the upper cells found by an earlier reset(i).
  void reset(size_t i, const uint32_t* upper_cells);
  // The leaves of upper cells d = 1..7, as upper_cells()[d - 1].
  const uint32_t* upper_cells() const { return up_ + 1; }

  // Home of point p of the current leaf's lattice (see above). Inline for
  // the common cases: the leaf itself, or an upper cell of the same level,
  // where the point is the child anchor at the bits where t_i = 1.
  PointHome home(int p) const {
    const PointCode code = kPointCodes[p];
    if (code.cell == 0) return {static_cast<uint32_t>(leaf_), code.child};
    const uint32_t j = up_[code.cell];
    if (j != kAbsentLeaf && up_level_[code.cell] == level_) return {j, code.child};
    return home_elsewhere(p);
  }

  size_t leaf() const { return leaf_; }
  int level() const { return level_; }
  uint32_t edge() const { return edge_; }
  const uint32_t* anchor() const { return anchor_[0]; }

 private:
  // Per leaf point: its upper cell d (bits where t_i = 2) and the bits
  // where t_i = 1.
  struct PointCode {
    uint8_t cell, child;
  };
  static constexpr std::array<PointCode, 27> kPointCodes = [] {
    std::array<PointCode, 27> codes{};
    for (int p = 0; p < 27; ++p) {
      const int t[3] = {p % 3, p / 3 % 3, p / 9};
      for (int k = 0; k < 3; ++k) {
        codes[p].cell = static_cast<uint8_t>(codes[p].cell | (t[k] == 2) << k);
        codes[p].child = static_cast<uint8_t>(codes[p].child | (t[k] == 1) << k);
      }
    }
    return codes;
  }();

  PointHome home_elsewhere(int p) const;
  void move_to(size_t i);
  void describe_upper_cells();

  const LinearOctree& tree_;
  size_t leaf_ = 0;
  int level_ = 0;
  uint32_t edge_ = 0;
  // Per upper cell d (0: the leaf itself): leaf containing the cell's
  // anchor, its level and anchor.
  uint32_t up_[8] = {};
  int up_level_[8] = {};
  uint32_t anchor_[8][3] = {};
};

}  // namespace partet
