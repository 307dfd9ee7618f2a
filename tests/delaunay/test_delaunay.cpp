// delaunay_tetrahedralize (delaunay/delaunay.hpp): on random points and on
// lattices full of cospherical and coplanar points every tet is positively
// oriented, faces pair up with their neighbours, the tets fill the
// enclosing tet, no point lies strictly inside a tet's circumsphere, and
// equal points are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "delaunay/delaunay.hpp"
#include "tetrahedralization_checks.hpp"

namespace partet {
namespace {

// A tetrahedralization (tetrahedralization_checks.hpp) with the
// empty-sphere property checked against every point.
void expect_delaunay(const DelaunayTets& d) {
  expect_tetrahedralization(d);
  for (size_t t = 0; t < d.num_tets(); ++t) {
    if (!d.finite(t)) continue;
    const uint32_t* v = &d.tets[4 * t];
    const double* p[4];
    for (int k = 0; k < 4; ++k) p[k] = &d.xyz[3 * size_t{v[k]}];
    for (size_t q = 0; q < d.num_points; ++q)
      ASSERT_LE(insphere(p[0], p[1], p[2], p[3], &d.xyz[3 * q]), 0) << "point " << q << " inside tet " << t;
  }
}

TEST(Delaunay, RandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> xyz(3 * 400);
  for (double& x : xyz) x = u(rng);
  const DelaunayTets d = delaunay_tetrahedralize(xyz);
  expect_delaunay(d);
  size_t finite = 0;
  for (size_t t = 0; t < d.num_tets(); ++t) finite += d.finite(t);
  EXPECT_GT(finite, 2000u);
}

// A cubic lattice with the cells' centres (the templates' body-centred
// lattice) and a finer corner: cospherical and coplanar points in bulk.
TEST(Delaunay, LatticePointsWithTiesGiveNoFlatTet) {
  std::vector<double> xyz;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j <= 5; ++j)
      for (int k = 0; k <= 5; ++k) {
        xyz.insert(xyz.end(), {double(i), double(j), double(k)});
        if (i < 5 && j < 5 && k < 5) xyz.insert(xyz.end(), {i + 0.5, j + 0.5, k + 0.5});
      }
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j)
      for (int k = 0; k <= 4; ++k)
        if (i % 2 || j % 2 || k % 2) xyz.insert(xyz.end(), {6 + 0.5 * i, 0.5 * j, 0.5 * k});
  const DelaunayTets d = delaunay_tetrahedralize(xyz);
  expect_delaunay(d);
}

TEST(Delaunay, OnePointAndCoplanarPoints) {
  expect_delaunay(delaunay_tetrahedralize({0.5, 0.25, 0.125}));
  std::vector<double> plane;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) plane.insert(plane.end(), {double(i), double(j), 0.0});
  expect_delaunay(delaunay_tetrahedralize(plane));
}

TEST(Delaunay, SameInputSameTets) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> xyz(3 * 300);
  for (double& x : xyz) x = std::round(u(rng) * 8) / 8;  // many ties
  std::vector<double> unique;
  for (size_t i = 0; i < xyz.size() / 3; ++i) {
    bool seen = false;
    for (size_t j = 0; j < unique.size() / 3 && !seen; ++j)
      seen = unique[3 * j] == xyz[3 * i] && unique[3 * j + 1] == xyz[3 * i + 1] && unique[3 * j + 2] == xyz[3 * i + 2];
    if (!seen) unique.insert(unique.end(), &xyz[3 * i], &xyz[3 * i] + 3);
  }
  const DelaunayTets a = delaunay_tetrahedralize(unique), b = delaunay_tetrahedralize(unique);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.neighbours, b.neighbours);
  expect_delaunay(a);
}

// Points near a sphere and its centre: the centre's cavity is every tet
// of the points inserted before it, a boundary of hundreds of vertices,
// where the new tets are linked through a hash of their edges instead of
// the table of the small cavities.
TEST(Delaunay, CentreOfASphereOpensOneLargeCavity) {
  std::vector<double> xyz;
  const int n = 800;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = 2.399963229728653 * i;
    xyz.insert(xyz.end(), {r * std::cos(phi), r * std::sin(phi), z});
  }
  xyz.insert(xyz.end(), {0.0, 0.0, 0.0});
  const DelaunayTets d = delaunay_tetrahedralize(xyz);
  EXPECT_GT(d.largest_boundary, 256u);
  expect_delaunay(d);
}

// The message names the two input points by their indices in the input.
TEST(Delaunay, EqualPointsAreRefused) {
  try {
    delaunay_tetrahedralize({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0});
    FAIL() << "equal points accepted";
  } catch (const InternalError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("points 1 and 4") != std::string::npos || what.find("points 4 and 1") != std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace partet
