// Self-intersection search: clean generated surfaces stay clean at any
// scale; overlapping, pushed-through, folded and corner-touching surfaces
// report exactly the pairs a brute-force all-pairs search finds; the limit
// and the order are deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "core/intersections.hpp"
#include "surface/self_intersections.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

// Icosahedron subdivided `levels` times, vertices pushed onto the sphere.
SurfaceMesh icosphere(int levels, double radius = 1) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  SurfaceMesh s;
  s.xyz = {-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t,
           0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1};
  s.tris = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
            3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const uint32_t v = static_cast<uint32_t>(s.num_vertices());
      for (int k = 0; k < 3; ++k) s.xyz.push_back(0.5 * (s.xyz[3 * a + k] + s.xyz[3 * b + k]));
      midpoint.emplace(key, v);
      return v;
    };
    std::vector<uint32_t> tris;
    for (size_t f = 0; f < s.num_triangles(); ++f) {
      const uint32_t a = s.tris[3 * f], b = s.tris[3 * f + 1], c = s.tris[3 * f + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      tris.insert(tris.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    s.tris = tris;
  }
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    double* p = &s.xyz[3 * v];
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int k = 0; k < 3; ++k) p[k] *= radius / len;
  }
  return s;
}

// Torus around z: n steps around the axis, m around the tube.
SurfaceMesh torus(uint32_t n, uint32_t m, double big = 2, double small = 0.5) {
  SurfaceMesh s;
  const double pi = std::acos(-1.0);
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      s.xyz.insert(s.xyz.end(), {(big + small * std::cos(v)) * std::cos(u),
                                 (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)});
    }
  }
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < m; ++j) {
      const uint32_t a = i * m + j, b = ((i + 1) % n) * m + j;
      const uint32_t c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      s.tris.insert(s.tris.end(), {a, b, c, a, c, d});
    }
  }
  return s;
}

SurfaceMesh transformed(SurfaceMesh s, double scale, double dx, double dy, double dz) {
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    s.xyz[3 * v] = s.xyz[3 * v] * scale + dx;
    s.xyz[3 * v + 1] = s.xyz[3 * v + 1] * scale + dy;
    s.xyz[3 * v + 2] = s.xyz[3 * v + 2] * scale + dz;
  }
  return s;
}

// Both surfaces in one mesh, the second one's vertices renumbered after the
// first's (so no ids are shared).
SurfaceMesh joined(const SurfaceMesh& a, const SurfaceMesh& b) {
  SurfaceMesh s = a;
  const uint32_t offset = static_cast<uint32_t>(a.num_vertices());
  s.xyz.insert(s.xyz.end(), b.xyz.begin(), b.xyz.end());
  for (uint32_t v : b.tris) s.tris.push_back(v + offset);
  return s;
}

std::vector<TrianglePair> brute_force(const SurfaceMesh& s) {
  std::vector<TrianglePair> pairs;
  for (uint32_t i = 0; i < s.num_triangles(); ++i) {
    for (uint32_t j = i + 1; j < s.num_triangles(); ++j) {
      const uint32_t* ti = &s.tris[3 * i];
      const uint32_t* tj = &s.tris[3 * j];
      const double* a[3] = {s.point(ti[0]), s.point(ti[1]), s.point(ti[2])};
      const double* b[3] = {s.point(tj[0]), s.point(tj[1]), s.point(tj[2])};
      if (surface_triangles_conflict(a, ti, b, tj)) pairs.push_back({i, j});
    }
  }
  return pairs;
}

bool contains(const std::vector<TrianglePair>& pairs, TrianglePair p) {
  return std::find(pairs.begin(), pairs.end(), p) != pairs.end();
}

