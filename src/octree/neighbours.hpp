// Neighbour queries on a complete linear octree, by locating grid points
// just outside a leaf (binary searches, no stored adjacency).
//
// Numbering (the same everywhere that names a leaf's faces, edges, corners):
// - corner k (0..7) is at the high side of axis i iff bit i of k is set
//   (the same as the child index of an octant and the Morton order);
// - face f (0..5) = 2 * axis + side: 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z;
//   its in-face axes are u = (axis + 1) % 3, v = (axis + 2) % 3 (u x v =
//   +axis), as in templates/face_rule.hpp; quadrant q of a face is the upper
//   half along u iff bit 0 of q, along v iff bit 1;
// - edge e (0..11) = 4 * axis + su + 2 * sv, where `axis` is the edge's
//   direction, u = (axis + 1) % 3, v = (axis + 2) % 3 the two others and su,
//   sv (0 low, 1 high) the sides of the edge on them: edges 0-3 run along x
//   (u = y, v = z), 4-7 along y (u = z, v = x), 8-11 along z (u = x, v = y).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/octree.hpp"

namespace partet {

constexpr int kFaceCount = 6;
constexpr int kEdgeCount = 12;
constexpr size_t kNoLeaf = SIZE_MAX;

// The two corners (ascending) at the ends of edge e.
void edge_corners(int edge, int& c0, int& c1);

// Leaves across face `face` of leaf i in a 2:1 balanced tree: 0 on the root
// boundary, 1 (same level or coarser), or 4 (one level finer, out[q] across
// quadrant q). Returns the count.
// Throws InternalError when the neighbours are two or more levels finer.
int face_neighbours(const LinearOctree& tree, size_t i, int face, size_t out[4]);

// Appends to `out` every leaf across face `face` of leaf i, for any complete
// tree (no balance needed): the face is split into quadrants until each
// quadrant lies in one leaf.
void append_face_neighbours(const LinearOctree& tree, size_t i, int face, std::vector<size_t>& out);

// The leaf containing the grid cell next to the start (low end) of edge
// `edge` of leaf i, in region `region` around the edge: 1 across u only, 2
// across v only, 3 across both (u, v as in the edge numbering); kNoLeaf when
// that region is outside the root cube. A leaf found there that is no finer
// than leaf i spans the whole edge; a finer one shares the edge's first part.
size_t edge_region_leaf(const LinearOctree& tree, size_t i, int edge, int region);

// True when a leaf sharing a positive length of edge `edge` of leaf i (in one
// of the three octant-sized regions around the edge) is finer than leaf i.
// Any complete tree; with 2:1 balance such leaves are exactly one level finer
// and split the edge at its midpoint.
bool edge_has_finer_leaf(const LinearOctree& tree, size_t i, int edge);

}  // namespace partet
