// Vertices for the gap between the surface and the templated core, given to
// the face removals before they start (paper §2.3: "all interior vertices
// have been provided by template meshing"; these are the ones the
// templates leave out).
//
// The interior leaves' centres are template vertices; the gap the front
// fills has none, so without these its tets reach from the surface straight
// to the core, half a layer to two layers away, and are flat or long. A gap
// vertex is the centre of a too-close or boundary leaf that lies inside the
// domain and at least `gap` target sizes from every surface triangle:
// distance(centre, t) >= gap * s_t for every triangle t, s_t the mean target
// size of its vertices, the same measure and threshold that keep the core
// away from the surface (octree/classify.hpp). The first layer of front
// tets on a triangle of size s wants its apex 0.82 s above it; a centre
// nearer than 0.5 s would make flat tets, and on thin walls of long
// triangles (CAD parts) it blocks the front instead of helping it.
//
// Where they lie. A too-close leaf of edge h is interior (classification
// put it inside the domain) and its centre is at least h / 2 from the
// surface and from every template vertex (those lie on interior leaves'
// boxes); a boundary leaf's centre is kept only when the exact ray parity
// test puts it inside. Leaf centres are lattice points (octree.hpp), so a
// gap vertex has exact coordinates and its lattice Morton key as global id,
// in the same id space as the template vertices and disjoint from them.
//
// Distances are in doubles: the placement is a heuristic; every decision
// the front takes on these points is exact. Cost: one range query per
// batch of nearby surface triangles (each triangle's box grown by gap *
// s_t, octree/triangle_batches.hpp) and one ray test per boundary leaf
// centre that stays.
//
// Deterministic: leaf order.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct GapVertices {
  std::vector<double> xyz;          // 3 per vertex
  std::vector<uint64_t> global_ids;  // lattice Morton keys
  std::vector<uint32_t> leaf;       // the leaf each is the centre of
  size_t size() const { return leaf.size(); }
};

// `tree` is complete and classified (classify_leaves) from `surface` with
// target sizes `vertex_size` (one per surface vertex); `gap` is the
// classification's too-close threshold in target sizes (0: no vertices).
GapVertices gap_vertices(const LinearOctree& tree, const RootCube& root, const SurfaceMesh& surface,
                         const std::vector<double>& vertex_size, double gap);

}  // namespace partet
