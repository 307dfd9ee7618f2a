// The Delaunay fill: most of the volume meshed at once by a Delaunay
// tetrahedralization of the front's vertices, leaving to the face removals
// only the cavities around the input triangles that are not Delaunay.
//
// From the initial front (make_initial_front, gap vertices added) and the
// templated core:
//  1. the Delaunay tetrahedralization of every vertex (the core's lattice
//     points, the surface's vertices, the gap vertices), delaunay.hpp;
//  2. the missing input edges recovered by flips (edge_recovery.hpp), so
//     that more input triangles are faces; of the tets the flips made, those
//     on four surface vertices whose shape measure is under 0.3 are removed
//     (the optimizer cannot move their vertices, the front's removals
//     place their own; kept, they left the smallest angle lower on
//     several CAD parts);
//  3. the input triangles that are faces become walls; every
//     tet that meets a missing input triangle beyond the vertices
//     they share (tet_triangle_contact.hpp) is removed. The tets meeting
//     one are found from the tets around its vertices, growing across
//     faces to the tets that meet it too: its relative interior is
//     connected and crosses from tet to tet through faces, or along edges
//     whose ring of tets all meet it;
//  4. the tets left split into components across faces that are not
//     walls; a path from inside the surface to outside crosses it through
//     a wall or through a removed tet, so a component lies on one side.
//     A component is kept when it has a wall with the component on the
//     material side and none with it on the other, and no tet on the
//     enclosing tet's corners; a component with no wall (closed in by
//     removed tets) is dropped, and the face removals fill its place;
//  5. the kept tets replace the core's (the templates' lattice points
//     stay, and the tetrahedralization of the core's lattice is mostly
//     the templates' own: the body-centred lattice has a unique Delaunay
//     tetrahedralization, which is the paired faces' tets; at 2:1
//     transitions the ties give other tets, a fifth of the core's under
//     40 degrees on elephant r1, which the optimizer then improves); the
//     front becomes the boundary of what is left: the input triangles
//     with no kept tet on their material side (in the surface's order,
//     first), then the faces of kept tets whose other side is not kept,
//     oriented away from them. Gap vertices no kept tet uses stay free
//     (moved after the used ones), the others are meshed.
// The result is what the front's removals would start from had they made
// the kept tets themselves: every kept tet lies inside the surface and
// meets no input triangle beyond its own vertices, edges and faces.
// Deterministic.
#pragma once

#include <cstddef>

#include "core/tet_mesh.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"

namespace partet {

// The fill runs on surfaces of more triangles than this. On smaller ones
// the removals take milliseconds, and with the optimizer's alternatives
// for small meshes (pass_alternatives.hpp, cone_alternative.hpp) the
// front's meshes keep the best smallest angles on the small symmetric
// bodies (star 47.9 against 45.0 degrees with the fill, the octahedron
// and icosahedron refined once 54.7 and 58.3 against 52.2 and 33.6).
constexpr size_t kDelaunayFillTriangles = 1000;

struct DelaunayFillCounts {
  size_t delaunay_tets = 0;       // finite tets of the tetrahedralization
  size_t recovered_edges = 0;     // input edges made by edge removals (edge_recovery.hpp)
  size_t recovered_faces = 0;     // input triangles made faces by edge removals with them (edge_recovery.hpp)
  size_t missing_triangles = 0;   // input triangles that are not faces after them
  size_t removed_tets = 0;        // tets meeting one of them, and the flat flipped ones (step 2)
  size_t kept_tets = 0;
  size_t dropped_components = 0;  // components without a wall, or with walls on both sides
  size_t walk_steps = 0;          // tets visited locating the points
  size_t cavity_tets = 0;         // tets replaced by the insertions
};

// `front` must come from make_initial_front over `tree` (free vertices
// added or not); `mesh` is the templated core whose vertices are the
// front's first core_vertices. Replaces `mesh` by the kept tets over all the
// front's vertices (xyz and global ids as the front's) and the front's
// faces and free vertices by what is left (vertex numbering unchanged
// except within the free vertices).
DelaunayFillCounts delaunay_fill(InitialFront& front, const LinearOctree& tree, TetMesh& mesh);

}  // namespace partet
