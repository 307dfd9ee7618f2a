// Exact intersection tests between points, segments and triangles in 3-D,
// built on the exact predicates: every answer is exact for finite doubles.
// All sets are closed (touching counts as intersecting). Triangles must be
// non-degenerate (vertices not collinear) unless a function says otherwise.
#pragma once

#include <cstdint>

namespace partet {

// True when a, b, c lie on one line, including when some of them coincide.
bool points_collinear(const double* a, const double* b, const double* c);

// Closed segment pq against closed triangle abc, including the coplanar
// case (the segment overlapping the triangle or touching its boundary) and
// an endpoint on the triangle. p == q is allowed (then: is p in abc).
bool segment_triangle_intersect(const double* p, const double* q, const double* a,
                                const double* b, const double* c);

// Closed triangles a and b (three vertices each) share at least one point.
bool triangles_intersect(const double* const a[3], const double* const b[3]);

// Two triangles of one surface, each with its vertex ids: true when they
// meet anywhere other than in what they share by id. Sharing is decided by
// ids only: distinct ids at equal coordinates are an intersection.
//  - no shared id: triangles_intersect;
//  - one shared vertex v, a = (v, a1, a2), b = (v, b1, b2): segment a1a2
//    meets b or segment b1b2 meets a;
//  - a shared edge uw with apexes p (of a) and q (of b): u, w, p, q are
//    coplanar and p, q lie on the same side of line uw (or q on it): the
//    triangles fold onto each other;
//  - three shared ids (a duplicate triangle): true.
bool surface_triangles_conflict(const double* const a[3], const uint32_t ia[3],
                                const double* const b[3], const uint32_t ib[3]);

}  // namespace partet
