// Exact segment and triangle intersection tests (see intersections.hpp).
//
// Method. A segment against a triangle: the sides of its endpoints relative
// to the triangle's plane (orient3d); strictly one side: disjoint; crossing:
// the crossing point is in the closed triangle iff the three orientations
// of (p, q, edge) have no strictly opposite signs; in the plane: a 2-D test
// in the coordinate projection that keeps the triangle non-degenerate (an
// affine bijection of the plane, so it preserves incidence exactly). Two
// triangles meet iff an edge of one meets the other.
//
// Two triangles of one surface are first tried for a cheap proof that they
// do not conflict: the filtered orientations against a plane, then a
// separating line in one coordinate projection (any projection: triangles
// whose projections are disjoint are disjoint). On a refined surface most
// neighbours are exactly coplanar, where orient3d can only answer by its
// exact path; the projected tests, all exact orient2d, decide them in the
// filter. Only pairs neither proof clears take the full test, so the
// answers are those of the full test alone.
#include "core/intersections.hpp"

#include <cmath>

#include "core/predicates.hpp"

namespace partet {
namespace {

// True when the signs contain both a strictly positive and a strictly
// negative one.
bool mixed_signs(int s1, int s2, int s3) {
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  return positive && negative;
}

bool same_strict_side(int s1, int s2) { return (s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0); }

// A coordinate axis whose projection keeps triangle abc non-degenerate
// (2 when there is none, i.e. abc is degenerate).
int projection_axis(const double* a, const double* b, const double* c) {
  for (int drop = 2; drop >= 0; --drop)
    if (orient2d_projected(a, b, c, drop) != 0) return drop;
  return 2;
}

// In the projection dropping `drop`: r, known collinear with p and q, lies
// on the closed segment pq.
bool within_segment(const double* p, const double* q, const double* r, int drop) {
  for (int k = 0; k < 3; ++k) {
    if (k == drop) continue;
    const double lo = p[k] < q[k] ? p[k] : q[k];
    const double hi = p[k] < q[k] ? q[k] : p[k];
    if (r[k] < lo || r[k] > hi) return false;
  }
  return true;
}

// Closed segments pq and rs meet, in the projection dropping `drop`.
bool segments_meet_2d(const double* p, const double* q, const double* r, const double* s, int drop) {
  const int o1 = orient2d_projected(p, q, r, drop);
  const int o2 = orient2d_projected(p, q, s, drop);
  const int o3 = orient2d_projected(r, s, p, drop);
  const int o4 = orient2d_projected(r, s, q, drop);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && within_segment(p, q, r, drop)) return true;
  if (o2 == 0 && within_segment(p, q, s, drop)) return true;
  if (o3 == 0 && within_segment(r, s, p, drop)) return true;
  if (o4 == 0 && within_segment(r, s, q, drop)) return true;
  return false;
}

// Point p in the closed triangle abc, in the projection dropping `drop`
// (abc non-degenerate there: the three orientations cannot all be <= 0
// relative to its own, so "no mixed signs" means inside).
bool point_in_triangle_2d(const double* p, const double* a, const double* b, const double* c,
                          int drop) {
  return !mixed_signs(orient2d_projected(a, b, p, drop), orient2d_projected(b, c, p, drop),
                      orient2d_projected(c, a, p, drop));
}

// Closed segment pq against closed triangle abc, all in one plane.
bool segment_triangle_coplanar(const double* p, const double* q, const double* a, const double* b,
                               const double* c) {
  const int drop = projection_axis(a, b, c);
  return point_in_triangle_2d(p, a, b, c, drop) || point_in_triangle_2d(q, a, b, c, drop) ||
         segments_meet_2d(p, q, a, b, drop) || segments_meet_2d(p, q, b, c, drop) ||
         segments_meet_2d(p, q, c, a, drop);
}

// Segment pq against triangle abc, given sp = orient3d(a, b, c, p) and
// sq = orient3d(a, b, c, q).
bool segment_triangle_with_sides(const double* p, const double* q, int sp, int sq, const double* a,
                                 const double* b, const double* c) {
  if (same_strict_side(sp, sq)) return false;
  if (sp == 0 && sq == 0) return segment_triangle_coplanar(p, q, a, b, c);
  if (sp == 0 || sq == 0) {
    const double* on_plane = sp == 0 ? p : q;
    return point_in_triangle_2d(on_plane, a, b, c, projection_axis(a, b, c));
  }
  return !mixed_signs(orient3d(p, q, a, b), orient3d(p, q, b, c), orient3d(p, q, c, a));
}

// Coplanar closed triangles: an edge crossing or one inside the other.
bool triangles_intersect_coplanar(const double* const a[3], const double* const b[3]) {
  const int drop = projection_axis(a[0], a[1], a[2]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_meet_2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], drop)) return true;
  return point_in_triangle_2d(a[0], b[0], b[1], b[2], drop) ||
         point_in_triangle_2d(b[0], a[0], a[1], a[2], drop);
}

