// A mesh cut into parts along its faces, each part a mesh of its own, and
// the parts joined back: how the optimizer runs on the ranks' parts (paper
// §4.1 steps 11-12). A part's faces on a cut are faces of one tet in it, so
// optimize_mesh treats them as boundary: their vertices are frozen and
// they keep their three vertices and side. What each part does inside
// (moves, flips, insertions, collapses) therefore leaves the cuts as they
// were, and the parts joined back are a conforming mesh of the same
// region with the same boundary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tet_mesh.hpp"

namespace partet {

struct MeshPart {
  TetMesh mesh;                 // the part's tets on its own vertices (split_mesh adds no boundary triangles)
  std::vector<uint32_t> whole;  // per part vertex: its index in the whole mesh, ascending
  std::vector<uint8_t> on_cut;  // per part vertex: 1 when a tet outside the part uses it
};

// The tets of part p (part_of_tet[t] == p, in tet order) on the vertices
// they use (in whole-mesh order). `part_of_tet` has one entry per tet, each
// below `parts` or negative (the tet is in no part).
std::vector<MeshPart> split_mesh(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet, int parts);

// The inverse of split_mesh after the parts changed inside: every tet in a
// part is replaced by its part's tets now (in part order, then the tets in
// no part, in their order), the part vertices' coordinates (moved ones) are
// copied back, and vertices a part added (beyond `whole`) are appended, part
// by part. Vertices a part left unused stay, unused (drop_unused_vertices).
// The boundary triangles stay as they are (their vertices never move);
// `mesh.global_ids` must be empty. Returns the part of each tet now (-1
// for those in no part).
std::vector<int32_t> join_parts(TetMesh& mesh, const std::vector<int32_t>& part_of_tet,
                                const std::vector<MeshPart>& parts);

// Per vertex: 1 when tets of two parts use it (it lies on a cut); the tets
// in no part (a negative part) count as one more part.
std::vector<uint8_t> cut_vertices(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet);

// Per tet, its ring around the marked vertices: 0 for a tet with a marked
// vertex, k for one sharing a vertex with ring k - 1 and in none before,
// -1 beyond ring `layers`. `marked` has one flag per vertex.
std::vector<int> tet_rings(const TetMesh& mesh, std::vector<uint8_t> marked, int layers);

// The tets with a marked vertex, grown by `layers` rings of tets (tets
// sharing a vertex with the band): those of tet_rings at or under `layers`.
std::vector<uint8_t> band_around(const TetMesh& mesh, std::vector<uint8_t> marked, int layers);

}  // namespace partet
