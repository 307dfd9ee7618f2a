// Exact intersection tests: hand-made touching, crossing, coplanar and
// near-miss cases, the surface rules for shared vertices and edges, and
// random small-integer triangles (apart, or sharing a vertex or an edge)
// against independent oracles in integers, under symmetries and exact
// transformations.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/intersections.hpp"
#include "core/predicates.hpp"

namespace partet {
namespace {

using P = std::array<double, 3>;

bool tri_tri(const P& a0, const P& a1, const P& a2, const P& b0, const P& b1, const P& b2) {
  const double* a[3] = {a0.data(), a1.data(), a2.data()};
  const double* b[3] = {b0.data(), b1.data(), b2.data()};
  return triangles_intersect(a, b);
}

bool seg_tri(const P& p, const P& q, const P& a, const P& b, const P& c) {
  return segment_triangle_intersect(p.data(), q.data(), a.data(), b.data(), c.data());
}

// A triangle with its vertex ids.
struct Tri {
  P p[3];
  uint32_t id[3];
};

bool conflict(const Tri& s, const Tri& t) {
  const double* a[3] = {s.p[0].data(), s.p[1].data(), s.p[2].data()};
  const double* b[3] = {t.p[0].data(), t.p[1].data(), t.p[2].data()};
  return surface_triangles_conflict(a, s.id, b, t.id);
}

// conflict must not depend on argument order or on where each triangle's
// vertex list starts or which way it runs.
bool conflict_all_orders(const Tri& s, const Tri& t) {
  const bool expected = conflict(s, t);
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& ps : perms) {
    for (const auto& pt : perms) {
      Tri x, y;
      for (int i = 0; i < 3; ++i) {
        x.p[i] = s.p[ps[i]];
        x.id[i] = s.id[ps[i]];
        y.p[i] = t.p[pt[i]];
        y.id[i] = t.id[pt[i]];
      }
      EXPECT_EQ(conflict(x, y), expected);
      EXPECT_EQ(conflict(y, x), expected);
    }
  }
  return expected;
}

const P kO{0, 0, 0}, kX{1, 0, 0}, kY{0, 1, 0};

TEST(Intersections, PointsCollinear) {
  EXPECT_TRUE(points_collinear(P{0, 0, 0}.data(), P{1, 1, 1}.data(), P{2, 2, 2}.data()));
  EXPECT_TRUE(points_collinear(P{1, 2, 3}.data(), P{1, 2, 3}.data(), P{5, -1, 0}.data()));
  EXPECT_TRUE(points_collinear(P{1, 2, 3}.data(), P{1, 2, 3}.data(), P{1, 2, 3}.data()));
  EXPECT_FALSE(points_collinear(P{0, 0, 0}.data(), P{1, 1, 1}.data(), P{2, 2, std::nextafter(2.0, 3.0)}.data()));
  // Collinear along x only in a projection: not collinear in 3-D.
  EXPECT_FALSE(points_collinear(P{0, 0, 0}.data(), P{1, 0, 0}.data(), P{2, 0, 1e-300}.data()));
  // Far from the origin, exactly on a line.
  const double o = 1e15;
  EXPECT_TRUE(points_collinear(P{o, o, o}.data(), P{o + 1, o + 2, o + 3}.data(), P{o + 3, o + 6, o + 9}.data()));
  EXPECT_FALSE(points_collinear(P{o, o, o}.data(), P{o + 1, o + 2, o + 3}.data(), P{o + 3, o + 6, o + 10}.data()));
}

TEST(Intersections, SegmentTriangleCrossing) {
  EXPECT_TRUE(seg_tri({0.2, 0.2, -1}, {0.2, 0.2, 1}, kO, kX, kY));     // through the interior
  EXPECT_FALSE(seg_tri({1, 1, -1}, {1, 1, 1}, kO, kX, kY));            // beside it
  EXPECT_TRUE(seg_tri({0, 0, -1}, {0, 0, 1}, kO, kX, kY));             // through a vertex
  EXPECT_TRUE(seg_tri({0.5, 0, -1}, {0.5, 0, 1}, kO, kX, kY));         // through an edge
  EXPECT_TRUE(seg_tri({0.5, 0.5, -1}, {0.5, 0.5, 1}, kO, kX, kY));     // through the hypotenuse
  EXPECT_FALSE(seg_tri({0.2, 0.2, 0.1}, {0.3, 0.3, 1}, kO, kX, kY));   // one side
  EXPECT_TRUE(seg_tri({0.2, 0.2, 0}, {0.3, 0.3, 1}, kO, kX, kY));      // endpoint on the face
  EXPECT_FALSE(seg_tri({2, 2, 0}, {2, 2, 1}, kO, kX, kY));             // endpoint on the plane, outside
  EXPECT_TRUE(seg_tri({1, 0, 0}, {3, 3, 3}, kO, kX, kY));              // endpoint at a vertex
  // One ulp beyond the hypotenuse x + y = 1, and exactly on it.
  const double beyond = std::nextafter(0.5, 1.0);
  EXPECT_FALSE(seg_tri({0.5, beyond, -1}, {0.5, beyond, 1}, kO, kX, kY));
  EXPECT_TRUE(seg_tri({0.5, 0.5, -1e-300}, {0.5, 0.5, 1e300}, kO, kX, kY));
  // Just above the plane by the smallest subnormal.
  EXPECT_FALSE(seg_tri({0.2, 0.2, 4.9e-324}, {0.2, 0.2, 1}, kO, kX, kY));
}

TEST(Intersections, SegmentTriangleCoplanar) {
  EXPECT_TRUE(seg_tri({0.1, 0.1, 0}, {0.2, 0.2, 0}, kO, kX, kY));    // inside
  EXPECT_TRUE(seg_tri({-1, 0.5, 0}, {1, 0.5, 0}, kO, kX, kY));       // across
  EXPECT_FALSE(seg_tri({-1, -1, 0}, {-2, 5, 0}, kO, kX, kY));        // disjoint
  EXPECT_TRUE(seg_tri({-1, 0, 0}, {0.5, 0, 0}, kO, kX, kY));         // overlapping an edge
  EXPECT_FALSE(seg_tri({2, 0, 0}, {3, 0, 0}, kO, kX, kY));           // on the edge's line, beyond
  EXPECT_TRUE(seg_tri({1, 0, 0}, {2, 0, 0}, kO, kX, kY));            // touching a vertex
  EXPECT_TRUE(seg_tri({0.5, 0.5, 0}, {1, 1, 0}, kO, kX, kY));        // touching the hypotenuse
  EXPECT_FALSE(seg_tri({0.5, std::nextafter(0.5, 1.0), 0}, {1, 1, 0}, kO, kX, kY));
  EXPECT_TRUE(seg_tri({0.25, 0.25, 0}, {0.25, 0.25, 0}, kO, kX, kY));  // a point inside
  EXPECT_FALSE(seg_tri({0.75, 0.75, 0}, {0.75, 0.75, 0}, kO, kX, kY)); // a point outside
  // A vertical triangle (the x = 0 plane): its z projection is degenerate.
  const P a{0, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
  EXPECT_TRUE(seg_tri({0, 0.2, 0.2}, {0, 2, 2}, a, b, c));
  EXPECT_FALSE(seg_tri({0, 0.6, 0.6}, {0, 2, 2}, a, b, c));
}

TEST(Intersections, TrianglesHandMade) {
  EXPECT_TRUE(tri_tri(kO, kX, kY, kO, kX, kY));                                  // identical
  EXPECT_FALSE(tri_tri(kO, kX, kY, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}));            // parallel planes
  EXPECT_TRUE(tri_tri(kO, kX, kY, {1, 0, 0}, {2, 0, 1}, {2, 1, -1}));            // touching at a vertex
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.2, 0.2, 0}, {0.2, 0.2, 1}, {0.4, 0.2, 1}));  // vertex on the face
  EXPECT_TRUE(tri_tri(kO, kX, kY, {-1, 0.2, 0}, {2, 0.2, 0}, {0, 0.2, 1}));       // T-junction: edge on face
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.3, -1, 0}));  // piercing
  EXPECT_FALSE(tri_tri(kO, kX, kY, {2, 2, -1}, {2, 2, 1}, {3, 2, 0}));            // planes cross, triangles apart
  // Crossing planes where the intersection line misses one triangle.
  EXPECT_FALSE(tri_tri(kO, kX, kY, {0.6, 0.6, -1}, {0.6, 0.6, 1}, {2, 2, 0}));
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {2, 2, 0}));
  // Edge to edge, crossing at one point.
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.5, -1, 0}, {0.5, 1, 0}, {0.5, 0, 1}));
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.5, 0, -1}, {0.5, 0, 1}, {0.5, -1, 0}));
}