// The coordinate axis along which the normal of triangle abc is largest,
// in floating point: the projection dropping it is the least distorted.
// The tests below verify exactly whatever they need of it.
int dominant_axis(const double* a, const double* b, const double* c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz), std::fabs(ux * vy - uy * vx)};
  return n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
}

// In the projection dropping `drop`: the line through an edge of t has the
// three vertices of o strictly on the side away from t (t degenerate
// there: on either side). Then the projections, so the triangles, are
// disjoint.
bool edge_separates_2d(const double* const t[3], const double* const o[3], int drop) {
  const int side = orient2d_projected(t[0], t[1], t[2], drop);
  for (int i = 0; i < 3; ++i) {
    const double* p = t[i];
    const double* q = t[(i + 1) % 3];
    const int first = orient2d_projected(p, q, o[0], drop);
    if (first == 0 || first == side) continue;
    if (orient2d_projected(p, q, o[1], drop) == first && orient2d_projected(p, q, o[2], drop) == first)
      return true;
  }
  return false;
}

// Triangles a and b, sharing no vertex, are proved disjoint: b strictly on
// one side of a's plane by the filter alone, or a separating edge in the
// projection that suits a.
bool disjoint_cheaply(const double* const a[3], const double* const b[3]) {
  const PlaneSide plane(a[0], a[1], a[2]);
  const int s0 = plane.filtered(b[0]);
  if (s0 != 0 && plane.filtered(b[1]) == s0 && plane.filtered(b[2]) == s0) return true;
  const int drop = dominant_axis(a[0], a[1], a[2]);
  return edge_separates_2d(a, b, drop) || edge_separates_2d(b, a, drop);
}

// Triangles (v, a1, a2) and (v, b1, b2) are proved to meet only in v: in the
// projection that suits the first, both project to proper triangles (so the
// projection is one to one on each) and the line through v along an edge of
// one has the other's two far vertices strictly on the side away from it.
// Then the projections meet only in v's image, and the triangles only in v.
bool meet_only_at_apex_2d(const double* v, const double* a1, const double* a2, const double* b1,
                          const double* b2) {
  const int drop = dominant_axis(v, a1, a2);
  const int sa = orient2d_projected(v, a1, a2, drop);
  const int sb = orient2d_projected(v, b1, b2, drop);
  if (sa == 0 || sb == 0) return false;
  // Along v->x, with the cone's own far vertex on side `own`: both of the
  // other's far vertices on the side -own.
  auto clears = [drop](const double* v0, const double* x, int own, const double* p, const double* q) {
    return orient2d_projected(v0, x, p, drop) == -own && orient2d_projected(v0, x, q, drop) == -own;
  };
  return clears(v, a1, sa, b1, b2) || clears(v, a2, -sa, b1, b2) || clears(v, b1, sb, a1, a2) ||
         clears(v, b2, -sb, a1, a2);
}

}  // namespace

bool points_collinear(const double* a, const double* b, const double* c) {
  return orient2d_projected(a, b, c, 0) == 0 && orient2d_projected(a, b, c, 1) == 0 &&
         orient2d_projected(a, b, c, 2) == 0;
}

bool segment_triangle_intersect(const double* p, const double* q, const double* a,
                                const double* b, const double* c) {
  return segment_triangle_with_sides(p, q, orient3d(a, b, c, p), orient3d(a, b, c, q), a, b, c);
}

