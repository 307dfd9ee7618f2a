// Recursive bisection on one rank: nothing to cut, and the pieces it is
// made of: inertia axes of known point sets, MROB's closest coordinate axis,
// the ordered keys and the weighted cut, migration as the identity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "parallel/comm.hpp"
#include "parallel/migrate.hpp"
#include "partition/inertia.hpp"
#include "partition/recursive_bisection.hpp"
#include "partition/weighted_cut.hpp"

namespace partet {
namespace {

std::vector<double> random_points(size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xyz(3 * n);
  for (double& v : xyz) v = u(rng);
  return xyz;
}

// The principal axis of the unit-weight points xyz, on this (serial) comm.
std::vector<double> axis_of(const std::vector<double>& xyz, bool* valid = nullptr) {
  size_t n = xyz.size() / 3;
  std::vector<uint64_t> w(n, 1);
  std::vector<int32_t> slot(n, 0);
  InertiaAxes a = principal_axes(Comm::world(), xyz.data(), w.data(), slot.data(), n, 1);
  if (valid != nullptr) *valid = a.valid[0] != 0;
  return a.axis;
}

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(PartitionSerial, OneRankKeepsEverythingWithoutSeparators) {
  std::vector<double> xyz = random_points(500, 1);
  std::vector<double> w(500, 2.0);
  for (BisectionMethod m : {BisectionMethod::kRob, BisectionMethod::kRib, BisectionMethod::kMrob}) {
    PartitionResult r = partition_points(Comm::world(), xyz.data(), w.data(), 500, m);
    ASSERT_EQ(r.destination.size(), 500u);
    for (int32_t d : r.destination) EXPECT_EQ(d, 0);
    EXPECT_TRUE(r.separators.empty());
  }
  PartitionResult empty = partition_points(Comm::world(), nullptr, nullptr, 0, BisectionMethod::kMrob);
  EXPECT_TRUE(empty.destination.empty());
  EXPECT_TRUE(empty.separators.empty());
}

TEST(PartitionSerial, InvalidPointsAreRejected) {
  std::vector<double> xyz = random_points(4, 2);
  std::vector<double> w{1, 1, -1, 1};
  EXPECT_THROW(partition_points(Comm::world(), xyz.data(), w.data(), 4, BisectionMethod::kMrob), InternalError);
  w[2] = 1;
  xyz[5] = NAN;
  EXPECT_THROW(partition_points(Comm::world(), xyz.data(), w.data(), 4, BisectionMethod::kMrob), InternalError);
}

TEST(PartitionSerial, InertiaAxisOfALine) {
  std::vector<double> xyz;
  for (int i = 0; i < 101; ++i) {
    double t = i * 0.37 - 11.0;
    xyz.insert(xyz.end(), {t, t, 0.0});
  }
  std::vector<double> a = axis_of(xyz);
  EXPECT_NEAR(a[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(a[1], std::sqrt(0.5), 1e-12);
  EXPECT_EQ(a[2], 0.0);

  // A noisy line along (1, 2, -3): the axis follows it, largest component positive.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  xyz.clear();
  const double d[3] = {-1 / std::sqrt(14.0), -2 / std::sqrt(14.0), 3 / std::sqrt(14.0)};
  for (int i = 0; i < 2000; ++i) {
    double t = (i - 1000) * 0.01;
    for (int k = 0; k < 3; ++k) xyz.push_back(t * d[k] + noise(rng));
  }
  a = axis_of(xyz);
  EXPECT_GT(dot(a.data(), d), 0.9999);
  EXPECT_GT(a[2], 0.0);
  EXPECT_EQ(closest_coordinate_axis(a.data()), 2);
}

TEST(PartitionSerial, InertiaAxisOfAFlatDiscLiesInItsPlane) {
  // A disc in the plane through the origin with normal (1, 1, 1)/sqrt(3).
  const double n[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double e1[3] = {1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0};
  const double e2[3] = {1 / std::sqrt(6.0), 1 / std::sqrt(6.0), -2 / std::sqrt(6.0)};
  auto disc = [&](double stretch) {
    std::vector<double> xyz;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 64; ++j) {
        double r = (i + 0.5) / 40, t = 2 * std::numbers::pi * j / 64;
        double u = stretch * r * std::cos(t), v = r * std::sin(t);
        for (int k = 0; k < 3; ++k) xyz.push_back(u * e1[k] + v * e2[k]);
      }
    return xyz;
  };
  bool valid = false;
  std::vector<double> a = axis_of(disc(1.0), &valid);
  EXPECT_TRUE(valid);
  EXPECT_LT(std::fabs(dot(a.data(), n)), 1e-5);
  EXPECT_NEAR(dot(a.data(), a.data()), 1.0, 1e-12);
  // Stretched along e1, the disc's axis is e1.
  a = axis_of(disc(3.0));
  EXPECT_GT(std::fabs(dot(a.data(), e1)), 1 - 1e-9);
}

TEST(PartitionSerial, NoSpreadNoAxis) {
  bool valid = true;
  std::vector<double> a = axis_of({1, 2, 3, 1, 2, 3}, &valid);
  EXPECT_FALSE(valid);
  EXPECT_EQ(a, std::vector<double>({0, 0, 0}));
  double zero[6] = {0, 0, 0, 0, 0, 0}, axis[3];
  EXPECT_FALSE(principal_axis_of_covariance(zero, axis));
}

TEST(PartitionSerial, CovarianceEigenvector) {
  double axis[3];
  const double diag[6] = {1, 3, 2, 0, 0, 0};
  ASSERT_TRUE(principal_axis_of_covariance(diag, axis));
  EXPECT_EQ(axis[0], 0.0);
  EXPECT_EQ(axis[1], 1.0);
  EXPECT_EQ(axis[2], 0.0);
  // [[2, 1, 0], [1, 2, 0], [0, 0, 1]]: eigenvalue 3 along (1, 1, 0).
  const double mixed[6] = {2, 2, 1, 1, 0, 0};
  ASSERT_TRUE(principal_axis_of_covariance(mixed, axis));
  EXPECT_NEAR(axis[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(axis[1], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(axis[2], 0.0, 1e-15);
}

TEST(PartitionSerial, MrobTakesTheClosestCoordinateAxis) {
  const double a[3] = {0.3, -0.9, 0.1};
  EXPECT_EQ(closest_coordinate_axis(a), 1);
  const double b[3] = {-0.1, 0.2, -0.97};
  EXPECT_EQ(closest_coordinate_axis(b), 2);
  const double tie[3] = {0.6, -0.6, 0.1};
  EXPECT_EQ(closest_coordinate_axis(tie), 0);
  // The closest axis of a cloud stretched along (0.4, 0.2, 1) is z.
  std::vector<double> xyz = random_points(3000, 4);
  for (size_t i = 0; i < 3000; ++i) {
    double t = xyz[3 * i] * 10;
    xyz[3 * i] = 0.4 * t + 0.1 * xyz[3 * i + 1];
    xyz[3 * i + 1] = 0.2 * t + 0.1 * xyz[3 * i + 2];
    xyz[3 * i + 2] = t;
  }
  EXPECT_EQ(closest_coordinate_axis(axis_of(xyz).data()), 2);
}

TEST(PartitionSerial, OrderedKeysFollowTheDoubles) {
  const double v[] = {-INFINITY, -1e300, -1.0, -1e-310, 0.0, 1e-310, 0.5, 1.0, 1e300, INFINITY};
  for (size_t i = 0; i + 1 < std::size(v); ++i) EXPECT_LT(ordered_key(v[i]), ordered_key(v[i + 1])) << i;
  EXPECT_EQ(ordered_key(-0.0), ordered_key(0.0));
}

TEST(PartitionSerial, WeightedCutTakesThePrefixClosestToTheTarget) {
  // Projections ordered 0..5 (given out of order, differing in a middle
  // byte of their keys' first word); weights 1..6.
  std::vector<uint64_t> order{3, 0, 5, 1, 4, 2};
  const size_t n = order.size();
  std::vector<double> projection(n), xyz(3 * n, 0.0), key_weight(n, 1.0);
  std::vector<uint64_t> w(n);
  std::vector<int32_t> slot(n, 0);
  for (size_t i = 0; i < n; ++i) {
    projection[i] = 1.0 + std::ldexp(static_cast<double>(order[i]), -30);
    w[i] = order[i] + 1;
  }
  const CutKeys keys{projection.data(), xyz.data(), key_weight.data(), 0};
  auto low_keys = [&](uint64_t target) {
    std::vector<uint8_t> low = weighted_cut(Comm::world(), keys, w.data(), slot.data(), n, {target});
    std::vector<uint64_t> out;
    for (size_t i = 0; i < low.size(); ++i)
      if (low[i]) out.push_back(order[i]);
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(low_keys(5), (std::vector<uint64_t>{0, 1, 2}));  // 1+2+3 = 6 is closer to 5 than 3
  EXPECT_EQ(low_keys(4), (std::vector<uint64_t>{0, 1}));        // 3 is closer to 4 than 6
  EXPECT_EQ(low_keys(8), (std::vector<uint64_t>{0, 1, 2, 3}));  // 6 and 10 are as close: take the point
  EXPECT_EQ(low_keys(0), (std::vector<uint64_t>{}));
  EXPECT_EQ(low_keys(21), (std::vector<uint64_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(low_keys(100), (std::vector<uint64_t>{0, 1, 2, 3, 4, 5}));
}

TEST(PartitionSerial, WeightedCutBreaksTiesWithLaterKeyWords) {
  // Equal projections and x; y (the key's third word) orders the points;
  // points of no slot stay out.
  const size_t n = 8;
  std::vector<double> projection(n, 7.0), xyz(3 * n, 0.0), key_weight(n, 1.0);
  std::vector<uint64_t> w(n, 1);
  std::vector<int32_t> slot(n, 0);
  for (size_t i = 0; i < n; ++i) xyz[3 * i + 1] = static_cast<double>(n - i);
  const CutKeys keys{projection.data(), xyz.data(), key_weight.data(), 0};
  slot[0] = -1;
  std::vector<uint8_t> low = weighted_cut(Comm::world(), keys, w.data(), slot.data(), n, {3});
  EXPECT_EQ(low, (std::vector<uint8_t>{0, 0, 0, 0, 0, 1, 1, 1}));
  // Two slots at once, one of them empty.
  slot.assign(n, 0);
  for (size_t i = 0; i < n; i += 2) slot[i] = 2;
  low = weighted_cut(Comm::world(), keys, w.data(), slot.data(), n, {1, 0, 2});
  EXPECT_EQ(low, (std::vector<uint8_t>{0, 0, 0, 0, 1, 0, 1, 1}));
  // Equal points and weights: the global index (the last word) decides,
  // the lowest first.
  std::fill(xyz.begin(), xyz.end(), 0.5);
  slot.assign(n, 0);
  const CutKeys same{projection.data(), xyz.data(), key_weight.data(), 40};
  EXPECT_EQ(weighted_cut(Comm::world(), same, w.data(), slot.data(), n, {3}),
            (std::vector<uint8_t>{1, 1, 1, 0, 0, 0, 0, 0}));
}

TEST(PartitionSerial, MigrateOnOneRankIsTheIdentity) {
  std::vector<int32_t> dest{0, 0, 0};
  std::vector<double> xyz{1, 2, 3, 4, 5, 6, 7, 8, 9};
  std::vector<int32_t> sources;
  EXPECT_EQ(migrate(Comm::world(), dest, xyz, 3, &sources), xyz);
  EXPECT_EQ(sources, (std::vector<int32_t>{0, 0, 0}));
  dest[1] = 1;
  EXPECT_THROW(migrate(Comm::world(), dest, xyz, 3), InternalError);
  EXPECT_THROW(migrate(Comm::world(), dest, std::vector<double>{1.0}, 3), InternalError);
}

}  // namespace
}  // namespace partet
