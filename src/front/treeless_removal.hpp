// Tree-less face removals with new vertices (paper §2.4, pipeline step 10,
// first mechanism): the faces that tree-supported removals leave are
// removed by tets whose apex is a new vertex. Surface triangles and surface
// vertices are never changed; no tet is deleted.
//
// Cavity fill, in rounds until the front is empty, a round makes no tet,
// or the vertex budget (4 × the alive faces at the start + 64 new
// vertices) is spent: the alive faces are split into components (faces
// sharing an edge); for each component of at most 64 faces, in order of its
// lowest face index, the star points tried are the mean of its face
// centroids and the mean of its vertices. A star point q must see every
// face of the component (orient3d(a, b, c, q) > 0); then q is added and the
// faces are coned to it one by one, each tet made only when check_removal
// (removal_checks.hpp) says valid against the front gathered from the
// leaves over the tet's bounding box (not tried when one of those leaves is
// owned by another rank); q is removed again when no tet was made. After
// each fill remove_faces_tree_supported runs again, so that the
// neighbouring faces use the new vertex; it also runs once first.
// Points are computed in doubles; every decision on them is exact.
//
// Global ids of new vertices: kSteinerVertexId | (front vertex index),
// with bits 63 and 62 set. Lattice keys (core vertices) are below 2^63 and
// surface vertices are kSurfaceVertexId | s with s < 2^32 (bit 62 clear),
// so the three id spaces are disjoint.
//
// Termination: the budget bounds the new vertices, each fill adds one, and
// tree-supported removal terminates (face_removal.hpp). Deterministic:
// fixed orders, ties by index.
#pragma once

#include <cstdint>

#include "core/tet_mesh.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"

namespace partet {

constexpr uint64_t kSteinerVertexId = kSurfaceVertexId | (uint64_t{1} << 62);

// As remove_faces_tree_supported (same contract on `front`, `tree`, `root`
// and `out`): new vertices are appended to the front and to `out` (with
// global ids when `out` has them). The counts include the tets and checks
// of the tree-supported runs; foreign_faces is that of the last of them.
RemovalCounts remove_faces_with_new_vertices(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                             const RemovalOptions& options = {});

}  // namespace partet
