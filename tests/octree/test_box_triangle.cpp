// Box against triangle: the exact intersection test on touching and
// one-ulp-apart cases and against a feature-by-feature reference on random
// (often degenerate) inputs; the distance threshold against sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/intersections.hpp"
#include "octree/box_triangle.hpp"

namespace partet {
namespace {

const double kLo[3] = {0, 0, 0};
const double kHi[3] = {1, 1, 1};

double up(double x) { return std::nextafter(x, HUGE_VAL); }

// Reference: a vertex in the box, a triangle edge meeting a box face (two
// triangles each), or a box edge meeting the triangle.
bool reference_meets(const double* lo, const double* hi, const double* a, const double* b, const double* c) {
  const double* v[3] = {a, b, c};
  for (const double* p : v) {
    bool in = true;
    for (int i = 0; i < 3; ++i) in = in && p[i] >= lo[i] && p[i] <= hi[i];
    if (in) return true;
  }
  double corner[8][3];
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) corner[k][i] = (k >> i & 1) ? hi[i] : lo[i];
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      // The face's corners in cyclic order.
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      const int base = side << axis;
      const int f[4] = {base, base | 1 << u, base | 1 << u | 1 << w, base | 1 << w};
      for (int e = 0; e < 3; ++e) {
        if (segment_triangle_intersect(v[e], v[(e + 1) % 3], corner[f[0]], corner[f[1]], corner[f[2]]) ||
            segment_triangle_intersect(v[e], v[(e + 1) % 3], corner[f[0]], corner[f[2]], corner[f[3]]))
          return true;
      }
    }
  }
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 8; ++k)
      if (!(k >> axis & 1) && segment_triangle_intersect(corner[k], corner[k | 1 << axis], a, b, c)) return true;
  return false;
}

bool meets(const double* a, const double* b, const double* c) {
  const bool got = box_meets_triangle(kLo, kHi, a, b, c);
  EXPECT_EQ(got, reference_meets(kLo, kHi, a, b, c));
  return got;
}

TEST(OctreeBoxTriangle, TouchingACornerAndOneUlpAway) {
  // The plane x + y + z = 3 passes through corner (1, 1, 1).
  const double a[3] = {3, 0, 0}, b[3] = {0, 3, 0}, c[3] = {0, 0, 3};
  EXPECT_TRUE(meets(a, b, c));
  const double a2[3] = {up(3), 0, 0}, b2[3] = {0, up(3), 0}, c2[3] = {0, 0, up(3)};
  EXPECT_FALSE(meets(a2, b2, c2));
  // A triangle vertex exactly on the corner, the rest outside.
  const double p[3] = {1, 1, 1}, q[3] = {2, 1, 3}, r[3] = {1, 3, 2};
  EXPECT_TRUE(meets(p, q, r));
  const double p2[3] = {up(1), 1, 1};
  EXPECT_FALSE(meets(p2, q, r));
}

TEST(OctreeBoxTriangle, TouchingAnEdgeAndOneUlpAway) {
  // The plane x + y = 2 contains the box edge x = y = 1.
  const double a[3] = {2, 0, -1}, b[3] = {0, 2, -1}, c[3] = {1, 1, 5};
  EXPECT_TRUE(meets(a, b, c));
  const double a2[3] = {up(2), 0, -1}, b2[3] = {0, up(2), -1}, c2[3] = {up(1), up(1), 5};
  EXPECT_FALSE(meets(a2, b2, c2));
  // A triangle edge crossing the box edge x = y = 1 at (1, 1, 0.5); the
  // rest of the triangle has x + y > 2.
  const double g[3] = {2, 0, 0.5}, h[3] = {0, 2, 0.5}, k[3] = {2, 2, 0.7};
  EXPECT_TRUE(meets(g, h, k));
  const double g2[3] = {up(2), 0, 0.5}, h2[3] = {0, up(2), 0.5};
  EXPECT_FALSE(meets(g2, h2, k));
}

TEST(OctreeBoxTriangle, TouchingAFaceAndOneUlpAway) {
  const double a[3] = {-1, -1, 1}, b[3] = {3, -1, 1}, c[3] = {-1, 3, 1};
  EXPECT_TRUE(meets(a, b, c));
  const double a2[3] = {-1, -1, up(1)}, b2[3] = {3, -1, up(1)}, c2[3] = {-1, 3, up(1)};
  EXPECT_FALSE(meets(a2, b2, c2));
  // A single vertex on the face's interior.
  const double p[3] = {0.5, 0.5, 1}, q[3] = {0.5, 2, 2}, r[3] = {2, 0.5, 3};
  EXPECT_TRUE(meets(p, q, r));
}