TEST(Intersections, TrianglesCoplanar) {
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.5, 0, 0}, {1, 1, 0}, {0, 0.5, 0}));       // overlapping
  EXPECT_FALSE(tri_tri(kO, kX, kY, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}));          // disjoint
  EXPECT_TRUE(tri_tri(kO, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}));  // one inside
  EXPECT_TRUE(tri_tri(kO, kX, kY, kX, kY, {1, 1, 0}));                         // sharing an edge
  EXPECT_TRUE(tri_tri(kO, kX, kY, kX, {2, 0, 0}, {2, 1, 0}));                  // sharing a vertex
  EXPECT_TRUE(tri_tri(kO, kX, kY, {0.5, 0.5, 0}, {1, 1, 0}, {2, 0, 0}));       // vertex on an edge
  const double e = std::nextafter(0.5, 1.0);
  EXPECT_FALSE(tri_tri(kO, kX, kY, {0.5, e, 0}, {1, 1, 0}, {2, 0, 0}));        // one ulp away
  // In the plane x + y + z = 1, no coordinate plane parallel to it.
  const P a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
  EXPECT_TRUE(tri_tri(a, b, c, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}));
  EXPECT_TRUE(tri_tri(a, b, c, {0.5, 0.5, 0}, {1.5, 0.5, -1}, {0.5, 1.5, -1}));  // touching an edge midpoint
  EXPECT_FALSE(tri_tri(a, b, c, {1, 1, -1}, {1.5, 0.5, -1}, {0.5, 1.5, -1}));
}

