// The face rule of the interior-leaf templates: how one square face of an
// interior leaf is triangulated, as a function of the points lying on that
// face alone, so that the two sides of a face (possibly on two ranks)
// triangulate it identically without talking to each other.
//
// Leaf lattice. The points a template uses are the 27 points of its leaf's
// 3x3x3 lattice: t in {0,1,2}^3, point = anchor + t * (edge / 2), indexed
// t0 + 3 t1 + 9 t2. Corners have every t_i in {0,2}, edge midpoints one t_i
// equal to 1, face centres two, the leaf centre (index 13) three.
//
// The vertex set V is the set of corners of interior leaves (a global fact,
// the same on every rank). For a face F of an interior leaf, with corners,
// four edge midpoints and a centre:
//  - fanned: if F's centre or any of its midpoints is in V, F's centre
//    becomes a vertex (a "virtual" one when it is not in V: both sides add
//    it by the same rule) and F is fanned from it over its boundary polygon:
//    the four corners and the midpoints that are in V, in order;
//  - diagonal: otherwise F is split into two triangles by the diagonal that
//    joins its (even, even) corner to its (odd, odd) corner, coordinates in
//    units of F's own edge (exactly one corner of F is (even, even)).
// Every face triangle is coned to the leaf centre, unless the face is
// paired with an interior leaf of the same level: then the face's boundary
// polygon is split around the axis between the two centres
// (template_mesh.hpp).
//
// Why this conforms in a tree 2:1 balanced across faces and edges (leaves
// sharing part of a face or of an edge differ by at most one level):
//  - two leaves of the same level sharing F see the same points of V on F,
//    hence the same triangulation;
//  - a coarse face G of level l against finer leaves: the leaves touching G
//    from the other side share part of G, so they have level exactly l+1;
//    a leaf with a corner inside an edge of G shares part of that edge, so
//    its level is at most l+1. Hence the points of V on G are among its corners,
//    midpoints and centre, and a quadrant Q of G (a face of a level-(l+1)
//    leaf) carries no point of V but its corners: its own midpoints and
//    centre are odd multiples of edge/4 on G's edges or inside G. Q is
//    split by its diagonal from its (even, even) corner (a corner of G,
//    since G's coordinates are even multiples of Q's edge) to its (odd, odd)
//    corner (G's centre). If a fine leaf across Q is interior, its corners
//    (G's centre and two midpoints of G) are in V, so G is fanned from its
//    centre, and G's fan triangles inside Q, (centre, corner, midpoint) and
//    (centre, midpoint, corner), are exactly Q's two triangles. A fan
//    triangle (centre, corner, corner) over a missing midpoint spans two
//    quadrants whose fine leaves are both not interior (an interior one
//    would have put the midpoint in V): no tet lies across it, it is exposed;
//  - an edge e of the triangulation on a leaf edge is split at its midpoint
//    on all faces around it or on none (the midpoint is in V or not), so
//    faces that only meet along an edge, e.g. exposed faces of two interior
//    leaves that share only an edge, still match;
//  - a quadrant Q seen from a coarser leaf is never fanned, so no face
//    centre ever falls on a coarser leaf's face.
// The same argument gives `leaf_neighbourhood.hpp` its invariant: every
// template vertex lies on the child-anchor lattice of the leaf containing it.
#pragma once

#include <cstdint>

namespace partet {

constexpr int kLeafPoints = 27;
constexpr int kLeafCentre = 13;
constexpr int leaf_point(int tx, int ty, int tz) { return tx + 3 * ty + 9 * tz; }

// Faces f = 2 * axis + side (side 1: the face at the upper coordinate). The
// in-face axes are u = (axis + 1) % 3 and v = (axis + 2) % 3, so u x v is
// the +axis direction.
constexpr int kLeafFaces = 6;
constexpr int face_axis(int f) { return f >> 1; }
constexpr int face_side(int f) { return f & 1; }
constexpr int face_u(int f) { return (face_axis(f) + 1) % 3; }
constexpr int face_v(int f) { return (face_axis(f) + 2) % 3; }

// Leaf point of face f at in-face lattice coordinates (pu, pv) in {0,1,2}^2.
constexpr int face_point(int f, int pu, int pv) {
  int t[3] = {0, 0, 0};
  t[face_axis(f)] = 2 * face_side(f);
  t[face_u(f)] = pu;
  t[face_v(f)] = pv;
  return leaf_point(t[0], t[1], t[2]);
}
constexpr int face_centre(int f) { return face_point(f, 1, 1); }
// Midpoint k of face f, counterclockwise about +axis: (1,0), (2,1), (1,2), (0,1).
constexpr int face_midpoint(int f, int k) {
  constexpr int kU[4] = {1, 2, 1, 0}, kV[4] = {0, 1, 2, 1};
  return face_point(f, kU[k], kV[k]);
}

// Face cases: 0..15 fanned, the value being the mask of the midpoints (bit
// k: face_midpoint(f, k)) on the fan's boundary polygon; 16 the diagonal
// (0,0)-(2,2); 17 the diagonal (2,0)-(0,2) (in-face lattice coordinates).
constexpr int kFaceCases = 18;
constexpr int kDiagonalCase = 16;
constexpr uint8_t kNoFaceCase = 0xFF;  // not an interior leaf

// The diagonal case of face f of a leaf whose anchor is `anchor` (grid
// units) and edge `edge`: the (even, even) corner is in-face corner
// (e_u, e_v) with e = (anchor / edge) & 1, and the diagonal joins (0,0) to
// (2,2) when e_u == e_v, (2,0) to (0,2) otherwise.
inline int diagonal_case(int f, const uint32_t* anchor, uint32_t edge) {
  uint32_t eu = anchor[face_u(f)] / edge, ev = anchor[face_v(f)] / edge;
  return kDiagonalCase + static_cast<int>((eu ^ ev) & 1);
}

struct FaceTriangle {
  uint8_t p[3];      // leaf points, counterclockwise seen from outside the leaf
  uint8_t quadrant;  // in-face quadrant it lies in: bit 0 upper u half, bit 1 upper v half
};
struct FaceTriangulation {
  uint8_t count;
  FaceTriangle tri[8];
};

// The triangles of face f in case c. The quadrant of a triangle is where
// its centroid lies, ties going to the lower half; a fan triangle over a
// missing midpoint and both triangles of a diagonal case lie over
// quadrants that are all covered by the same leaf or all exposed (see
// above), so testing the one quadrant tells whether the triangle is shared.
const FaceTriangulation& face_triangulation(int f, int c);

// The 12 edge midpoints of a leaf (the odd leaf points but the centre).
constexpr int kLeafEdges = 12;
inline constexpr uint8_t kEdgeMidpoints[kLeafEdges] = {1, 3, 5, 7, 9, 11, 15, 17, 19, 21, 23, 25};
// The 8 corners, corner c at t = 2 * (c & 1, c >> 1 & 1, c >> 2 & 1).
constexpr int corner_point(int c) {
  return leaf_point(2 * (c & 1), 2 * (c >> 1 & 1), 2 * (c >> 2 & 1));
}

}  // namespace partet