bool triangles_intersect(const double* const a[3], const double* const b[3]) {
  int side_b[3];  // vertices of b relative to the plane of a
  for (int i = 0; i < 3; ++i) side_b[i] = orient3d(a[0], a[1], a[2], b[i]);
  if (same_strict_side(side_b[0], side_b[1]) && same_strict_side(side_b[1], side_b[2])) return false;
  if (side_b[0] == 0 && side_b[1] == 0 && side_b[2] == 0) return triangles_intersect_coplanar(a, b);
  int side_a[3];  // vertices of a relative to the plane of b
  for (int i = 0; i < 3; ++i) side_a[i] = orient3d(b[0], b[1], b[2], a[i]);
  if (same_strict_side(side_a[0], side_a[1]) && same_strict_side(side_a[1], side_a[2])) return false;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segment_triangle_with_sides(a[i], a[j], side_a[i], side_a[j], b[0], b[1], b[2])) return true;
    if (segment_triangle_with_sides(b[i], b[j], side_b[i], side_b[j], a[0], a[1], a[2])) return true;
  }
  return false;
}

bool surface_triangles_conflict(const double* const a[3], const uint32_t ia[3],
                                const double* const b[3], const uint32_t ib[3]) {
  int shared = 0;
  int match_a[3] = {-1, -1, -1};  // index in b of the vertex of a with the same id
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (ia[i] == ib[j]) {
        match_a[i] = j;
        ++shared;
      }
    }
  }
  if (shared == 0) return !disjoint_cheaply(a, b) && triangles_intersect(a, b);
  if (shared >= 3) return true;
  if (shared == 1) {
    int i = 0;
    while (match_a[i] < 0) ++i;
    const int j = match_a[i];
    const double* a1 = a[(i + 1) % 3];
    const double* a2 = a[(i + 2) % 3];
    const double* b1 = b[(j + 1) % 3];
    const double* b2 = b[(j + 2) % 3];
    const PlaneSide plane_b(b[0], b[1], b[2]);
    const int fa1 = plane_b.filtered(a1);
    if (fa1 != 0 && plane_b.filtered(a2) == fa1) return false;
    if (meet_only_at_apex_2d(a[i], a1, a2, b1, b2)) return false;
    // a1, a2 strictly on one side of b's plane: a meets that plane only in
    // the shared vertex (the common case on a smooth surface); and vice versa.
    const int sa1 = orient3d(b[0], b[1], b[2], a1);
    const int sa2 = orient3d(b[0], b[1], b[2], a2);
    if (same_strict_side(sa1, sa2)) return false;
    const int sb1 = orient3d(a[0], a[1], a[2], b1);
    const int sb2 = orient3d(a[0], a[1], a[2], b2);
    if (same_strict_side(sb1, sb2)) return false;
    return segment_triangle_with_sides(a1, a2, sa1, sa2, b[0], b[1], b[2]) ||
           segment_triangle_with_sides(b1, b2, sb1, sb2, a[0], a[1], a[2]);
  }
  // A shared edge: apexes are the unmatched vertices.
  int apex_a = 0;
  while (match_a[apex_a] >= 0) ++apex_a;
  int apex_b = 0;
  while (apex_b == match_a[0] || apex_b == match_a[1] || apex_b == match_a[2]) ++apex_b;
  // The apexes strictly on opposite sides of the edge's line in a
  // projection that keeps a proper: no conflict. Coplanar, they are on
  // opposite sides in their plane too (the projection is one to one on it);
  // not coplanar, the triangles meet only along the edge anyway.
  const double* u = a[(apex_a + 1) % 3];
  const double* w = a[(apex_a + 2) % 3];
  int drop = dominant_axis(u, w, a[apex_a]);
  int side_a = orient2d_projected(u, w, a[apex_a], drop);
  if (side_a == 0) {
    drop = projection_axis(u, w, a[apex_a]);
    side_a = orient2d_projected(u, w, a[apex_a], drop);
  }
  const int side_b = orient2d_projected(u, w, b[apex_b], drop);
  if (side_a * side_b < 0) return false;
  return orient3d(a[0], a[1], a[2], b[apex_b]) == 0;
}

}  // namespace partet
