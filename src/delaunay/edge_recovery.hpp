// Input edges recovered in a Delaunay tetrahedralization by flips.
//
// An input triangle that is not a Delaunay face nearly always lacks an
// edge. Triangles split 1:4 are coplanar in fours, and their quads are
// mostly not Delaunay: for edge ac, shared by input triangles abc and acd,
// the tetrahedralization holds the other diagonal bd instead, with a and
// c on its ring of tets; on CAD surfaces long triangles lose edges that
// cross a few tets. Each edge recovered makes its input triangles faces
// (when their other edges are there), which the Delaunay fill then keeps
// as walls instead of removing every tet they cut and leaving the hole to
// the front's face removals (femur refined once: 9,097 missing triangles
// -> 1,800).
//
// For each edge of a missing input triangle, in key order, over rounds
// while one succeeds (at most kMaxRecoveryRounds), the first of these that
// applies and is valid:
//  1. removal of bd with the chord ac: the ring's polygon triangulated
//     with the chord, each triangle coned to b and to d; of those whose
//     every tet is positive by exact orient3d, the one whose worst tet has
//     the largest shape measure (shape_measure.hpp; dynamic programming
//     over the polygon's sub-chains). When one side of the chord has no
//     such triangulation and holds a single ring vertex x, the 2-3 flip of
//     the two ring tets on (b, d, x) instead (bd stays);
//  2. walking segment ac from a through the tets (exact orient3d): when
//     it leaves a through an edge of a's star, the removal of that edge
//     with the chord; when it crosses one face, the 2-3 flip of that face;
//     when the faces it crosses all share an edge, the removal of that
//     edge with the chord; otherwise 2-3 flips of the first face crossed
//     from a (or, where that one is not convex, from c), each leaving one
//     face fewer to cross, down to the last.
// An edge uv is removed only when it is not an input edge and its ring
// closes (not on the enclosing tet's faces) within kMaxRecoveryRing tets;
// a 2-3 flip never takes an input triangle's face. So no flip destroys an
// input edge or face: every round keeps what the earlier ones recovered,
// and a round that recovers nothing ends them. A walk that meets an edge
// or a vertex after its start is not followed. The result is a
// tetrahedralization of the same points (no longer Delaunay near the
// recovered edges), every tet positive, adjacency kept. Deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "delaunay/delaunay.hpp"

namespace partet {

// Rings longer than this are not removed.
inline constexpr int kMaxRecoveryRing = 12;

struct EdgeRecoveryCounts {
  size_t missing_triangles = 0;  // input triangles that were not faces at the start
  size_t recovered_edges = 0;
  size_t rounds = 0;
};

// `triangles`: the input triangles, 3 vertex indices of `d` each (oriented
// either way; an edge on other than two of them is left alone). Recovers
// missing input edges as the file comment says; `flipped` gets a flag per
// tet of the result, set on those a flip made.
EdgeRecoveryCounts recover_input_edges(DelaunayTets& d, std::span<const uint32_t> triangles,
                                       std::vector<uint8_t>& flipped);

}  // namespace partet