TEST(SelfIntersections, CleanClosedSurfaces) {
  const SurfaceMesh shapes[] = {test::box_surface(), test::box_surface(3, 0.001, 7), icosphere(3),
                                torus(48, 24), torus(200, 3)};
  for (const SurfaceMesh& s : shapes) {
    EXPECT_TRUE(find_self_intersections(s, 100).empty());
    EXPECT_TRUE(find_self_intersections(transformed(s, 1e-200, 0, 0, 0), 100).empty());
    EXPECT_TRUE(find_self_intersections(transformed(s, 1e200, 0, 0, 0), 100).empty());
    EXPECT_TRUE(find_self_intersections(transformed(s, 1, 1e6, -3e7, 0.5), 100).empty());
  }
  // Two disjoint shapes in one mesh, one nested in the other.
  EXPECT_TRUE(find_self_intersections(joined(icosphere(2, 3), torus(40, 12)), 100).empty());
}

TEST(SelfIntersections, TwoBoxesOverlapping) {
  const SurfaceMesh s = joined(test::box_surface(), transformed(test::box_surface(), 1, 0.5, 0.5, 0.5));
  const auto pairs = find_self_intersections(s, 1000);
  EXPECT_FALSE(pairs.empty());
  EXPECT_EQ(pairs, brute_force(s));
  for (const TrianglePair& p : pairs) {
    EXPECT_LT(p.a, 12u);  // each pair has one triangle of each box
    EXPECT_GE(p.b, 12u);
  }
}

// Triangles of `s` with every vertex at z == 0.
std::vector<uint32_t> bottom_triangles(const SurfaceMesh& s) {
  std::vector<uint32_t> bottom;
  for (uint32_t t = 0; t < s.num_triangles(); ++t) {
    const uint32_t* v = &s.tris[3 * t];
    if (s.point(v[0])[2] == 0 && s.point(v[1])[2] == 0 && s.point(v[2])[2] == 0) bottom.push_back(t);
  }
  return bottom;
}

TEST(SelfIntersections, VertexPushedThroughTheOppositeFace) {
  SurfaceMesh s = test::box_surface();
  const std::vector<uint32_t> bottom = bottom_triangles(s);
  ASSERT_EQ(bottom.size(), 2u);
  // Vertex 7 = (1, 1, 1) pushed down through the bottom face z = 0.
  s.xyz[21] = 0.6;
  s.xyz[22] = 0.7;
  s.xyz[23] = -0.5;
  const auto pairs = find_self_intersections(s, 1000);
  EXPECT_EQ(pairs, brute_force(s));
  bool bottom_hit = false;
  for (const TrianglePair& p : pairs)
    for (uint32_t t : bottom) bottom_hit = bottom_hit || p.a == t || p.b == t;
  EXPECT_TRUE(bottom_hit);
}

TEST(SelfIntersections, AdjacentFacesFoldedOntoEachOther) {
  // The two bottom triangles share an edge; moving the apex of one to the
  // centroid of the other, in the plane, folds it over the other.
  SurfaceMesh s = test::box_surface();
  const std::vector<uint32_t> bottom = bottom_triangles(s);
  ASSERT_EQ(bottom.size(), 2u);
  const uint32_t* t0 = &s.tris[3 * bottom[0]];
  const uint32_t* t1 = &s.tris[3 * bottom[1]];
  const uint32_t apex = *std::find_if(t1, t1 + 3, [&](uint32_t v) { return std::count(t0, t0 + 3, v) == 0; });
  double centroid[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) centroid[k] += s.point(t0[i])[k] / 3;
  for (int k = 0; k < 3; ++k) s.xyz[3 * apex + k] = centroid[k];
  const auto pairs = find_self_intersections(s, 1000);
  EXPECT_TRUE(contains(pairs, {bottom[0], bottom[1]}));
  EXPECT_EQ(pairs, brute_force(s));
}

