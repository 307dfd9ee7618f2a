// cone_quality_bound, cones_can_beat and cones_can_keep_angle: the bound
// is reached by the centroid of a regular tet, no cone set beats it (every
// interior vertex's star is the cone set of its own position, and random
// points in the star do no better), and cones_can_beat and
// cones_can_keep_angle agree with it on either side.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "check/quality.hpp"
#include "core/predicates.hpp"
#include "optimize/cone_bound.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

using test::add_positive_tet;

TEST(ConeBound, ARegularTetsCentroidConesReachIt) {
  TetMesh m;
  m.xyz = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
  add_positive_tet(m, 0, 1, 2, 3);
  TetTopology topo(m);
  const uint32_t cavity[1] = {0};
  // Its dihedral angles (70.5 degrees) split in half at the centroid; the
  // four cones' worst quality is then sin(35.3 degrees) scaled.
  double worst = 1;
  const double centroid[3] = {0, 0, 0};
  constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (const auto& f : kFaces) {
    const double* p[3] = {m.point(f[0]), m.point(f[1]), m.point(f[2])};
    const double* a = orient3d(p[0], p[1], p[2], centroid) > 0 ? p[1] : p[2];
    const double* b = a == p[1] ? p[2] : p[1];
    worst = std::min(worst, tet_quality(p[0], a, b, centroid));
  }
  EXPECT_NEAR(cone_quality_bound(topo, cavity), worst, 1e-12);
  EXPECT_NEAR(worst, kRegularSineScale * std::sin(std::acos(1.0 / 3) / 2), 1e-12);
  EXPECT_TRUE(cones_can_beat(topo, cavity, worst * 0.999));
  EXPECT_FALSE(cones_can_beat(topo, cavity, worst * 1.001));
  // In angles: half the regular tet's dihedral angle, 35.26 degrees.
  const double half = std::acos(1.0 / 3) / 2;
  EXPECT_TRUE(cones_can_keep_angle(topo, cavity, half * 0.999));
  EXPECT_FALSE(cones_can_keep_angle(topo, cavity, half * 1.001));
}

// The smallest dihedral angle of the star's tets (radians).
double smallest_angle(const TetTopology& topo, const std::vector<uint32_t>& star) {
  double smallest = 10;
  for (uint32_t t : star) {
    const uint32_t* v = topo.tet(t);
    smallest = std::min(smallest,
                        tet_shape(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3])).min_dihedral_rad);
  }
  return smallest;
}

// A 3 x 3 x 3 Kuhn lattice with its 8 interior vertices jittered.
TetMesh jittered_lattice(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  TetMesh m = test::kuhn_lattice(3);
  for (int z = 1; z < 3; ++z)
    for (int y = 1; y < 3; ++y)
      for (int x = 1; x < 3; ++x)
        for (int i = 0; i < 3; ++i) m.xyz[3 * (x + 4 * y + 16 * z) + i] += jitter(rng);
  return m;
}

TEST(ConeBound, NoPointInAStarBeatsIt) {
  std::mt19937 rng(11);
  int below = 0;  // stars whose bound cones_can_beat can refuse
  for (int mesh = 0; mesh < 20; ++mesh) {
    TetMesh m = jittered_lattice(rng);
    ASSERT_TRUE(test::all_positive(m));
    TetTopology topo(m);
    for (uint32_t v : {21u, 22u, 25u, 26u, 37u, 38u, 41u, 42u}) {
      std::vector<uint32_t> star;
      topo.vertex_star(v, star);
      ASSERT_EQ(star.size(), 24u);
      const double bound = cone_quality_bound(topo, star);
      // The star is the cone set of v's own position.
      double own = 1;
      for (uint32_t t : star) own = std::min(own, topo.quality(t));
      EXPECT_LE(own, bound + 1e-12);
      // Whatever smallest angle a position reaches, the angle bound allows.
      EXPECT_TRUE(cones_can_keep_angle(topo, star, smallest_angle(topo, star)));
      // And of any other point: the same tets with v moved there.
      std::uniform_real_distribution<double> step(-0.3, 0.3);
      const double home[3] = {topo.point(v)[0], topo.point(v)[1], topo.point(v)[2]};
      for (int trial = 0; trial < 50; ++trial) {
        const double x[3] = {home[0] + step(rng), home[1] + step(rng), home[2] + step(rng)};
        topo.move_vertex(v, x);
        double worst = 1;
        for (uint32_t t : star) worst = std::min(worst, topo.quality(t));
        EXPECT_LE(worst, bound + 1e-12);
        if (test::all_positive(m)) {
          EXPECT_TRUE(cones_can_keep_angle(topo, star, smallest_angle(topo, star)));
        }
      }
      topo.move_vertex(v, home);
      EXPECT_TRUE(cones_can_beat(topo, star, std::min(bound, quality_of_angle(45)) * 0.999));
      if (bound < quality_of_angle(44)) {
        EXPECT_FALSE(cones_can_beat(topo, star, bound * 1.001));
        ++below;
      }
    }
  }
  EXPECT_GT(below, 0);
}

// Read from a ring of tets around an edge, the verdicts are those of the
// cavity's edge table for every bar, the bound's own value included (the
// same angles bit for bit), on every interior edge of jittered lattices.
TEST(ConeBound, RingVerdictsAreTheCavitys) {
  std::mt19937 rng(12);
  int rings = 0, refused = 0;
  for (int mesh = 0; mesh < 5; ++mesh) {
    TetMesh m = jittered_lattice(rng);
    TetTopology topo(m);
    for (uint32_t t = 0; t < topo.slots(); ++t)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          TetTopology::Ring ring;
          if (!topo.edge_ring(t, i, j, ring)) continue;
          ++rings;
          const std::vector<uint32_t> cavity(ring.tets, ring.tets + ring.n);
          const double bound = cone_quality_bound(topo, cavity);
          const double angle = smallest_angle(topo, cavity);
          for (const double scale : {0.5, 0.9, 0.999, 1.0, 1.001, 1.1, 2.0}) {
            const double worst = std::min(bound, quality_of_angle(45)) * scale;
            EXPECT_EQ(cones_can_beat(topo, ring, worst), cones_can_beat(topo, cavity, worst)) << t << " " << scale;
            EXPECT_EQ(cones_can_keep_angle(topo, ring, angle * scale), cones_can_keep_angle(topo, cavity, angle * scale))
                << t << " " << scale;
            refused += !cones_can_beat(topo, cavity, worst);
          }
        }
  }
  EXPECT_GT(rings, 1000);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace partet