TEST(Intersections, SurfaceSharedEdge) {
  // Edge (0, 1) shared; apexes on opposite sides in one plane: fine.
  Tri s{{kO, kX, kY}, {0, 1, 2}};
  Tri flat{{kX, kO, {0.5, -1, 0}}, {1, 0, 3}};
  EXPECT_FALSE(conflict_all_orders(s, flat));
  // Folded at a right angle: fine.
  Tri folded{{kX, kO, {0.5, 0, 1}}, {1, 0, 3}};
  EXPECT_FALSE(conflict_all_orders(s, folded));
  // Folded completely over onto the same side: overlap.
  Tri over{{kX, kO, {0.5, 0.25, 0}}, {1, 0, 3}};
  EXPECT_TRUE(conflict_all_orders(s, over));
  // Nearly folded over, off the plane by a tiny amount: fine.
  Tri almost{{kX, kO, {0.5, 0.25, 1e-300}}, {1, 0, 3}};
  EXPECT_FALSE(conflict_all_orders(s, almost));
  // The apex beyond the far vertex, still same side: overlap.
  Tri long_over{{kX, kO, {3, 5, 0}}, {1, 0, 3}};
  EXPECT_TRUE(conflict_all_orders(s, long_over));
}

TEST(Intersections, SurfaceSharedVertex) {
  Tri s{{kO, kX, kY}, {0, 1, 2}};
  // A fan neighbour sharing only vertex 0, opposite quadrant: fine.
  Tri other{{kO, {-1, 0, 0}, {0, -1, 0}}, {0, 3, 4}};
  EXPECT_FALSE(conflict_all_orders(s, other));
  // Shared vertex, tilted away: fine.
  Tri tilted{{kO, {-1, 0, 1}, {0, -1, 1}}, {0, 3, 4}};
  EXPECT_FALSE(conflict_all_orders(s, tilted));
  // The opposite edge pierces the other triangle.
  Tri pierce{{kO, {0.2, 0.2, -1}, {0.3, 0.1, 1}}, {0, 3, 4}};
  EXPECT_TRUE(conflict_all_orders(s, pierce));
  // Coplanar, overlapping wedges at the shared vertex.
  Tri wedge{{kO, {1, 1, 0}, {-1, 1, 0}}, {0, 3, 4}};
  EXPECT_TRUE(conflict_all_orders(s, wedge));
  // An edge from the shared vertex running along an edge of the other.
  Tri along{{kO, {0.5, 0, 0}, {0.5, -1, 0}}, {0, 3, 4}};
  EXPECT_TRUE(conflict_all_orders(s, along));
  // Touching only at the shared vertex, the edge lines meeting there.
  Tri touch{{kO, {-1, 0, 0}, {-1, -1, 0}}, {0, 3, 4}};
  EXPECT_FALSE(conflict_all_orders(s, touch));
  // Shared vertex, and another vertex at the same place under another id.
  Tri twin{{kO, {0, 1, 0}, {-1, 1, 0}}, {0, 3, 4}};
  EXPECT_TRUE(conflict_all_orders(s, twin));
}

