// Gathering a distributed tree and its templated core onto rank 0, or onto
// every rank, for the steps that need the whole of them (the initial front
// and the face removals, whose ranks each work on a copy of the whole
// front: pipeline/tree_removal_step.hpp): they get exactly what the
// one-rank pipeline has after templating.
//
// Each rank sends its own leaves (key, level, class), the face cases and
// tet counts of those leaves and its part of the core (template_interior of
// its local view). Leaves are Morton-contiguous by rank, so the leaves and
// the tets concatenated in rank order are the serial arrays; the vertices
// are the union of the parts' global ids, ascending (the serial numbering),
// and each one's home leaf is the leaf whose key range holds the grid point
// under it (lattice key >> 3).
#pragma once

#include "octree/octree.hpp"
#include "octree/triangle_bins.hpp"
#include "parallel/comm.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

// Collective. `view`: this rank's local view (owner = rank on its own
// leaves); `part`: template_interior(view, root, rank). On rank 0 (on
// every rank with `everywhere`), `tree` and `core` become the whole tree
// (owner 0 everywhere) and template_interior(tree, root); elsewhere they
// are left empty. With `rows` (in and out): on entry this rank's own
// leaves' triangle rows (classify_distributed's own_rows); where the tree
// is gathered they become the whole tree's (bin_triangles(tree)'s first
// and tris), elsewhere empty.
void gather_tree_and_core(const Comm& comm, const LinearOctree& view, const TemplateCore& part,
                          LinearOctree& tree, TemplateCore& core, bool everywhere = false,
                          LeafTriangles* rows = nullptr);

}  // namespace partet
