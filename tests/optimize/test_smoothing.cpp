// Smoothing of one interior vertex, the quality measure, and the frozen
// flags of optimize_mesh on a cube coned to a perturbed centre; the least
// norm point of a few gradients against a brute-force search, and of NaN
// gradients.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "check/quality.hpp"
#include "check/validate.hpp"
#include "optimize/optimize.hpp"
#include "optimize/smoothing.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/vertex_incidence.hpp"
#include "optimize_test_util.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::all_positive;
using test::boundary_faces;
using test::worst_quality;

// The unit cube's 12 boundary triangles coned to an interior vertex 8 at c.
TetMesh coned_cube(double x, double y, double z) {
  SurfaceMesh box = test::box_surface();
  TetMesh m;
  m.xyz = box.xyz;
  m.xyz.insert(m.xyz.end(), {x, y, z});
  m.tris = box.tris;
  for (size_t t = 0; t < box.num_triangles(); ++t)
    m.tets.insert(m.tets.end(), {box.tris[3 * t], box.tris[3 * t + 2], box.tris[3 * t + 1], 8});
  return m;
}

TEST(TetQuality, RegularIsOneFlatIsZeroInvertedIsNegative) {
  const double p[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const double (&a)[3] = p[0], (&b)[3] = p[1], (&c)[3] = p[2], (&d)[3] = p[3];
  const double regular = orient3d(a, b, c, d) > 0 ? tet_quality(a, b, c, d) : tet_quality(a, c, b, d);
  EXPECT_NEAR(regular, 1, 1e-12);
  const double flat[3] = {1.0 / 3, 1.0 / 3, -1.0 / 3};  // in the plane of a, b, c
  EXPECT_LE(std::fabs(tet_quality(a, b, c, flat)), 1e-12);
  EXPECT_LT(orient3d(a, b, c, d) > 0 ? tet_quality(a, c, b, d) : tet_quality(a, b, c, d), 0);
  // All dihedral angles of a tet scoring quality_of_angle(30) lie in [30, 150].
  const double q30 = quality_of_angle(30);
  const double s[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 0.3}};
  const TetShape shape = tet_shape(s[0], s[1], s[2], s[3]);
  const bool inside = shape.min_dihedral_rad >= std::numbers::pi / 6 && shape.max_dihedral_rad <= 5 * std::numbers::pi / 6;
  EXPECT_EQ(tet_quality(s[0], s[1], s[2], s[3]) >= q30, inside);
}

TEST(Smoothing, MovesAPerturbedCentreAndImprovesTheWorstTet) {
  TetMesh m = coned_cube(0.85, 0.8, 0.75);
  ASSERT_TRUE(all_positive(m));
  const double before = worst_quality(m);
  const std::vector<double> corners(m.xyz.begin(), m.xyz.begin() + 24);
  TetTopology topo(m);
  SmoothingScratch scratch;
  EXPECT_TRUE(smooth_vertex(topo, 8, scratch));
  EXPECT_TRUE(all_positive(m));
  EXPECT_GT(worst_quality(m), before + 0.1);
  EXPECT_EQ(std::memcmp(corners.data(), m.xyz.data(), 24 * sizeof(double)), 0);
  // Near the centre now, where the worst tet is best.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.xyz[24 + i], 0.5, 0.1);
  // A second call cannot make it worse.
  const double after = worst_quality(m);
  smooth_vertex(topo, 8, scratch);
  EXPECT_GE(worst_quality(m), after);
}

TEST(Smoothing, NeverAcceptsAnInvalidOrWorsePosition) {
  // The centre itself is optimal: nothing to gain.
  TetMesh m = coned_cube(0.5, 0.5, 0.5);
  TetTopology topo(m);
  SmoothingScratch scratch;
  const double before = worst_quality(m);
  smooth_vertex(topo, 8, scratch);
  EXPECT_GE(worst_quality(m), before);
  EXPECT_NEAR(m.xyz[24], 0.5, 1e-6);
}

TEST(OptimizeMesh, FrozenVerticesStayAndFreeOnesMove) {
  TetMesh m = coned_cube(0.85, 0.8, 0.75);
  const TetMesh original = m;
  std::vector<uint8_t> frozen(9, 0);
  frozen[8] = 1;
  OptimizeOptions options;
  options.insert_vertices = false;
  optimize_mesh(m, options, &frozen);
  EXPECT_EQ(m.xyz, original.xyz);

  OptimizeStats stats = optimize_mesh(m, options);
  EXPECT_NE(m.xyz[24], original.xyz[24]);
  EXPECT_GT(stats.vertices_moved, 0u);
  EXPECT_GT(stats.after.radius_ratio_min, stats.before.radius_ratio_min);
  EXPECT_EQ(std::memcmp(m.xyz.data(), original.xyz.data(), 24 * sizeof(double)), 0);
  EXPECT_EQ(boundary_faces(m), boundary_faces(original));
  ValidationResult r = validate_mesh(m, nullptr);
  EXPECT_TRUE(r.valid) << format_text(r);
}

