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
//  2. when the faces segment ac crosses all share an edge, the removal of
//     that edge with the chord;
//  3. steps from either end e of the segment, a first, at most
//     kMaxRecoverySteps, until ac is an edge: the walk from e (exact
//     orient3d) either leaves e through an edge of e's star, which is
//     removed with the chord when its ring holds both ends, else by the
//     fan of its ring from e (every new tet has e); or it crosses a face
//     first, which goes by its 2-3 flip when that is valid, else by the
//     fan from e of the ring of an edge of it that the apex across lies
//     beyond, seen from e (a 3-2 flip when the ring has three tets). Each
//     step leaves e past the tets it took away. (2-3 flips alone, from the
//     ends, left 178 of the 298 triangles of lever's vertices missing and
//     236 of the 878 of eight split once; with the fans 141 and 98; femur
//     refined once in the fill 1,901 -> 780.)
// Then, for each input triangle abc still missing whose three edges are
// edges, once: an edge pq opposite one of its edges in a tet around that
// edge, whose ring holds a, b and c, is removed by the best valid
// triangulation of its ring polygon that has the triangle abc (the
// polygon's chains between a, b and c triangulated as for a chord), so
// that abc becomes the face of the two tets the triangle makes with p and
// q (a 3-2 flip when the ring is a, b, c). Femur refined once: 780 -> 633
// triangles missing; the 64 corpus inputs 10,499 -> 9,957.
// Every new tet is positive. An edge uv is removed only when it is not an
// input edge and its ring closes (not on the enclosing tet's faces) within
// kMaxRecoveryRing tets, and only uv goes; a 2-3 flip never takes an input
// triangle's face. So no flip destroys an input edge or face: every round
// keeps what the earlier ones recovered, and a round that recovers nothing
// ends them. A walk that meets an edge or a vertex after its start is not
// followed; the steps taken for an edge that is not recovered in the end
// stay (valid tets, not Delaunay). The result is a tetrahedralization of
// the same points (no longer Delaunay near the recovered edges), every tet
// positive, adjacency kept. Deterministic.
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
  size_t recovered_faces = 0;    // missing triangles whose edges were all there, made faces
  size_t rounds = 0;
};

// `triangles`: the input triangles, 3 vertex indices of `d` each (oriented
// either way; an edge on other than two of them is left alone). Recovers
// missing input edges as the file comment says; `flipped` gets a flag per
// tet of the result, set on those a flip made.
EdgeRecoveryCounts recover_input_edges(DelaunayTets& d, std::span<const uint32_t> triangles,
                                       std::vector<uint8_t>& flipped);

}  // namespace partet
