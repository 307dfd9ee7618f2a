// Classification of a distributed octree (classify.hpp) on every rank at
// once, each rank classifying its own leaves with no neighbour leaves from
// other ranks. Every rank reads the whole surface (for now). Each rank runs
// the serial classification on its partition view (key_ranges.hpp: its
// leaves and the placeholder octants of the other ranks):
// - boundary: a per-leaf exact test, the same as serially;
// - interior / outside: one exact ray-parity test per connected group of
//   non-boundary leaves; the groups of the view are not the serial groups
//   (placeholders cut or join them) but any group is on one side of the
//   surface, and the exact test at any of its leaves tells which;
// - too close: a leaf's test needs, for each triangle t near it, b_t, the
//   edge of the coarsest leaf of the whole tree meeting t; each rank finds
//   it among its own leaves and one all-reduce (a level per triangle) takes
//   the minimum over ranks.
// So every leaf gets the class the serial classification gives it.
#pragma once

#include <vector>

#include "octree/classify.hpp"
#include "octree/distributed_build.hpp"
#include "octree/triangle_bins.hpp"

namespace partet {

// Collective: sets tree.leaves.cls; returns the counts summed over ranks
// (groups: the sum of the ranks' group counts). With `own_rows`, the
// triangles binned into this rank's leaves (bin_triangles' rows of them, in
// their order; no `coarsest`), which gather_tree_and_core can put together
// into the whole tree's.
ClassCounts classify_distributed(const Comm& comm, DistributedOctree& tree, const SurfaceMesh& surface,
                                 const RootCube& root, const std::vector<double>& vertex_size,
                                 const ClassifyOptions& options = {}, LeafTriangles* own_rows = nullptr);

}  // namespace partet