TEST(OctreeBoxTriangle, InsideCrossingAndDisjoint) {
  const double a[3] = {0.2, 0.2, 0.2}, b[3] = {0.8, 0.3, 0.4}, c[3] = {0.5, 0.9, 0.6};
  EXPECT_TRUE(meets(a, b, c));  // inside
  const double d[3] = {-5, -5, 0.5}, e[3] = {5, -5, 0.5}, f[3] = {0, 5, 0.5};
  EXPECT_TRUE(meets(d, e, f));  // slices the box, no vertex inside
  const double g[3] = {0.5, 0.5, -1}, h[3] = {0.5, 0.6, 2}, k[3] = {0.6, 0.5, 2};
  EXPECT_TRUE(meets(g, h, k));  // thin sliver piercing two faces
  // Disjoint although the bounding boxes overlap, no vertex is inside and
  // the plane cuts the box: only a box axis x triangle edge separates them.
  const double p[3] = {0, 1.5, -0.5}, q[3] = {-1, 1, 0.5}, r[3] = {3, 1.5, 0.5};
  EXPECT_FALSE(meets(p, q, r));
  // Beside the box edge x = y = 1: x + y >= 2.7 on the whole triangle.
  const double p2[3] = {2.2, 0.5, -1}, q2[3] = {0.5, 2.2, -1}, r2[3] = {1.4, 1.4, 3};
  EXPECT_FALSE(meets(p2, q2, r2));
  const double s[3] = {3, 3, 3}, t[3] = {4, 3, 3}, u[3] = {3, 4, 3};
  EXPECT_FALSE(meets(s, t, u));  // far away
}

// A random triangle with coordinates from a small set around the unit box
// (many exact contacts); false when its points are collinear.
bool lattice_triangle(std::mt19937& rng, double v[3][3]) {
  static constexpr double kValues[] = {-1, -0.5, 0, 0.25, 0.5, 1, 1.5, 2};
  std::uniform_int_distribution<int> pick(0, 7);
  for (int i = 0; i < 3; ++i)
    for (double& x : v[i]) x = kValues[pick(rng)];
  return !points_collinear(v[0], v[1], v[2]);
}

TEST(OctreeBoxTriangle, MatchesReferenceOnLatticeTriangles) {
  std::mt19937 rng(3);
  int hits = 0, total = 0;
  for (int k = 0; k < 40000; ++k) {
    double v[3][3];
    if (!lattice_triangle(rng, v)) continue;
    const bool got = box_meets_triangle(kLo, kHi, v[0], v[1], v[2]);
    ASSERT_EQ(got, reference_meets(kLo, kHi, v[0], v[1], v[2])) << k;
    hits += got;
    ++total;
  }
  EXPECT_GT(hits, total / 10);
  EXPECT_LT(hits, total - total / 10);
}

TEST(OctreeBoxTriangle, MatchesReferenceOnRandomTriangles) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-1.5, 2.5);
  for (int k = 0; k < 40000; ++k) {
    double v[3][3];
    for (auto& p : v)
      for (double& x : p) x = coord(rng);
    const double lo[3] = {0, 0.25, 0.5}, hi[3] = {0.5, 0.75, 1};
    ASSERT_EQ(box_meets_triangle(lo, hi, v[0], v[1], v[2]), reference_meets(lo, hi, v[0], v[1], v[2])) << k;
  }
}

