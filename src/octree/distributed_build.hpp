// The distributed octree (paper §3.3): built from (grid point, level) pairs
// spread over the ranks, refined along the surface triangles and 2:1
// balanced, with no rank ever holding the whole tree. As a set of leaves the
// result is exactly the serial tree (build_octree, refine_for_triangles,
// balance_octree); rank r holds one Morton-contiguous run of it, and the runs
// follow each other in rank order, so the concatenation of the ranks' leaves
// is the serial leaf array.
//
// Building. Every rank starts from the root as the only terminal octant of
// the rank set [0, P). A rank set with more than one rank splits, once, its
// terminal octants that hold a point asking for a deeper level; the load of
// a terminal octant is the sum of the levels of its points. The set is then
// cut in two, ranks [first, mid) and [mid, last) with mid = first +
// floor(size / 2), at the octant boundary (in Morton order) whose prefix load
// is nearest to size(low) / size of the total (first such boundary on ties);
// while that cut misses its target by more than a sixteenth of one rank's
// share and the octant straddling the target holds a point asking for a
// deeper level, that octant is split too and the cut taken again. Low ranks
// take the octants before the cut, high ranks the others, and the points
// move to the half holding their octant (a rank of the other half sends them
// to the rank at its own position there). All rank sets of a depth work in
// the same collective calls, each summing over its own segment (no
// sub-communicators). When every set is one rank, each rank builds the
// subtrees of its terminal octants from its points with no communication.
// Only octants holding a point that asks for a deeper level are ever split,
// so the leaves are those of the coarsest tree meeting the requests: the
// serial tree's.
//
// Triangles. Every rank reads the whole surface (for now) and runs the
// serial refinement on its partition view (key_ranges.hpp), splitting only
// its own leaves: a leaf's refinement depends on the leaf and the triangles
// alone.
//
// Balance. The required octants of balance.hpp are a union over leaves, each
// leaf's depending on that leaf alone, and closed under the requirement
// rule: the octants made by splitting to meet them require nothing outside
// them. So each rank computes the required octants of its own leaves (those
// across its range boundary included, up to the root), sends each to the
// rank holding its anchor key, and every rank refines its leaves with what it
// received: one exchange, with nothing left to propagate afterwards.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/key_ranges.hpp"
#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct DistributedOctree {
  LinearOctree leaves;  // this rank's leaves, sorted by key; owner = this rank
  KeyPartition ranges;  // every rank's key range (the same on all ranks)
};

struct TreeBuildCounts {
  int depths = 0;         // rank-set halvings
  int coarse_passes = 0;  // collective split passes over all depths
};

// Collective. `grid` (3 per point, below kGridSize) and `level` (one per
// point, at most kMaxLevel): this rank's slice of the (point, level) pairs.
DistributedOctree build_distributed_octree(const Comm& comm, const std::vector<uint32_t>& grid,
                                           const std::vector<uint8_t>& level, TreeBuildCounts* counts = nullptr);

// refine_for_triangles on this rank's leaves (no communication).
void refine_distributed_for_triangles(DistributedOctree& tree, int rank, const SurfaceMesh& surface,
                                      const RootCube& root, const std::vector<uint8_t>& vertex_level);

// Collective: balance_octree over all ranks' leaves (grading radius as there).
void balance_distributed_octree(const Comm& comm, DistributedOctree& tree, int grading = 1);

}  // namespace partet
