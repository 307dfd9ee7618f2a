// Tests of the tet quality metrics: the regular tet, the Kuhn cube, slivers,
// degenerate tets (no NaN), the 1st percentile, skipped tets, the tets
// under an angle, and JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "check/compensated_sum.hpp"
#include "check/quality.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

const double kRegularDihedral = std::acos(1.0 / 3) * 180 / std::numbers::pi;  // 70.5288 degrees

// Regular tet, positively oriented: alternate corners of the cube [-1,1]^3.
TetMesh regular_tet() {
  TetMesh m;
  m.xyz = {1, 1, 1, -1, 1, -1, 1, -1, -1, -1, -1, 1};
  m.tets = {0, 1, 2, 3};
  return m;
}

double rad_to_deg(double r) { return r * 180 / std::numbers::pi; }

TetShape shape_of(const TetMesh& m, size_t t) {
  const uint32_t* v = &m.tets[4 * t];
  return tet_shape(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

TEST(QualityTetShape, RegularTet) {
  TetShape s = shape_of(regular_tet(), 0);
  EXPECT_NEAR(rad_to_deg(s.min_dihedral_rad), kRegularDihedral, 1e-12);
  EXPECT_NEAR(rad_to_deg(s.max_dihedral_rad), kRegularDihedral, 1e-12);
  EXPECT_NEAR(kRegularDihedral, 70.528779365509308, 1e-12);
  EXPECT_NEAR(s.radius_ratio, 1, 1e-14);
  EXPECT_NEAR(s.edge_ratio, 1, 1e-15);
  EXPECT_NEAR(s.volume, 8.0 / 3, 1e-14);
}

TEST(QualityTetShape, OrientationDoesNotChangeShape) {
  TetMesh m = regular_tet();
  std::swap(m.tets[0], m.tets[1]);
  TetShape s = shape_of(m, 0);
  EXPECT_NEAR(s.volume, -8.0 / 3, 1e-14);
  EXPECT_NEAR(s.radius_ratio, 1, 1e-14);
  EXPECT_NEAR(rad_to_deg(s.min_dihedral_rad), kRegularDihedral, 1e-12);
}

TEST(QualityTetShape, ScaledAndTranslatedRegularTetFarFromOrigin) {
  TetMesh m = regular_tet();
  for (size_t i = 0; i < m.xyz.size(); ++i) m.xyz[i] = 1e6 + 1e-3 * m.xyz[i];
  TetShape s = shape_of(m, 0);
  EXPECT_NEAR(s.radius_ratio, 1, 1e-6);
  EXPECT_NEAR(rad_to_deg(s.min_dihedral_rad), kRegularDihedral, 1e-5);
}

TEST(QualityTetShape, Sliver) {
  // Four nearly coplanar points: the corners of a unit square, two of them
  // lifted by h. Dihedral angles near 0 and 180, radius ratio near 0.
  const double h = 1e-3;
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 1, 0, 1, 0, h, 0, 1, h};
  m.tets = {0, 1, 2, 3};
  TetShape s = shape_of(m, 0);
  EXPECT_LT(rad_to_deg(s.min_dihedral_rad), 0.2);
  EXPECT_GT(rad_to_deg(s.max_dihedral_rad), 179.8);
  EXPECT_GT(s.radius_ratio, 0);
  EXPECT_LT(s.radius_ratio, 1e-2);
  EXPECT_NEAR(s.edge_ratio, std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(std::fabs(s.volume), h / 3, 1e-15);
}

TEST(QualityTetShape, FlatTetGivesZeroAndStraightAnglesWithoutNaN) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  m.tets = {0, 1, 2, 3};
  TetShape s = shape_of(m, 0);
  EXPECT_EQ(s.radius_ratio, 0);
  EXPECT_EQ(s.volume, 0);
  EXPECT_EQ(rad_to_deg(s.min_dihedral_rad), 0);
  EXPECT_NEAR(rad_to_deg(s.max_dihedral_rad), 180, 1e-12);
}

TEST(QualityTetShape, CoincidentPointsGiveNoNaN) {
  TetMesh m;
  m.xyz = {0.5, 0.5, 0.5};
  m.tets = {0, 0, 0, 0};
  TetShape s = shape_of(m, 0);
  EXPECT_EQ(s.radius_ratio, 0);
  EXPECT_EQ(s.min_dihedral_rad, 0);
  EXPECT_EQ(s.max_dihedral_rad, std::numbers::pi);
  EXPECT_TRUE(std::isinf(s.edge_ratio));
  EXPECT_FALSE(std::isnan(s.volume));
}

TEST(QualityTetShape, MinDihedralAloneIsTetShapes) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1e-3, 0.3, 0.2, 0.1, 1, 1, 0};
  // Regular-ish, sliver, flat, coincident corners, and both orientations.
  const uint32_t tets[][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {1, 2, 4, 0}, {0, 1, 2, 6}, {0, 0, 1, 2}, {5, 1, 2, 3}};
  for (const auto& t : tets) {
    const double* p[4] = {m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])};
    EXPECT_EQ(tet_min_dihedral(p[0], p[1], p[2], p[3]), tet_shape(p[0], p[1], p[2], p[3]).min_dihedral_rad);
  }
}

