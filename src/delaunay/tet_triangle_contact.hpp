// Whether a tet and a triangle meet beyond what they share: exact, on
// closed sets, with sharing decided by vertex ids. The Delaunay fill
// (front/delaunay_fill.hpp) removes every Delaunay tet that meets an input
// triangle missing from the tetrahedralization this way.
//
// With S the vertices both have (by id), the answer is whether the closed
// tet K and the closed triangle T meet outside the simplex of S:
//  - S empty: whether they meet at all: an edge of K meets T, an edge of T
//    meets a face of K, or a vertex of T lies in K (two convex bodies that
//    meet have an edge of one through a facet of the other or a vertex of
//    one in the other);
//  - S = {v}: the face of K opposite v meets T, or the edge of T opposite
//    v meets K. (A common point x != v: the ray from v through x leaves K
//    on that face and T on that edge, and whichever exit comes first lies
//    in the other body.)
//  - S = {u, w}: T's third vertex p lies in the closed wedge of K at edge
//    uw (on K's side of both of K's faces through uw, or on one of them):
//    projected along uw, T is a ray from the edge and K a wedge, so T
//    enters K exactly when the ray lies in the wedge.
//  - S = T's three vertices: never (T is a face of K).
#pragma once

#include <cstdint>

namespace partet {

// K = tet (4 points, ids), positively oriented; T = triangle (3 points,
// ids), not degenerate.
bool tet_meets_triangle_beyond_shared(const double* const tet[4], const uint32_t tet_ids[4],
                                      const double* const tri[3], const uint32_t tri_ids[3]);

}  // namespace partet
