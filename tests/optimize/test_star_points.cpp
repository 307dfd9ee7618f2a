// StarPoints: the batched measures of a vertex's star at trial points are
// tet_quality, tet_radius_ratio and the relaxation's circumcentre terms bit
// for bit, and its orientations orient3d's, at ordinary, degenerate,
// inverted and overflowing points, with the vertex at every corner.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "check/quality.hpp"
#include "core/predicates.hpp"
#include "optimize/star_points.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

// The centre vertex of a 2 x 2 x 2 Kuhn lattice, its points jittered.
constexpr uint32_t kCentre = 13;

TetMesh jittered_lattice() {
  TetMesh m = test::kuhn_lattice(2);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (double& c : m.xyz) c += jitter(rng);
  return m;
}

std::vector<std::vector<double>> trial_points(const TetMesh& m) {
  std::vector<std::vector<double>> points;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> near(0.5, 1.5), far(-40, 40);
  for (int i = 0; i < 200; ++i) points.push_back({near(rng), near(rng), near(rng)});
  for (int i = 0; i < 50; ++i) points.push_back({far(rng), far(rng), far(rng)});
  // On a neighbour (zero-length edges), on the plane of a face, overflowing.
  points.push_back({m.point(0)[0], m.point(0)[1], m.point(0)[2]});
  points.push_back({m.point(4)[0], m.point(4)[1], m.point(4)[2]});
  const double* a = m.point(1);
  const double* b = m.point(3);
  points.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
  // The centre's own point: every tet positive.
  points.push_back({m.point(kCentre)[0], m.point(kCentre)[1], m.point(kCentre)[2]});
  points.push_back({1e200, -1e200, 1e200});
  points.push_back({1e-300, 1e-300, 1e-300});
  return points;
}

uint64_t bits(double x) { return std::bit_cast<uint64_t>(x); }

// The optimal Delaunay point's terms of tet (p0, p1, p2, p3) as the
// relaxation first summed them: det, then det times the circumcentre.
std::array<double, 4> circumcentre_terms_of(const double* const* p) {
  double e[3][3], c[3][3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) e[j][i] = p[j + 1][i] - p[0][i];
  for (int j = 0; j < 3; ++j) {
    const double* u = e[(j + 1) % 3];
    const double* w = e[(j + 2) % 3];
    c[j][0] = u[1] * w[2] - u[2] * w[1];
    c[j][1] = u[2] * w[0] - u[0] * w[2];
    c[j][2] = u[0] * w[1] - u[1] * w[0];
  }
  const double det = e[0][0] * c[0][0] + e[0][1] * c[0][1] + e[0][2] * c[0][2];
  double len[3];
  for (int j = 0; j < 3; ++j) len[j] = e[j][0] * e[j][0] + e[j][1] * e[j][1] + e[j][2] * e[j][2];
  std::array<double, 4> out{det, 0, 0, 0};
  for (int i = 0; i < 3; ++i)
    out[1 + i] = det * (p[0][i] + (len[0] * c[0][i] + len[1] * c[1][i] + len[2] * c[2][i]) / (2 * det));
  return out;
}

// Vertex v's star in `topo`, as slots and as vertex quadruples.
void star_of(const TetTopology& topo, uint32_t v, std::vector<uint32_t>& star, std::vector<uint32_t>& quads) {
  topo.vertex_star(v, star);
  topo.tet_vertices(star, quads);
}

TEST(StarPoints, MeasuresAreTheScalarOnesBitForBit) {
  TetMesh mesh = jittered_lattice();
  TetTopology topo(mesh);
  std::vector<uint32_t> star, quads;
  star_of(topo, kCentre, star, quads);
  ASSERT_EQ(star.size(), 24u);
  std::vector<int> corners(4, 0);
  for (size_t k = 0; k < star.size(); ++k)
    for (int j = 0; j < 4; ++j) corners[j] += quads[4 * k + j] == kCentre;
  for (int j = 0; j < 4; ++j) EXPECT_GT(corners[j], 0) << "the centre at corner " << j;

  StarPoints points;
  points.load(topo, kCentre, quads);
  ASSERT_EQ(points.size(), star.size());
  std::vector<double> quality(star.size()), ratio(star.size()), terms(4 * star.size());
  std::vector<std::vector<double>> trials = trial_points(mesh);
  // The centroid of the face opposite the centre in the first tet: within
  // rounding of its plane, where orient3d's filter leaves the sign to the
  // exact path.
  std::vector<double> on_face(3, 0.0);
  for (int j = 0; j < 4; ++j)
    if (quads[j] != kCentre)
      for (int i = 0; i < 3; ++i) on_face[i] += mesh.point(quads[j])[i] / 3;
  trials.push_back(on_face);
  for (const std::vector<double>& x : trials) {
    points.place(x.data());
    points.qualities(quality.data());
    points.radius_ratios(ratio.data());
    const size_t n = star.size();
    points.circumcentre_terms(terms.data(), terms.data() + n, terms.data() + 2 * n, terms.data() + 3 * n);
    bool positive = true;
    for (size_t k = 0; k < star.size(); ++k) {
      const double* q[4];
      for (int j = 0; j < 4; ++j) q[j] = quads[4 * k + j] == kCentre ? x.data() : mesh.point(quads[4 * k + j]);
      positive = positive && orient3d(q[0], q[1], q[2], q[3]) > 0;
    }
    EXPECT_EQ(points.all_positive(), positive) << "at " << x[0] << " " << x[1] << " " << x[2];
    for (size_t k = 0; k < star.size(); ++k) {
      const double* p[4];
      for (int j = 0; j < 4; ++j) p[j] = quads[4 * k + j] == kCentre ? x.data() : mesh.point(quads[4 * k + j]);
      EXPECT_EQ(bits(quality[k]), bits(tet_quality(p[0], p[1], p[2], p[3])))
          << "tet " << k << " at " << x[0] << " " << x[1] << " " << x[2];
      EXPECT_EQ(bits(ratio[k]), bits(tet_radius_ratio(p[0], p[1], p[2], p[3])))
          << "tet " << k << " at " << x[0] << " " << x[1] << " " << x[2];
      const std::array<double, 4> want = circumcentre_terms_of(p);
      for (int j = 0; j < 4; ++j)
        EXPECT_EQ(bits(terms[j * n + k]), bits(want[j])) << "tet " << k << " term " << j << " at " << x[0];
    }
  }
}

TEST(StarPoints, ReloadingTakesTheNewStar) {
  TetMesh mesh = jittered_lattice();
  TetTopology topo(mesh);
  std::vector<uint32_t> star, quads;
  star_of(topo, kCentre, star, quads);
  StarPoints points;
  points.load(topo, kCentre, quads);
  // A corner vertex's star (one tet or a few) replaces the centre's.
  star_of(topo, 0, star, quads);
  points.load(topo, 0, quads);
  ASSERT_EQ(points.size(), star.size());
  std::vector<double> quality(star.size());
  points.place(mesh.point(0));
  points.qualities(quality.data());
  for (size_t k = 0; k < star.size(); ++k) EXPECT_EQ(bits(quality[k]), bits(topo.quality(star[k])));
}

}  // namespace
}  // namespace partet
