// The initial front: what is left to mesh once the interior leaves are
// templated, as oriented triangles facing the unmeshed region (the gap
// between the surface and the templated core):
//  - the surface triangles, reversed: the diagnosed surface faces outward
//    from the material, the front faces into it;
//  - the exposed faces of the core (faces of templated tets used by one
//    tet), oriented away from their tet, i.e. into the gap.
// Interior leaves do not meet the surface (a leaf meeting it is a boundary
// leaf), so the two sheets share no vertex and no edge: each is closed on
// its own (the core sheet may have edges and vertices where two interior
// leaves touch along an edge or at a point only: non-manifold, but every
// edge is used equally often in both directions).
//
// Vertices. One numbering joins the core and the surface: the core's
// vertices first, with the core's indices (0 .. core_vertices-1), then the
// surface's vertices in the surface's order. Global ids: a core vertex has
// its lattice Morton key (below 2^63), surface vertex s has
// kSurfaceVertexId | s. Every vertex knows the leaf whose half-open box
// contains it, and the front vertices (those used by front faces, and the
// free ones) are listed leaf by leaf.
//
// Free vertices come last (add_free_vertices): points inside the unmeshed
// region that no face uses yet, given to the removals as targets (the gap
// vertices, gap_vertices.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "surface/surface_mesh.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

constexpr uint64_t kSurfaceVertexId = uint64_t{1} << 63;

struct InitialFront {
  size_t core_vertices = 0;
  std::vector<double> xyz;            // 3 per joint vertex
  std::vector<uint64_t> global_ids;   // per joint vertex (see above)
  std::vector<uint32_t> vertex_leaf;  // per joint vertex: the leaf containing it
  // 3 joint vertex indices per front face, counterclockwise seen from the
  // unmeshed region. The first `surface_faces` faces are the reversed
  // surface triangles, in the surface's order; then the core's exposed
  // faces, leaf by leaf in tet order.
  std::vector<uint32_t> faces;
  size_t surface_faces = 0;
  size_t free_vertices = 0;  // the last free_vertices vertices: used by no face
  // Per leaf + 1: the front vertices contained in leaf i are
  // front_vertices[leaf_first_front_vertex[i] .. leaf_first_front_vertex[i+1]),
  // ascending.
  std::vector<uint32_t> leaf_first_front_vertex;
  std::vector<uint32_t> front_vertices;

  size_t num_faces() const { return faces.size() / 3; }
};

// The leaf whose half-open box contains point p, from exact comparisons
// with lattice coordinates; points outside the root cube are clamped into it.
uint32_t leaf_of_point(const LinearOctree& tree, const RootCube& root, const double* p);

// `core` must come from template_interior(tree, root); `surface` is the
// diagnosed (outward oriented) surface the tree was built from.
InitialFront make_initial_front(const LinearOctree& tree, const RootCube& root,
                                const TemplateCore& core, const SurfaceMesh& surface);

// Appends free vertices at `xyz` (3 per vertex) with global ids `ids`
// (disjoint from the others), each in the leaf given by `leaf` (which must
// contain it), and lists them as front vertices.
void add_free_vertices(InitialFront& front, const LinearOctree& tree, const std::vector<double>& xyz,
                       const std::vector<uint64_t>& ids, const std::vector<uint32_t>& leaf);

// Lists the front vertices leaf by leaf again (those used by faces and the
// free ones): a counting sort by leaf, stable in index. For callers that
// change the faces or the free vertices.
void list_front_vertices(InitialFront& front, size_t leaves);

// The front as a surface mesh of its faces and the vertices they use (for
// --front-out), in the front's face order and joint vertex order.
SurfaceMesh front_surface(const InitialFront& front);

}  // namespace partet