TEST(QualityMeasure, RegularTet) {
  QualityStats q = measure_quality(regular_tet());
  EXPECT_EQ(q.tets, 1u);
  EXPECT_NEAR(q.min_dihedral_deg, kRegularDihedral, 1e-12);
  EXPECT_NEAR(q.max_dihedral_deg, kRegularDihedral, 1e-12);
  EXPECT_NEAR(q.radius_ratio_min, 1, 1e-14);
  EXPECT_NEAR(q.radius_ratio_mean, 1, 1e-14);
  EXPECT_NEAR(q.radius_ratio_p01, 1, 1e-14);
  EXPECT_EQ(q.dihedral_under_5 + q.dihedral_under_10 + q.dihedral_under_20, 0u);
  EXPECT_NEAR(q.edge_ratio_max, 1, 1e-15);
  EXPECT_NEAR(q.volume, 8.0 / 3, 1e-14);
}

TEST(QualityMeasure, KuhnCube) {
  // The Kuhn simplex has dihedral angles of 45, 60 and 90 degrees.
  QualityStats q = measure_quality(test::cube_tets());
  EXPECT_EQ(q.tets, 6u);
  EXPECT_NEAR(q.min_dihedral_deg, 45, 1e-12);
  EXPECT_NEAR(q.max_dihedral_deg, 90, 1e-12);
  EXPECT_NEAR(q.edge_ratio_max, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(q.edge_ratio_mean, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(q.radius_ratio_min, q.radius_ratio_mean, 1e-14);
  EXPECT_GT(q.radius_ratio_min, 0.5);
  EXPECT_LT(q.radius_ratio_min, 0.8);
  EXPECT_DOUBLE_EQ(q.volume, 1);
}

// `count` translated copies of the regular tet, the first `slivers` of them
// replaced by slivers of decreasing thickness.
TetMesh tets_with_slivers(size_t count, size_t slivers) {
  TetMesh m;
  TetMesh regular = regular_tet();
  for (size_t i = 0; i < count; ++i) {
    uint32_t base = static_cast<uint32_t>(m.num_vertices());
    if (i < slivers) {
      double h = 1e-2 / static_cast<double>(i + 1);
      double sliver[12] = {0, 0, 0, 1, 1, 0, 1, 0, h, 0, 1, h};
      m.xyz.insert(m.xyz.end(), sliver, sliver + 12);
    } else {
      m.xyz.insert(m.xyz.end(), regular.xyz.begin(), regular.xyz.end());
    }
    for (size_t k = base * 3; k < m.xyz.size(); k += 3) m.xyz[k] += 3.0 * static_cast<double>(i);
    for (uint32_t k = 0; k < 4; ++k) m.tets.push_back(base + k);
  }
  return m;
}

TEST(QualityMeasure, FirstPercentileAndSmallAngleCounts) {
  QualityStats one_in_100 = measure_quality(tets_with_slivers(100, 1));
  EXPECT_EQ(one_in_100.tets, 100u);
  EXPECT_LT(one_in_100.radius_ratio_p01, 0.05);
  EXPECT_EQ(one_in_100.radius_ratio_p01, one_in_100.radius_ratio_min);
  EXPECT_EQ(one_in_100.dihedral_under_5, 1u);
  EXPECT_EQ(one_in_100.dihedral_under_20, 1u);
  EXPECT_LT(one_in_100.min_dihedral_deg, 5);
  EXPECT_GT(one_in_100.max_dihedral_deg, 175);

  // Rank floor(0.01 * 199) = 1: the second smallest, here a regular tet.
  QualityStats one_in_200 = measure_quality(tets_with_slivers(200, 1));
  EXPECT_NEAR(one_in_200.radius_ratio_p01, 1, 1e-14);
  QualityStats three_in_300 = measure_quality(tets_with_slivers(300, 3));
  EXPECT_LT(three_in_300.radius_ratio_p01, 0.05);
  EXPECT_GT(three_in_300.radius_ratio_p01, three_in_300.radius_ratio_min);
  EXPECT_EQ(three_in_300.dihedral_under_5, 3u);
}

// Over blocks of tets (more than one, a partial last one), flat and
// coincident tets among them, the mesh's measure is the per-tet shapes
// added up in tet order: the same bits.
TEST(QualityMeasure, IsThePerTetShapesAddedUp) {
  TetMesh m;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int i = 0; i < 300; ++i) m.xyz.insert(m.xyz.end(), {coordinate(rng), coordinate(rng), coordinate(rng)});
  m.xyz.insert(m.xyz.end(), {0, 0, 0, 1, 0, 0, 2, 0, 0});  // collinear: flat tets
  std::uniform_int_distribution<uint32_t> vertex(0, 299);
  for (int t = 0; t < 700; ++t) {
    const uint32_t a = vertex(rng), b = (a + 1 + vertex(rng) % 99) % 300, c = (b + 1 + vertex(rng) % 99) % 300,
                   d = (c + 1 + vertex(rng) % 99) % 300;  // four different points
    m.tets.insert(m.tets.end(), {a, b, c, d});
  }
  m.tets.insert(m.tets.end(), {300, 301, 302, 7, 4, 4, 5, 6});
  const QualityStats q = measure_quality(m);
  size_t under[3] = {0, 0, 0};
  double rr_sum = 0, rr_min = 1, edge_sum = 0, edge_max = 0, smallest = 7, largest = -1;
  CompensatedSum volume;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    const TetShape s = tet_shape(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    const double degrees[3] = {5, 10, 20};
    for (int i = 0; i < 3; ++i) under[i] += rad_to_deg(s.min_dihedral_rad) < degrees[i];
    rr_sum += s.radius_ratio;
    rr_min = std::min(rr_min, s.radius_ratio);
    edge_sum += s.edge_ratio;
    edge_max = std::max(edge_max, s.edge_ratio);
    smallest = std::min(smallest, s.min_dihedral_rad);
    largest = std::max(largest, s.max_dihedral_rad);
    volume.add(s.volume);
  }
  EXPECT_EQ(q.tets, m.num_tets());
  EXPECT_EQ(q.dihedral_under_5, under[0]);
  EXPECT_EQ(q.dihedral_under_10, under[1]);
  EXPECT_EQ(q.dihedral_under_20, under[2]);
  EXPECT_EQ(q.radius_ratio_mean, rr_sum / static_cast<double>(m.num_tets()));
  EXPECT_EQ(q.radius_ratio_min, rr_min);
  EXPECT_EQ(q.edge_ratio_max, edge_max);
  EXPECT_EQ(q.edge_ratio_mean, edge_sum / static_cast<double>(m.num_tets()));
  EXPECT_EQ(q.volume, volume.value());
  EXPECT_EQ(q.min_dihedral_deg, 0);  // the flat tets
  EXPECT_EQ(q.max_dihedral_deg, 180);
  EXPECT_EQ(smallest, 0);
  // Without the flat ones, the extreme angles are the shapes'.
  m.tets.resize(4 * 700);
  const QualityStats fair = measure_quality(m);
  smallest = 7, largest = -1;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    const TetShape s = tet_shape(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    smallest = std::min(smallest, s.min_dihedral_rad);
    largest = std::max(largest, s.max_dihedral_rad);
  }
  EXPECT_GT(rad_to_deg(smallest), 0);
  EXPECT_NEAR(fair.min_dihedral_deg, rad_to_deg(smallest), 1e-12);
  EXPECT_NEAR(fair.max_dihedral_deg, rad_to_deg(largest), 1e-12);
}

// tets_under_angle flags the tets tet_shape gives a smallest angle under
// the bound (random tets, over more than one block of them) and the flat
// ones; the regular tet only above its own angle.
TEST(QualityMeasure, TetsUnderAngleAreTheShapesUnderIt) {
  TetMesh m;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int i = 0; i < 200; ++i) m.xyz.insert(m.xyz.end(), {coordinate(rng), coordinate(rng), coordinate(rng)});
  m.xyz.insert(m.xyz.end(), {0, 0, 0, 1, 0, 0, 2, 0, 0});  // collinear: a flat tet
  std::uniform_int_distribution<uint32_t> vertex(0, 199);
  for (int t = 0; t < 900; ++t) {
    const uint32_t a = vertex(rng), b = (a + 1 + vertex(rng) % 66) % 200, c = (b + 1 + vertex(rng) % 66) % 200,
                   d = (c + 1 + vertex(rng) % 66) % 200;
    m.tets.insert(m.tets.end(), {a, b, c, d});
  }
  m.tets.insert(m.tets.end(), {200, 201, 202, 7});
  for (const double degrees : {2.0, 10.0, 40.0}) {
    const std::vector<uint8_t> under = tets_under_angle(m, degrees);
    ASSERT_EQ(under.size(), m.num_tets());
    size_t count = 0;
    for (size_t t = 0; t < m.num_tets(); ++t) {
      const TetShape s = shape_of(m, t);
      EXPECT_EQ(under[t] != 0, rad_to_deg(s.min_dihedral_rad) < degrees) << t << " at " << degrees;
      count += under[t];
    }
    EXPECT_GT(count, 0u);
    EXPECT_LT(count, m.num_tets());
    EXPECT_EQ(under.back(), 1);
  }
  const TetMesh regular = regular_tet();
  EXPECT_EQ(tets_under_angle(regular, kRegularDihedral - 1e-9)[0], 0);
  EXPECT_EQ(tets_under_angle(regular, kRegularDihedral + 1e-9)[0], 1);
}

