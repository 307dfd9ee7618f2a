// The pipeline's Delaunay fill step (front/delaunay_fill.hpp), between the
// initial front and the tree-supported removals, and its report counts.
#pragma once

#include "core/tet_mesh.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"
#include "pipeline/report.hpp"

namespace partet {

// delaunay_fill on `front` and the templated `core`, which it replaces by
// the kept tets; the counts: the tetrahedralization's tets, the missing
// triangles, the tets removed and kept, the components dropped, the front
// left (faces, free vertices) and the insertions' work (walk steps,
// cavity tets).
ojson fill_step(InitialFront& front, const LinearOctree& tree, TetMesh& core);

}  // namespace partet
