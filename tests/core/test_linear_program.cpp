// The small simplex solver: optimum on simple and degenerate programs,
// a zero objective, and an unbounded one.
#include <gtest/gtest.h>

#include "core/linear_program.hpp"

namespace partet {
namespace {

TEST(LinearProgram, SimpleOptimum) {
  // max x + y: x <= 1, y <= 2, x + y <= 2.5.
  LpResult r = maximise_lp({1, 0, 0, 1, 1, 1}, {1, 2, 2.5}, {1, 1});
  ASSERT_EQ(r.status, LpStatus::kOptimal);
  EXPECT_NEAR(r.objective, 2.5, 1e-12);
  EXPECT_NEAR(r.x[0] + r.x[1], 2.5, 1e-12);
}

TEST(LinearProgram, DegenerateConstraintsDoNotCycle) {
  // Many constraints through the optimum (1, 1): x + k y <= 1 + k.
  std::vector<double> a, b;
  for (int k = 0; k < 40; ++k) {
    a.insert(a.end(), {1.0, static_cast<double>(k)});
    b.push_back(1.0 + k);
    a.insert(a.end(), {static_cast<double>(k), 1.0});
    b.push_back(1.0 + k);
  }
  LpResult r = maximise_lp(a, b, {1, 1});
  ASSERT_EQ(r.status, LpStatus::kOptimal);
  EXPECT_NEAR(r.x[0], 1, 1e-12);
  EXPECT_NEAR(r.x[1], 1, 1e-12);
}

TEST(LinearProgram, ZeroObjectiveAndUnbounded) {
  LpResult zero = maximise_lp({1, 1}, {1}, {0, 0});
  ASSERT_EQ(zero.status, LpStatus::kOptimal);
  EXPECT_EQ(zero.objective, 0);
  LpResult unbounded = maximise_lp({1, -1}, {1}, {0, 1});
  EXPECT_EQ(unbounded.status, LpStatus::kUnbounded);
}

}  // namespace
}  // namespace partet