// The floating-point filter in front of the exact test must leave
// near-touching cases to it: a small box far from the origin, triangles
// with a vertex a few ulps off a box corner, edge or face and the others
// on either side of the box's planes.
TEST(OctreeBoxTriangle, MatchesReferenceNearTouchingFarFromOrigin) {
  std::mt19937 rng(17);
  const double lo[3] = {1e6, -2e6 + 0.375, 3e6}, hi[3] = {1e6 + 0x1p-10, -2e6 + 0.375 + 0x1p-10, 3e6 + 0x1p-10};
  std::uniform_int_distribution<int> ulps(-3, 3), pick(0, 2);
  std::uniform_real_distribution<double> spread(-2, 2);
  int hits = 0;
  for (int k = 0; k < 40000; ++k) {
    double v[3][3];
    for (int i = 0; i < 3; ++i) {
      // Vertex 0: each coordinate on lo, on hi or inside, nudged by ulps.
      const int where = pick(rng);
      double x = where == 0 ? lo[i] : (where == 1 ? hi[i] : 0.5 * (lo[i] + hi[i]));
      for (int u = ulps(rng); u != 0; u += u > 0 ? -1 : 1) x = std::nextafter(x, u > 0 ? HUGE_VAL : -HUGE_VAL);
      v[0][i] = x;
      for (int j = 1; j < 3; ++j) v[j][i] = lo[i] + spread(rng) * 0x1p-10;
    }
    const bool got = box_meets_triangle(lo, hi, v[0], v[1], v[2]);
    ASSERT_EQ(got, reference_meets(lo, hi, v[0], v[1], v[2])) << k;
    hits += got;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_LT(hits, 39000);
}

// Half-open boxes: on lattice coordinates (multiples of 1/4 in [-1, 2]) every
// predicate value is a multiple of 2^-12 at least, so pulling the open
// upper faces in by 2^-30 changes no nonzero sign: the closed test on that
// box is the reference.
TEST(OctreeBoxTriangle, HalfOpenMatchesShrunkClosedBoxOnLatticeTriangles) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coin(0, 1);
  int differ = 0, total = 0;
  for (int k = 0; k < 60000; ++k) {
    double v[3][3];
    if (!lattice_triangle(rng, v)) continue;
    const bool open[3] = {coin(rng) == 1, coin(rng) == 1, coin(rng) == 1};
    double shrunk[3];
    for (int i = 0; i < 3; ++i) shrunk[i] = open[i] ? kHi[i] - std::ldexp(1.0, -30) : kHi[i];
    const bool got = box_meets_triangle_half_open(kLo, kHi, open, v[0], v[1], v[2]);
    ASSERT_EQ(got, box_meets_triangle(kLo, shrunk, v[0], v[1], v[2])) << k;
    differ += got != box_meets_triangle(kLo, kHi, v[0], v[1], v[2]);
    ++total;
  }
  // Plenty of triangles touch only the open faces.
  EXPECT_GT(differ, total / 50);
}

// One TriangleBoxTest against many boxes (its precomputed edges, normal and
// magnitudes reused) answers as the per-box functions, on lattice
// triangles against lattice boxes of every size, closed and half-open.
TEST(OctreeBoxTriangle, OneTriangleManyBoxesMatchesPerBoxTests) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> cell(-4, 7), size(1, 6), coin(0, 1);
  int met = 0;
  for (int k = 0; k < 2000; ++k) {
    double v[3][3];
    if (!lattice_triangle(rng, v)) continue;
    const TriangleBoxTest triangle(v[0], v[1], v[2]);
    for (int b = 0; b < 20; ++b) {
      double lo[3], hi[3];
      for (int i = 0; i < 3; ++i) {
        lo[i] = cell(rng) / 4.0;
        hi[i] = lo[i] + size(rng) / 8.0;
      }
      const bool open[3] = {coin(rng) == 1, coin(rng) == 1, coin(rng) == 1};
      ASSERT_EQ(triangle.meets(lo, hi), box_meets_triangle(lo, hi, v[0], v[1], v[2])) << k << " " << b;
      ASSERT_EQ(triangle.meets_half_open(lo, hi, open), box_meets_triangle_half_open(lo, hi, open, v[0], v[1], v[2]))
          << k << " " << b;
      ASSERT_EQ(triangle.meets(lo, hi), reference_meets(lo, hi, v[0], v[1], v[2])) << k << " " << b;
      met += triangle.meets(lo, hi);
    }
  }
  EXPECT_GT(met, 1000);
}

// The 8 half-open octants of a cube tile it, so a triangle meets exactly
// the octants its points fall in, where closed octants also count every
// touch of a common plane, edge or corner.
std::vector<int> octants_met(const double* a, const double* b, const double* c, bool half_open) {
  const bool open[3] = {true, true, true};
  std::vector<int> met;
  for (int k = 0; k < 8; ++k) {
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = (k >> i & 1) ? 0.5 : 0;
      hi[i] = lo[i] + 0.5;
    }
    if (half_open ? box_meets_triangle_half_open(lo, hi, open, a, b, c) : box_meets_triangle(lo, hi, a, b, c))
      met.push_back(k);
  }
  return met;
}

