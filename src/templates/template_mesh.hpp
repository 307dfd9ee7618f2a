// Step 2 of the pipeline: template meshing of the interior leaves. Every
// leaf of class kInterior is split into positively oriented tets: its
// centre becomes a vertex and every triangle of its six faces, triangulated
// by the face rule (face_rule.hpp), is coned to it: 12 tets for a leaf
// whose faces carry no extra point, up to 48. A face's triangulation
// depends only on the points of V on that face, so the templates of
// neighbouring leaves conform with no communication, also across ranks.
//
// Contract: the tree is complete, sorted and 2:1 balanced across faces and
// edges; no interior leaf touches the far faces of the root cube (the
// lattice keys of points there would not fit 21 bits per axis; with
// make_root_cube's margin interior leaves never do). Throws InternalError
// otherwise (when detected).
//
// Output. Vertices are numbered by their home leaf (leaf_neighbourhood.hpp)
// in leaf order, then by child anchor: that is ascending lattice Morton key,
// the vertex's global id, independent of ranks. Coordinates come exactly
// from RootCube::lattice_point. Tets of leaf i are consecutive: for each
// face f = 0..5 in turn, one tet per triangle of face_triangulation(f, case)
// in order; a triangle (a, b, c) (outward) gives the tet (a, c, b, centre).
// Deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tet_mesh.hpp"
#include "octree/octree.hpp"

namespace partet {

struct TemplateCore {
  // xyz, tets; global_ids = lattice Morton keys (the vertex keys); no tris.
  TetMesh mesh;
  // Per leaf + 1: the vertices whose home is leaf i are
  // [leaf_first_vertex[i], leaf_first_vertex[i+1]).
  std::vector<uint32_t> leaf_first_vertex;
  // Per leaf + 1: the tets of leaf i are [leaf_first_tet[i], leaf_first_tet[i+1]).
  std::vector<uint64_t> leaf_first_tet;
  // 6 per leaf: the case of each face (face_rule.hpp), kNoFaceCase for
  // leaves that are not interior.
  std::vector<uint8_t> face_case;
  size_t leaves_templated = 0;
};

TemplateCore template_interior(const LinearOctree& tree, const RootCube& root);

// One rank's part: `view` is its local view (octree/ghost_layer.hpp), whose
// own leaves (owner `part`) are templated; its layer-1 leaves add their
// corners to V. The vertices are those of the part's tets, numbered as above
// among themselves (ascending global id), so the parts of all ranks put
// together are template_interior of the whole tree: the same tets, in the
// same order rank after rank, with the same global ids and coordinates.
TemplateCore template_interior(const LinearOctree& view, const RootCube& root, int32_t part);

}  // namespace partet