TEST(SelfIntersections, TouchingAtOneVertexWithDifferentIds) {
  // Boxes [0,1]^3 and [1,2]^3 meet only at the corner (1,1,1), which is
  // vertex 7 of the first and vertex 8 (local 0) of the second: every
  // triangle of one at that corner meets every one of the other there.
  const SurfaceMesh s = joined(test::box_surface(), transformed(test::box_surface(), 1, 1, 1, 1));
  std::vector<TrianglePair> expected;
  for (uint32_t i = 0; i < 12; ++i) {
    for (uint32_t j = 12; j < 24; ++j) {
      const bool has7 = std::count(&s.tris[3 * i], &s.tris[3 * i + 3], 7u) > 0;
      const bool has8 = std::count(&s.tris[3 * j], &s.tris[3 * j + 3], 8u) > 0;
      if (has7 && has8) expected.push_back({i, j});
    }
  }
  EXPECT_GE(expected.size(), 9u);
  EXPECT_EQ(find_self_intersections(s, 1000), expected);
  // With the corner merged into one vertex, the boxes share it: clean.
  SurfaceMesh merged = s;
  for (uint32_t& v : merged.tris)
    if (v == 8) v = 7;
  EXPECT_TRUE(find_self_intersections(merged, 1000).empty());
}

TEST(SelfIntersections, DuplicateTriangle) {
  SurfaceMesh s = test::box_surface();
  s.tris.insert(s.tris.end(), {s.tris[2], s.tris[1], s.tris[0]});  // triangle 0 again, reversed
  EXPECT_EQ(find_self_intersections(s, 1000), (std::vector<TrianglePair>{{0, 12}}));
}

TEST(SelfIntersections, VeryDifferentTriangleSizes) {
  // A fine sphere cut by one huge triangle, plus huge and tiny triangles
  // elsewhere: the same pairs as brute force.
  SurfaceMesh s = icosphere(3);
  const uint32_t base = static_cast<uint32_t>(s.num_vertices());
  s.xyz.insert(s.xyz.end(), {-1e4, -1e4, 0.1, 1e4, -1e4, 0.1, 0, 1e4, 0.1,      // cuts the sphere
                             -1e4, -1e4, 50, 1e4, -1e4, 50, 0, 1e4, 50,         // far above it
                             0.2, 0.2, 1.5, 0.2 + 1e-9, 0.2, 1.5, 0.2, 0.2 + 1e-9, 1.5});  // tiny, outside
  for (uint32_t v = 0; v < 9; ++v) s.tris.push_back(base + v);
  const auto pairs = find_self_intersections(s, 100000);
  EXPECT_EQ(pairs, brute_force(s));
  const uint32_t cutter = static_cast<uint32_t>(s.num_triangles()) - 3;
  size_t cut = 0;
  for (const TrianglePair& p : pairs) {
    EXPECT_EQ(p.b, cutter);
    cut += p.b == cutter;
  }
  EXPECT_GT(cut, 20u);
}

TEST(SelfIntersections, LimitAndDeterminism) {
  const SurfaceMesh s = joined(icosphere(2), transformed(icosphere(2), 1, 0.7, 0.2, 0.1));
  const auto all = find_self_intersections(s, SIZE_MAX);
  EXPECT_EQ(all, brute_force(s));
  ASSERT_GT(all.size(), 40u);
  EXPECT_TRUE(find_self_intersections(s, 0).empty());
  for (size_t limit : {size_t{1}, size_t{5}, size_t{17}, all.size(), all.size() + 10}) {
    const auto some = find_self_intersections(s, limit);
    EXPECT_EQ(some.size(), std::min(limit, all.size()));
    EXPECT_EQ(some, find_self_intersections(s, limit));
    for (size_t i = 0; i < some.size(); ++i) {
      EXPECT_LT(some[i].a, some[i].b);
      EXPECT_TRUE(contains(all, some[i]));
      if (i > 0) {
        EXPECT_TRUE(some[i - 1].a < some[i].a || (some[i - 1].a == some[i].a && some[i - 1].b < some[i].b));
      }
    }
  }
}

TEST(SelfIntersections, TinySurfaces) {
  SurfaceMesh empty;
  EXPECT_TRUE(find_self_intersections(empty, 10).empty());
  SurfaceMesh one;
  one.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  one.tris = {0, 1, 2};
  EXPECT_TRUE(find_self_intersections(one, 10).empty());
}

}  // namespace
}  // namespace partet