TEST(OptimizeMesh, NoPassesOnlyMeasures) {
  TetMesh m = coned_cube(0.85, 0.8, 0.75);
  const TetMesh original = m;
  OptimizeOptions options;
  options.passes = 0;
  OptimizeStats stats = optimize_mesh(m, options);
  EXPECT_EQ(m.xyz, original.xyz);
  EXPECT_EQ(m.tets, original.tets);
  EXPECT_EQ(stats.passes, 0);
  EXPECT_EQ(stats.before.tets, 12u);
  EXPECT_EQ(stats.after.radius_ratio_mean, stats.before.radius_ratio_mean);
}

// No floor: a relaxation may not lower the star's worst tet at all.
constexpr double kNoFloor = std::numeric_limits<double>::infinity();

double radius_ratio_sum(const TetMesh& m) {
  double sum = 0;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    sum += tet_radius_ratio(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
  }
  return sum;
}

// A coned cube with a random centre and its corners moved by up to 0.2 in
// each coordinate: some come out with a non-positive tet.
TetMesh jittered_coned_cube(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), inside(0.3, 0.7);
  TetMesh m = coned_cube(inside(rng), inside(rng), inside(rng));
  for (size_t i = 0; i < 24; ++i) m.xyz[i] += jitter(rng);
  return m;
}

// relax_vertex with v's star and neighbours gathered from the topology.
bool relax(TetTopology& topo, uint32_t v, SmoothingScratch& scratch, double floor) {
  VertexIncidence incidence(topo);
  return relax_vertex(topo, v, incidence.star(v), incidence.neighbours(v), scratch, floor);
}

// Relaxation takes a perturbed centre to (or towards) its neighbours'
// centroid, raising the radius ratios without lowering the worst tet, and
// leaves a centre already there alone.
TEST(Smoothing, RelaxationRaisesTheRadiusRatiosOnly) {
  TetMesh m = coned_cube(0.62, 0.57, 0.55);
  const double worst = worst_quality(m), sum = radius_ratio_sum(m);
  TetTopology topo(m);
  SmoothingScratch scratch;
  EXPECT_TRUE(relax(topo, 8, scratch, kNoFloor));
  EXPECT_TRUE(all_positive(m));
  EXPECT_GE(worst_quality(m), worst);
  EXPECT_GT(radius_ratio_sum(m), sum);
  // The neighbours are the 8 corners: their centroid is the cube's centre.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.xyz[24 + i], 0.5, 1e-12);
  EXPECT_EQ(topo.quality(0), tet_quality(m.point(m.tets[0]), m.point(m.tets[1]), m.point(m.tets[2]), m.point(m.tets[3])));
  EXPECT_FALSE(relax(topo, 8, scratch, kNoFloor));
}

// On jittered cubes with a random centre: relaxation never lowers the worst
// tet nor leaves a tet non-positive, and a move always raises the radius
// ratios. Some of the cases have a centroid that would raise the radius
// ratios but lower the worst tet (they must be refused or halved).
TEST(Smoothing, RelaxationKeepsTheWorstTet) {
  std::mt19937 rng(11);
  size_t moved = 0, tempting = 0;
  for (int trial = 0; trial < 300; ++trial) {
    TetMesh m = jittered_coned_cube(rng);
    if (!all_positive(m)) continue;
    const double worst = worst_quality(m), sum = radius_ratio_sum(m);
    // What the full step to the centroid would do.
    TetMesh at_centroid = m;
    for (int i = 0; i < 3; ++i) {
      double c = 0;
      for (size_t v = 0; v < 8; ++v) c += m.xyz[3 * v + i] / 8;
      at_centroid.xyz[24 + i] = c;
    }
    tempting += all_positive(at_centroid) && worst_quality(at_centroid) < worst && radius_ratio_sum(at_centroid) > sum;
    const std::vector<double> before = m.xyz;
    TetTopology topo(m);
    SmoothingScratch scratch;
    const bool relaxed = relax(topo, 8, scratch, kNoFloor);
    moved += relaxed;
    EXPECT_TRUE(all_positive(m)) << "trial " << trial;
    EXPECT_GE(worst_quality(m), worst) << "trial " << trial;
    if (relaxed) {
      EXPECT_GT(radius_ratio_sum(m), sum) << "trial " << trial;
    } else {
      EXPECT_EQ(m.xyz, before) << "trial " << trial;
    }
  }
  EXPECT_GT(moved, 50u);
  EXPECT_GT(tempting, 5u);
}

