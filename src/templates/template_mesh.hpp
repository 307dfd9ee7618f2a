// Step 2 of the pipeline: template meshing of the interior leaves. Every
// leaf of class kInterior is split into positively oriented tets around its
// centre, which becomes a vertex. Each of its six faces, with its boundary
// polygon given by the face rule (face_rule.hpp: the corners and the edge
// midpoints in V), is
//  - paired, when the leaf across it is an interior leaf of the same level:
//    the double pyramid over the face between the two centres is split
//    around their axis, one tet (a, b, other centre, centre) per boundary
//    segment (a, b), made by the leaf with the lower key. Over a face with
//    no midpoint these are the tets of the body-centred cubic lattice
//    (dihedral angles 60 and 90 degrees, radius ratio 0.95, against 0.64
//    for a face triangle coned to a centre);
//  - coned otherwise: every triangle of its face-rule triangulation is
//    coned to the centre.
// A leaf makes 0 to 48 tets. The faces inside a leaf are triangles (centre,
// a, b) over the boundary segments of its faces, which the face rule
// splits the same way on every face around an edge, so the tets of the six
// faces meet face to face whatever each face's kind. A face's treatment
// depends only on the points of V on it and the two leaves sharing it, so
// the templates of neighbouring leaves conform with no communication, also
// across ranks.
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
// in order, a triangle (a, b, c) (outward) giving the tet (a, c, b, centre),
// or one tet per boundary segment of a paired face the leaf makes, from
// in-face corner (0, 0) counterclockwise about +axis. The last vertex of
// every tet is the centre of the leaf that made it.
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

// The leaf across face f of interior leaf i when the two share that face
// whole and are both interior (same level): the face is then not coned to
// either centre but split around the axis between them (see above).
// kAbsentLeaf otherwise.
uint32_t paired_leaf(const LinearOctree& tree, size_t i, int f);

// Number of tets interior leaf i makes over its face f in case face_case:
// the face triangles when coned; when paired, one per boundary segment for
// the leaf with the lower key, none for the other.
uint32_t face_tets(const LinearOctree& tree, size_t i, int f, int face_case);

// One rank's part: `view` is its local view (octree/ghost_layer.hpp), whose
// own leaves (owner `part`) are templated; its layer-1 leaves add their
// corners to V. The vertices are those of the part's tets, numbered as above
// among themselves (ascending global id), so the parts of all ranks put
// together are template_interior of the whole tree: the same tets, in the
// same order rank after rank, with the same global ids and coordinates.
TemplateCore template_interior(const LinearOctree& view, const RootCube& root, int32_t part);

}  // namespace partet
