// The deepest kernel point of an open, nearly flat patch: in the patch's
// own bounding box it lies almost on the patch (the mechanism that put the
// tree-less removals' patch cones' new vertices next to flat surfaces);
// with the box lifted along the patch's normal it rises by the lift.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/kernel_point.hpp"
#include "core/predicates.hpp"

namespace partet::test {
namespace {

// An n x n grid of unit squares in the plane z = 0, two triangles each,
// facing +z, the grid's interior vertices raised by `bump` (a patch that
// is flat but for rounding-sized unevenness).
std::vector<double> flat_patch(int n, double bump) {
  auto z = [&](int i, int j) { return i > 0 && i < n && j > 0 && j < n && (i + j) % 2 == 0 ? bump : 0.0; };
  std::vector<double> t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a[3] = {double(i), double(j), z(i, j)}, b[3] = {double(i + 1), double(j), z(i + 1, j)};
      const double c[3] = {double(i + 1), double(j + 1), z(i + 1, j + 1)}, d[3] = {double(i), double(j + 1), z(i, j + 1)};
      for (const double* p : {a, b, c, a, c, d}) t.insert(t.end(), p, p + 3);
    }
  return t;
}

TEST(KernelPoint, FlatPatchPointLiesOnItWithoutLift) {
  const std::vector<double> patch = flat_patch(4, 1e-7);
  const KernelPoint k = deepest_kernel_point(patch);
  ASSERT_TRUE(k.found);
  EXPECT_LE(k.depth, 1e-7);
  EXPECT_LE(k.point[2], 1e-7);
}

TEST(KernelPoint, LiftedBoxLetsAFlatPatchPointRise) {
  const std::vector<double> patch = flat_patch(4, 1e-7);
  const double lift[3] = {0, 0, 0.75};
  const KernelPoint k = deepest_kernel_point(patch, lift);
  ASSERT_TRUE(k.found);
  EXPECT_GT(k.depth, 0.7);
  EXPECT_LE(k.point[2], 0.75 + 1e-7);
  for (size_t i = 0; i < patch.size(); i += 9)
    EXPECT_GT(orient3d(&patch[i], &patch[i + 3], &patch[i + 6], k.point), 0) << "triangle " << i / 9;
}

TEST(KernelPoint, LiftDoesNotMoveAClosedRegionsPoint) {
  // The unit cube's six faces seen from inside: the deepest point is the
  // centre at depth 0.5 whatever the lift, which only widens the box.
  const double v[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<double> t;
  for (const auto& q : quads)
    for (int corner : {q[0], q[1], q[2], q[0], q[2], q[3]}) t.insert(t.end(), v[corner], v[corner] + 3);
  // Inward: reverse the outward quads.
  for (size_t i = 0; i < t.size(); i += 9)
    for (int k = 0; k < 3; ++k) std::swap(t[i + 3 + k], t[i + 6 + k]);
  const double lift[3] = {0, 0, 2};
  for (const double* l : {static_cast<const double*>(nullptr), lift}) {
    const KernelPoint k = deepest_kernel_point(t, l);
    ASSERT_TRUE(k.found);
    EXPECT_NEAR(k.depth, 0.5, 1e-9);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(k.point[c], 0.5, 1e-9);
  }
}

}  // namespace
}  // namespace partet::test