TEST(Intersections, SurfaceIdsDecideSharing) {
  Tri s{{kO, kX, kY}, {0, 1, 2}};
  // Touching at one point: with a shared id it is fine, with distinct ids
  // it is an intersection.
  Tri shared{{kX, {2, 0, 0}, {2, 1, 1}}, {1, 3, 4}};
  EXPECT_FALSE(conflict_all_orders(s, shared));
  Tri distinct{{kX, {2, 0, 0}, {2, 1, 1}}, {5, 3, 4}};
  EXPECT_TRUE(conflict_all_orders(s, distinct));
  // Same edge, one endpoint under another id.
  Tri edge{{kX, kO, {0.5, -1, 0}}, {1, 7, 3}};
  EXPECT_TRUE(conflict_all_orders(s, edge));
  // A duplicate triangle.
  Tri dup{{kY, kO, kX}, {2, 0, 1}};
  EXPECT_TRUE(conflict_all_orders(s, dup));
  // Disjoint, no shared ids.
  Tri far{{{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}, {3, 4, 5}};
  EXPECT_FALSE(conflict_all_orders(s, far));
}

// ---- Random small-integer triangles against a separating-axis oracle --------

using I = std::array<int64_t, 3>;

I sub(const I& a, const I& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
I cross(const I& a, const I& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
int64_t dot(const I& a, const I& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Closed triangles are disjoint iff some axis separates their projections
// strictly; the candidates (face normals, edge-edge cross products, and the
// in-plane edge normals for the coplanar case) are complete for triangles.
bool oracle_intersect(const I (&a)[3], const I (&b)[3]) {
  const I na = cross(sub(a[1], a[0]), sub(a[2], a[0]));
  const I nb = cross(sub(b[1], b[0]), sub(b[2], b[0]));
  std::vector<I> axes = {na, nb};
  for (int i = 0; i < 3; ++i) {
    const I ea = sub(a[(i + 1) % 3], a[i]);
    const I eb = sub(b[(i + 1) % 3], b[i]);
    axes.push_back(cross(na, ea));
    axes.push_back(cross(nb, eb));
    for (int j = 0; j < 3; ++j) axes.push_back(cross(ea, sub(b[(j + 1) % 3], b[j])));
  }
  for (const I& axis : axes) {
    if (axis == I{0, 0, 0}) continue;
    int64_t amin = INT64_MAX, amax = INT64_MIN, bmin = INT64_MAX, bmax = INT64_MIN;
    for (int i = 0; i < 3; ++i) {
      amin = std::min(amin, dot(axis, a[i]));
      amax = std::max(amax, dot(axis, a[i]));
      bmin = std::min(bmin, dot(axis, b[i]));
      bmax = std::max(bmax, dot(axis, b[i]));
    }
    if (amax < bmin || bmax < amin) return false;
  }
  return true;
}

// The integer point mapped exactly to doubles: axes permuted, mirrored,
// scaled by a power of two and shifted far from the origin.
P transform(const I& p, int variant) {
  const int perm[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  const int* axis = perm[variant % 3];
  P r;
  for (int k = 0; k < 3; ++k) {
    double x = static_cast<double>(p[axis[k]]);
    if (variant & 4 && k == 0) x = -x;
    if (variant & 8) x = std::ldexp(x, -30) + 1048576.0;  // 2^20 + x 2^-30: exact
    r[k] = x;
  }
  return r;
}

TEST(Intersections, RandomIntegerTrianglesMatchOracle) {
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<int> coord(0, 3);
  int hits = 0;
  int tested = 0;
  while (tested < 4000) {
    I a[3], b[3];
    for (auto* t : {&a, &b})
      for (auto& p : *t)
        for (auto& x : p) x = coord(rng);
    if (cross(sub(a[1], a[0]), sub(a[2], a[0])) == I{0, 0, 0}) continue;
    if (cross(sub(b[1], b[0]), sub(b[2], b[0])) == I{0, 0, 0}) continue;
    // A quarter of the cases coplanar: both flattened onto z = 1.
    if (tested % 4 == 0) {
      for (auto* t : {&a, &b})
        for (auto& p : *t) p[2] = 1;
      if (cross(sub(a[1], a[0]), sub(a[2], a[0])) == I{0, 0, 0}) continue;
      if (cross(sub(b[1], b[0]), sub(b[2], b[0])) == I{0, 0, 0}) continue;
    }
    ++tested;
    const bool expected = oracle_intersect(a, b);
    hits += expected;
    for (int variant : {0, 1, 2, 4, 9, 13}) {
      const P ta[3] = {transform(a[0], variant), transform(a[1], variant), transform(a[2], variant)};
      const P tb[3] = {transform(b[0], variant), transform(b[1], variant), transform(b[2], variant)};
      ASSERT_EQ(tri_tri(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]), expected) << tested << " v" << variant;
      ASSERT_EQ(tri_tri(tb[2], tb[0], tb[1], ta[1], ta[0], ta[2]), expected) << tested << " v" << variant;
      // Distinct ids: the surface test is the plain intersection test.
      Tri s{{ta[0], ta[1], ta[2]}, {0, 1, 2}};
      Tri t{{tb[0], tb[1], tb[2]}, {3, 4, 5}};
      ASSERT_EQ(conflict(s, t), expected);
    }
  }
  // Both outcomes well represented.
  EXPECT_GT(hits, 800);
  EXPECT_LT(hits, 3200);
}

// Separating axes for a closed segment and a closed triangle: the
// triangle's normal, segment x edges, and the in-plane normals of the edges
// and of the segment (for the coplanar case).
bool oracle_segment_triangle(const I (&s)[2], const I (&a)[3]) {
  const I d = sub(s[1], s[0]);
  const I n = cross(sub(a[1], a[0]), sub(a[2], a[0]));
  std::vector<I> axes = {n, cross(n, d)};
  for (int i = 0; i < 3; ++i) {
    const I e = sub(a[(i + 1) % 3], a[i]);
    axes.push_back(cross(d, e));
    axes.push_back(cross(n, e));
  }
  for (const I& axis : axes) {
    if (axis == I{0, 0, 0}) continue;
    int64_t amin = INT64_MAX, amax = INT64_MIN;
    for (const I& p : a) {
      amin = std::min(amin, dot(axis, p));
      amax = std::max(amax, dot(axis, p));
    }
    const int64_t s0 = dot(axis, s[0]), s1 = dot(axis, s[1]);
    if (std::max(s0, s1) < amin || std::min(s0, s1) > amax) return false;
  }
  return true;
}

TEST(Intersections, RandomSegmentTriangleMatchesOracle) {
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<int> coord(0, 3);
  int tested = 0;
  int hits = 0;
  while (tested < 4000) {
    I a[3], s[2];
    for (auto& p : a)
      for (auto& x : p) x = coord(rng);
    for (auto& p : s)
      for (auto& x : p) x = coord(rng);
    if (tested % 3 == 0)  // coplanar cases
      for (auto* p : {&a[0], &a[1], &a[2], &s[0], &s[1]}) (*p)[1] = 2;
    if (cross(sub(a[1], a[0]), sub(a[2], a[0])) == I{0, 0, 0} || s[0] == s[1]) continue;
    ++tested;
    const bool expected = oracle_segment_triangle(s, a);
    hits += expected;
    for (int variant : {0, 2, 5, 14}) {
      const P p = transform(s[0], variant), q = transform(s[1], variant);
      const P ta = transform(a[0], variant), tb = transform(a[1], variant), tc = transform(a[2], variant);
      ASSERT_EQ(seg_tri(p, q, ta, tb, tc), expected) << tested << " v" << variant;
      ASSERT_EQ(seg_tri(q, p, tc, ta, tb), expected) << tested << " v" << variant;
      ASSERT_EQ(seg_tri(p, q, tb, ta, tc), expected) << tested << " v" << variant;
    }
  }
  EXPECT_GT(hits, 600);
  EXPECT_LT(hits, 3400);
}

// Two triangles of a surface sharing a vertex or an edge, against oracles in
// integers: with a shared vertex v they conflict iff an edge away from v of
// one meets the other; with a shared edge uw (apexes p and q) iff q lies in
// the plane of u, w, p on p's side of line uw or on it. Small coordinates,
// half of the cases flattened onto one plane, where the surface test's
// projected shortcuts must agree with its full test.
TEST(Intersections, RandomSharedVertexAndEdgeMatchOracle) {
  std::mt19937_64 rng(37);
  std::uniform_int_distribution<int> coord(0, 4);
  int tested = 0;
  int hits[2] = {0, 0};
  while (tested < 8000) {
    const int shared = 1 + tested % 2;
    I a[3], b[3];
    for (auto* t : {&a, &b})
      for (auto& p : *t)
        for (auto& x : p) x = coord(rng);
    b[0] = a[0];
    if (shared == 2) b[1] = a[1];
    if (tested % 4 < 2)
      for (auto* t : {&a, &b})
        for (auto& p : *t) p[(tested / 4) % 3] = 2;
    if (cross(sub(a[1], a[0]), sub(a[2], a[0])) == I{0, 0, 0}) continue;
    if (cross(sub(b[1], b[0]), sub(b[2], b[0])) == I{0, 0, 0}) continue;
    ++tested;
    bool expected;
    if (shared == 1) {
      const I sa[2] = {a[1], a[2]}, sb[2] = {b[1], b[2]};
      expected = oracle_segment_triangle(sa, b) || oracle_segment_triangle(sb, a);
    } else {
      const I n = cross(sub(a[1], a[0]), sub(a[2], a[0]));
      expected = dot(n, sub(b[2], a[0])) == 0 && dot(cross(sub(a[1], a[0]), sub(b[2], a[0])), n) >= 0;
    }
    hits[shared - 1] += expected;
    for (int variant : {0, 1, 6, 10, 13}) {
      Tri s{{transform(a[0], variant), transform(a[1], variant), transform(a[2], variant)}, {0, 1, 2}};
      Tri t{{transform(b[0], variant), transform(b[1], variant), transform(b[2], variant)},
            {0, shared == 2 ? 1u : 3u, 4}};
      ASSERT_EQ(conflict_all_orders(s, t), expected) << tested << " v" << variant;
    }
  }
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(hits[k], 400) << "shared " << k + 1;
    EXPECT_LT(hits[k], 3600) << "shared " << k + 1;
  }
}

}  // namespace
}  // namespace partet
