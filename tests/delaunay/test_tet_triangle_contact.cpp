// tet_meets_triangle_beyond_shared (delaunay/tet_triangle_contact.hpp) on
// hand cases for each number of shared vertices, and on random small-integer
// cases against an oracle: a point of the triangle strictly between its
// shared part and the rest, sampled on a fine barycentric grid, in the
// closed tet.
#include <gtest/gtest.h>

#include <random>

#include "core/predicates.hpp"
#include "delaunay/tet_triangle_contact.hpp"

namespace partet {
namespace {

const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1};

bool meets(const double* const k[4], const uint32_t kid[4], const double* const t[3], const uint32_t tid[3]) {
  return tet_meets_triangle_beyond_shared(k, kid, t, tid);
}

TEST(TetTriangleContact, NoSharedVertex) {
  const double* k[4] = {O, X, Y, Z};
  const uint32_t kid[4] = {0, 1, 2, 3};
  const double a[3] = {0.2, 0.2, -1}, b[3] = {0.2, 0.2, 1}, c[3] = {2, 2, 0};  // pierces the tet
  const double* t[3] = {a, b, c};
  const uint32_t tid[3] = {10, 11, 12};
  EXPECT_TRUE(meets(k, kid, t, tid));
  const double d[3] = {2, 0, 0}, e[3] = {0, 2, 0}, f[3] = {0, 0, 2};  // beyond the slanted face
  const double* far[3] = {d, e, f};
  EXPECT_FALSE(meets(k, kid, far, tid));
  const double g[3] = {1, 1, 1}, h[3] = {0.5, 0.5, 0};  // touches the face x+y+z=1 at one point
  const double i[3] = {2, 1, 0};
  const double* touch[3] = {g, h, i};
  EXPECT_TRUE(meets(k, kid, touch, tid));
  const double s[3] = {0.1, 0.1, 0.1}, u[3] = {0.2, 0.1, 0.1}, w[3] = {0.1, 0.2, 0.1};  // inside
  const double* inside[3] = {s, u, w};
  EXPECT_TRUE(meets(k, kid, inside, tid));
}

TEST(TetTriangleContact, OneSharedVertex) {
  const double* k[4] = {O, X, Y, Z};
  const uint32_t kid[4] = {0, 1, 2, 3};
  const double a[3] = {-1, -1, 0}, b[3] = {-1, 0, -1};  // away from the tet: only O in common
  const double* away[3] = {O, a, b};
  const uint32_t tid[3] = {0, 11, 12};
  EXPECT_FALSE(meets(k, kid, away, tid));
  const double c[3] = {1, 1, 1}, d[3] = {1, 1, -1};  // enters the tet from O
  const double* into[3] = {O, c, d};
  EXPECT_TRUE(meets(k, kid, into, tid));
  const double e[3] = {-1, 1, 0}, f[3] = {1, -1, 0};  // through O across the face z = 0's corner
  const double* across[3] = {O, e, f};
  EXPECT_TRUE(meets(k, kid, across, tid));
  const double g[3] = {-1, 0, 0}, h[3] = {0, -1, 0};  // in the plane z = 0, outside the face's corner
  const double* beside[3] = {O, g, h};
  EXPECT_FALSE(meets(k, kid, beside, tid));
}

TEST(TetTriangleContact, TwoSharedVertices) {
  const double* k[4] = {O, X, Y, Z};
  const uint32_t kid[4] = {0, 1, 2, 3};
  const uint32_t tid[3] = {0, 1, 12};
  const double in[3] = {0.5, 0.3, 0.3};
  const double* t_in[3] = {O, X, in};
  EXPECT_TRUE(meets(k, kid, t_in, tid));
  const double out[3] = {0.5, -0.3, -0.3};
  const double* t_out[3] = {O, X, out};
  EXPECT_FALSE(meets(k, kid, t_out, tid));
  const double on_face[3] = {0.5, 2, 0};  // in the plane of face OXY, on Y's side: overlaps it
  const double* t_on[3] = {O, X, on_face};
  EXPECT_TRUE(meets(k, kid, t_on, tid));
  const double on_other_side[3] = {0.5, -2, 0};  // in that plane, on the far side of OX
  const double* t_far[3] = {O, X, on_other_side};
  EXPECT_FALSE(meets(k, kid, t_far, tid));
  const double* face[3] = {O, X, Y};
  const uint32_t fid[3] = {0, 1, 2};
  EXPECT_FALSE(meets(k, kid, face, fid));
}

// The oracle: some point a b c-barycentric with weights on a grid of
// `steps`, other than the shared vertices' simplex, in the closed tet.
bool sampled_meet(const double* const k[4], const double* const t[3], const bool shared[3], int steps) {
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j) {
      const int w[3] = {i, j, steps - i - j};
      bool only_shared = true;
      for (int m = 0; m < 3; ++m) only_shared &= w[m] == 0 || shared[m];
      if (only_shared) continue;
      double p[3];
      for (int c = 0; c < 3; ++c) p[c] = (w[0] * t[0][c] + w[1] * t[1][c] + w[2] * t[2][c]) / steps;
      if (orient3d(k[1], k[2], k[3], p) <= 0 && orient3d(k[0], k[3], k[2], p) <= 0 &&
          orient3d(k[0], k[1], k[3], p) <= 0 && orient3d(k[0], k[2], k[1], p) <= 0)
        return true;
    }
  return false;
}

// Random cases on a small grid: wherever the oracle finds a common point
// the test must say they meet (the oracle samples, so it may miss a
// contact, never invent one).
TEST(TetTriangleContact, NeverMissesASampledContact) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coordinate(-3, 3), shared_count(0, 2);
  double pts[7][3];
  size_t met = 0, tried = 0;
  for (int round = 0; round < 3000; ++round) {
    for (auto& p : pts)
      for (double& x : p) x = coordinate(rng);
    const double* k[4] = {pts[0], pts[1], pts[2], pts[3]};
    if (orient3d(k[0], k[1], k[2], k[3]) <= 0) continue;
    const int s = shared_count(rng);
    const double* t[3] = {s > 0 ? pts[0] : pts[4], s > 1 ? pts[1] : pts[5], pts[6]};
    const uint32_t kid[4] = {0, 1, 2, 3};
    const uint32_t tid[3] = {s > 0 ? 0u : 4u, s > 1 ? 1u : 5u, 6u};
    double n[3];
    const double u[3] = {t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
    const double v[3] = {t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
    bool in_tet = false;  // a triangle vertex of its own equal to a tet vertex is sharing by position only
    for (int a = (s > 1 ? 2 : s); a < 3; ++a)
      for (int b = 0; b < 4; ++b) in_tet |= t[a][0] == k[b][0] && t[a][1] == k[b][1] && t[a][2] == k[b][2];
    if (in_tet) continue;
    const bool shared[3] = {s > 0, s > 1, false};
    ++tried;
    const bool sampled = sampled_meet(k, t, shared, 24);
    met += sampled;
    if (sampled) {
      EXPECT_TRUE(tet_meets_triangle_beyond_shared(k, kid, t, tid)) << "round " << round;
    }
  }
  EXPECT_GT(tried, 1000u);
  EXPECT_GT(met, 100u);
}

}  // namespace
}  // namespace partet