// With a floor, a relaxation may lower the star's worst tet, but never
// under the floor: on jittered cubes with a random centre it moves where
// the floorless one refuses, or further, lowering the worst tet in many
// cases; every move raises the radius ratios and leaves every tet positive.
TEST(Smoothing, RelaxationLowersTheWorstTetOnlyToTheFloor) {
  std::mt19937 rng(12);
  const double floor = quality_of_angle(10);
  size_t freed = 0, lowered = 0;
  for (int trial = 0; trial < 300; ++trial) {
    TetMesh m = jittered_coned_cube(rng);
    if (!all_positive(m)) continue;
    const double worst = worst_quality(m), sum = radius_ratio_sum(m);
    TetMesh kept = m;
    TetTopology kept_topo(kept);
    SmoothingScratch scratch;
    const bool moved_without = relax(kept_topo, 8, scratch, kNoFloor);
    TetTopology topo(m);
    const bool moved = relax(topo, 8, scratch, floor);
    EXPECT_TRUE(all_positive(m)) << "trial " << trial;
    EXPECT_GE(worst_quality(m), std::min(worst, floor)) << "trial " << trial;
    if (moved) {
      EXPECT_GT(radius_ratio_sum(m), sum) << "trial " << trial;
    }
    freed += moved && !moved_without;
    lowered += worst_quality(m) < worst;
  }
  EXPECT_GT(freed, 0u);
  EXPECT_GT(lowered, 20u);
}

// The least norm point of the hull of 1 to 6 random vectors (some through
// the origin's side, some not) against the best convex combination on a
// fine grid of weights: never farther from the origin, and close to it.
// Gradients of near-flat tets can overflow: with only NaN candidates the
// direction is zero (no move), never whatever the output held before.
TEST(Smoothing, LeastNormDirectionOfNaNGradientsIsZero) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t n = 0; n <= 6; ++n) {
    if (n == 1 || n == 2) continue;  // copied or clamped: NaN in, NaN out
    std::vector<double> gradient(3 * n, nan);
    std::vector<size_t> active;
    for (size_t k = 0; k < n; ++k) active.push_back(k);
    double d[3] = {5, -7, 11};
    least_norm_direction(gradient, active, d);
    EXPECT_EQ(d[0], 0) << n;
    EXPECT_EQ(d[1], 0) << n;
    EXPECT_EQ(d[2], 0) << n;
  }
}

TEST(Smoothing, LeastNormDirectionMatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const size_t n = 1 + trial % 6;
    std::vector<double> gradient(3 * (n + 1));
    std::vector<size_t> active;
    const double shift = trial % 2 ? 0.0 : 1.5;  // half the sets lie off the origin
    for (size_t k = 0; k < n; ++k) {
      for (int i = 0; i < 3; ++i) gradient[3 * (k + 1) + i] = coord(rng) + (i == 0 ? shift : 0);
      active.push_back(k + 1);  // slot 0 unused: indices go through `active`
    }
    double d[3];
    least_norm_direction(gradient, active, d);
    const double got = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    // Brute force over weights on a grid of step 1/40 (n <= 3), coarser above.
    const int steps = n <= 3 ? 40 : 12;
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> w(n, 0);
    for (;;) {
      int used = 0;
      for (size_t k = 0; k + 1 < n; ++k) used += w[k];
      if (used <= steps) {
        double p[3] = {0, 0, 0};
        for (size_t k = 0; k < n; ++k) {
          const double weight = (k + 1 < n ? w[k] : steps - used) / static_cast<double>(steps);
          for (int i = 0; i < 3; ++i) p[i] += weight * gradient[3 * (k + 1) + i];
        }
        best = std::min(best, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
      }
      size_t k = 0;
      while (k + 1 < n && ++w[k] > steps) w[k++] = 0;
      if (k + 1 >= n) break;
    }
    EXPECT_LE(got, best + 1e-9) << "trial " << trial << ", " << n << " vectors";
    EXPECT_GE(got, best - (n <= 3 ? 0.05 : 0.2)) << "trial " << trial << ", " << n << " vectors";
  }
}

}  // namespace
}  // namespace partet