TEST(OctreeBoxTriangle, HalfOpenOctantsCountEachPointOnce) {
  // In the common plane x = 1/2, away from the other planes: octant 1 only.
  const double a[3] = {0.5, 0.125, 0.125}, b[3] = {0.5, 0.375, 0.125}, c[3] = {0.5, 0.125, 0.375};
  EXPECT_EQ(octants_met(a, b, c, false), (std::vector<int>{0, 1}));
  EXPECT_EQ(octants_met(a, b, c, true), (std::vector<int>{1}));
  // Inside octant 0 but for one vertex on the common corner, which is in
  // octant 7.
  const double p[3] = {0.5, 0.5, 0.5}, q[3] = {0.125, 0.25, 0.25}, r[3] = {0.25, 0.125, 0.25};
  EXPECT_EQ(octants_met(p, q, r, false), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(octants_met(p, q, r, true), (std::vector<int>{0, 7}));
  // Along the common edge x = y = 1/2 with the rest in x, y < 1/2: the edge's
  // points are in octants 3 (z < 1/2) and 7.
  const double e[3] = {0.5, 0.5, 0.25}, f[3] = {0.5, 0.5, 0.75}, g[3] = {0.25, 0.125, 0.5};
  EXPECT_EQ(octants_met(e, f, g, true), (std::vector<int>{0, 3, 4, 7}));
}

// Distance from the box to the triangle sampled on a barycentric grid: an
// upper bound, within `spacing` of the true distance.
double sampled_distance(const double* a, const double* b, const double* c, int n, double& spacing) {
  double best = HUGE_VAL;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      double d2 = 0;
      for (int k = 0; k < 3; ++k) {
        const double p = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]);
        const double g = p < kLo[k] ? kLo[k] - p : (p > kHi[k] ? p - kHi[k] : 0.0);
        d2 += g * g;
      }
      best = std::min(best, std::sqrt(d2));
    }
  double longest = 0;
  const double* v[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    double l2 = 0;
    for (int k = 0; k < 3; ++k) l2 += (v[e][k] - v[(e + 1) % 3][k]) * (v[e][k] - v[(e + 1) % 3][k]);
    longest = std::max(longest, std::sqrt(l2));
  }
  spacing = longest / n;
  return best;
}

TEST(OctreeBoxTriangle, DistanceThresholdMatchesSampling) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> coord(-2, 3);
  int tested = 0;
  for (int k = 0; k < 3000; ++k) {
    double v[3][3];
    for (auto& p : v)
      for (double& x : p) x = coord(rng);
    if (box_meets_triangle(kLo, kHi, v[0], v[1], v[2])) continue;
    double spacing;
    const double d = sampled_distance(v[0], v[1], v[2], 120, spacing);
    EXPECT_TRUE(box_triangle_closer_than(kLo, kHi, v[0], v[1], v[2], d * (1 + 1e-12) + 1e-12)) << k;
    if (d - spacing > 1e-9) {
      EXPECT_FALSE(box_triangle_closer_than(kLo, kHi, v[0], v[1], v[2], d - spacing)) << k;
    }
    ++tested;
  }
  EXPECT_GT(tested, 1000);
  // Exact cases: a triangle parallel to the top face at height 0.5 above
  // it, and one beside an edge.
  const double a[3] = {-1, -1, 1.5}, b[3] = {3, -1, 1.5}, c[3] = {-1, 3, 1.5};
  EXPECT_TRUE(box_triangle_closer_than(kLo, kHi, a, b, c, 0.5001));
  EXPECT_FALSE(box_triangle_closer_than(kLo, kHi, a, b, c, 0.4999));
  // Edge (2, 2, -1)-(2, 2, 2) of a vertical triangle faces the box edge
  // x = y = 1 at distance sqrt(2).
  const double p[3] = {2, 2, -1}, q[3] = {2, 2, 2}, r[3] = {4, 3, 0.5};
  EXPECT_TRUE(box_triangle_closer_than(kLo, kHi, p, q, r, std::sqrt(2.0) + 1e-9));
  EXPECT_FALSE(box_triangle_closer_than(kLo, kHi, p, q, r, std::sqrt(2.0) - 1e-9));
}

}  // namespace
}  // namespace partet
