// Building the linear octree from (point, level) requests (the paper's
// buildTree / refineOctant, done top-down over sorted keys), and refining it
// until no leaf meeting a surface triangle is coarser than the triangle asks.
//
// Method. Requests are sorted by Morton key; the leaves inside an octant
// then hold a contiguous run of them. An octant is split when a request in
// its run asks for a deeper level, and its children take the sub-runs, found
// by binary search; leaves come out in Morton order. Refining an existing
// tree splices: each old leaf is copied, or replaced by the subtree built from
// the requests inside it (its class and owner copied to the new leaves).
// O(n * depth) for n requests, no per-leaf allocation.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

// The leaf containing the grid point with Morton key `key` must have level
// >= `level`. For an octant anchor key with its own level, this means every
// leaf inside that octant has level >= `level`.
struct RefineRequest {
  uint64_t key = 0;
  uint8_t level = 0;
};

// The coarsest complete octree in which every point lies in a leaf of level
// >= its level. `grid`: 3 grid coordinates per point (each below kGridSize),
// `level`: one per point (at most kMaxLevel). Leaves are unclassified,
// owner 0.
LinearOctree build_octree(const std::vector<uint32_t>& grid, const std::vector<uint8_t>& level);

// Refines `tree` (complete) as little as possible so that every request is
// met; leaves that need no split are kept as they are.
void refine_octree(LinearOctree& tree, std::vector<RefineRequest> requests);

// Refines `tree` so that no leaf whose closed box meets a surface triangle
// (exact test) is coarser than that triangle's level, the minimum (coarsest)
// of its vertices' levels: the triangle's size is that of its largest
// vertex target, the finer vertices are met by build_octree's point requests,
// and 2:1 balance grades between them. Each triangle visits the leaves over
// its bounding box (range query) and descends only into leaves coarser than
// its level, testing sub-octants exactly. One pass suffices: a leaf made by a
// split lies in a leaf that was tested.
void refine_for_triangles(LinearOctree& tree, const SurfaceMesh& surface, const RootCube& root,
                          const std::vector<uint8_t>& vertex_level);

// The same, refining only the leaves whose owner is `owner` (the others are
// left as they are): one rank's part of a partition view (key_ranges.hpp).
void refine_for_triangles(LinearOctree& tree, const SurfaceMesh& surface, const RootCube& root,
                          const std::vector<uint8_t>& vertex_level, int32_t owner);

}  // namespace partet
