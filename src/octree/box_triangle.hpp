// Axis-aligned box against triangle: an exact intersection test for the
// closed sets (the boundary-leaf decision) and a floating-point "nearer
// than r" test (the too-close heuristic).
//
// box_meets_triangle is exact for all finite doubles: it is the separating
// axis test with every axis decided by an exact predicate. Two compact convex
// sets are disjoint iff some axis strictly separates their projections, and
// for a box and a triangle the axes to try are the three box normals (exact
// coordinate comparisons: the bounding-box rejection), the triangle's normal
// (all 8 box corners strictly on one side: orient3d) and the 9 cross
// products of a box axis with a triangle edge. Those last are 2-D tests in the
// coordinate projection along the box axis: the projected box is a square and
// the projected triangle a triangle or a segment; by the 2-D separating axis
// theorem (a separating line can be chosen through an edge of one of the two
// polygons) they are disjoint iff the square is strictly outside the line of
// a projected triangle edge (orient2d; for a projected segment, strictly on
// either side) or separated along x or y (bounding boxes). Each test needs
// only the box corner that is extreme along the axis, and that corner is
// known exactly: per coordinate, from the sign of a coordinate difference
// (edge axes) or of the projected triangle's orientation (the normal). A
// triangle vertex inside the box is accepted first, as a shortcut, and the
// same axes in doubles with error bounds decide the clear cases (most of
// them) before any exact predicate runs.
#pragma once

namespace partet {

// Closed box [lo, hi] (lo <= hi componentwise) meets closed triangle abc
// (non-degenerate: the vertices are not collinear). Exact.
bool box_meets_triangle(const double* lo, const double* hi, const double* a, const double* b, const double* c);

// The same for the box with its upper face left out on the axes where
// open[k] is true: [lo_k, hi_k) there, [lo_k, hi_k] elsewhere (lo < hi on
// the open axes). Exact: the closed test on [lo, hi - eps] for an
// infinitesimal eps > 0 (symbolic perturbation). Half-open leaf boxes
// tile the root cube, so a point lies in exactly one of them.
bool box_meets_triangle_half_open(const double* lo, const double* hi, const bool* open, const double* a,
                                  const double* b, const double* c);

// One triangle against many boxes (the leaves a triangle's bounding box
// covers): the same answers as the two functions above, with the
// triangle's share of the work (bounding box, edges, normal, magnitudes
// for the filter's error bounds) done once. The points must outlive it.
class TriangleBoxTest {
 public:
  TriangleBoxTest(const double* a, const double* b, const double* c);
  bool meets(const double* lo, const double* hi) const;
  bool meets_half_open(const double* lo, const double* hi, const bool* open) const;

  struct Parts {
    const double* v[3];
    double e[3][3];  // e[k] = v[k + 1] - v[k]
    double n[3];     // e[0] x -e[2]
    double tlo[3], thi[3];
    double m;  // largest coordinate magnitude of the triangle
    double d;  // largest edge component magnitude
  };

 private:
  Parts parts_;
};

// Euclidean distance between closed box [lo, hi] and triangle abc is below
// r, in floating point (a heuristic, not exact). Precondition: the box and
// the triangle are disjoint; the distance is then realised by a triangle
// vertex and the box, a box corner and the triangle, or a box edge and a
// triangle edge, and cheap bounds decide most cases before those are tried.
bool box_triangle_closer_than(const double* lo, const double* hi, const double* a, const double* b,
                              const double* c, double r);

}  // namespace partet