TEST(QualityMeasure, SkipsOutOfRangeAndNonFiniteTets) {
  TetMesh m = test::cube_tets();
  m.tets[4 * 2 + 1] = 1000;
  m.xyz[3 * 5] = std::numeric_limits<double>::quiet_NaN();  // vertex 5: tets 4 and 5
  QualityStats q = measure_quality(m);
  EXPECT_EQ(q.tets, 3u);
  EXPECT_DOUBLE_EQ(q.volume, 0.5);
  EXPECT_FALSE(std::isnan(q.radius_ratio_mean));
}

TEST(QualityMeasure, EmptyMeshGivesZeros) {
  QualityStats q = measure_quality(TetMesh{});
  EXPECT_EQ(q.tets, 0u);
  EXPECT_EQ(q.radius_ratio_min, 0);
  EXPECT_EQ(q.volume, 0);
}

TEST(QualityJson, FieldsAndInfiniteEdgeRatioAsNull) {
  nlohmann::json j = measure_quality(test::cube_tets());
  EXPECT_EQ(j["tets"], 6);
  EXPECT_NEAR(j["min_dihedral_deg"].get<double>(), 45, 1e-12);
  for (const char* key : {"max_dihedral_deg", "radius_ratio_min", "radius_ratio_mean",
                          "radius_ratio_p01", "dihedral_under_5", "dihedral_under_10",
                          "dihedral_under_20", "edge_ratio_max", "edge_ratio_mean", "volume"})
    EXPECT_TRUE(j.contains(key)) << key;

  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.tets = {0, 1, 2, 2};
  nlohmann::json degenerate = measure_quality(m);
  EXPECT_TRUE(degenerate["edge_ratio_max"].is_null());
  EXPECT_EQ(degenerate["radius_ratio_min"], 0.0);
  EXPECT_NO_THROW(static_cast<void>(degenerate.dump()));
}

}  // namespace
}  // namespace partet
