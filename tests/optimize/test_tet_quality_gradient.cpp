// The analytic gradient of tet_quality against central differences, on
// random tets (positive and inverted) and for every vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

TEST(TetQualityGradient, MatchesCentralDifferencesAndTheValue) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    double x[4][3];
    for (auto& point : x)
      for (double& c : point) c = coordinate(rng);
    const double* p[4] = {x[0], x[1], x[2], x[3]};
    const double q = tet_quality(p[0], p[1], p[2], p[3]);
    for (int j = 0; j < 4; ++j) {
      double g[3];
      EXPECT_EQ(tet_quality_gradient(p, j, g), q);
      const double h = 1e-7;
      double numeric[3];
      bool smooth = true;
      for (int k = 0; k < 3; ++k) {
        const double keep = x[j][k];
        x[j][k] = keep + h;
        const double up = tet_quality(p[0], p[1], p[2], p[3]);
        x[j][k] = keep - h;
        const double down = tet_quality(p[0], p[1], p[2], p[3]);
        x[j][k] = keep;
        numeric[k] = (up - down) / (2 * h);
        // Near a kink (two edges tying) the one-sided slopes differ.
        const double left = (q - down) / h, right = (up - q) / h;
        smooth = smooth && std::fabs(left - right) <= 1e-4 * (1 + std::fabs(left));
      }
      if (!smooth) continue;
      ++compared;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(g[k], numeric[k], 1e-5 * (1 + std::fabs(numeric[k]))) << trial << " " << j;
    }
  }
  EXPECT_GT(compared, 1400);
}

TEST(TetQualityGradient, ZeroForADegenerateFace) {
  const double x[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 1}};
  const double* p[4] = {x[0], x[1], x[2], x[3]};
  double g[3] = {1, 1, 1};
  EXPECT_EQ(tet_quality_gradient(p, 3, g), 0);
  EXPECT_EQ(g[0], 0);
  EXPECT_EQ(g[1], 0);
  EXPECT_EQ(g[2], 0);
}

}  // namespace
}  // namespace partet
