// The initial front cut into the ranks' boundary leaves, built distributed
// (before the boundary partition): every rank gets the FrontPart of its own
// kBoundary and kTooClose leaves.
//
// Ownership rule: every face of the initial front (front/initial_front.hpp)
// belongs to exactly one such leaf, decided exactly:
//  - a surface face (a reversed surface triangle) to the leaf whose
//    half-open box contains the triangle's centroid, located with exact
//    signs of a + b + c - 3 x against the grid planes x. That leaf's closed
//    box meets the triangle, so it is a boundary leaf;
//  - a core face, a triangle of face f of an interior leaf, to the leaf just
//    across f at the triangle's quadrant (face_rule.hpp), the leaf whose
//    class makes the triangle exposed: the leaf on its unmeshed side. It is
//    not interior (the triangle would be shared) and not outside (interior
//    and outside leaves never share a face), so kBoundary or kTooClose.
// Faces, vertices and global ids are those of the initial front: the
// surface triangle (a, b, c) gives the face (a, c, b); a core face is
// (v0, v2, v1) of its template tet; a core vertex's id is its lattice
// Morton key, surface vertex s's id is kSurfaceVertexId | s. Together the
// ranks' parts hold exactly the faces of make_initial_front on the whole
// tree, for any rank count.
//
// Method: each rank makes the core faces of its own interior leaves (from
// its core part and local view, whose layer-1 leaves include every leaf
// across a face) and the surface faces whose centroid lies in one of its
// own leaves; a core face whose leaf belongs to another rank goes there
// (one exchange between neighbouring ranks; every rank reads the whole
// surface, so surface faces never move).
#pragma once

#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "partition/front_part.hpp"
#include "surface/surface_mesh.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

// Whether the leaves of class `c` are left to the advancing front (and so
// are partitioned): kBoundary and kTooClose.
inline bool front_leaf_class(LeafClass c) { return c == LeafClass::kBoundary || c == LeafClass::kTooClose; }

// The leaf whose half-open box contains the centroid of triangle (a, b, c)
// (exact; clamped into the root cube), an index into the complete `tree`.
size_t leaf_of_centroid(const LinearOctree& tree, const RootCube& root, const double* a, const double* b,
                        const double* c);

// Collective. `view`: this rank's local view after the manifold pass
// (ghost_view, make_core_manifold); `core`: template_interior(view, root,
// rank); `surface`: the whole diagnosed surface. `bytes`, when given, gets
// the bytes of the core faces exchanged added.
FrontPart make_boundary_front(const Comm& comm, const LinearOctree& view, const TemplateCore& core,
                              const RootCube& root, const SurfaceMesh& surface, MigrationBytes* bytes = nullptr);

}  // namespace partet
