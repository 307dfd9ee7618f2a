// The pieces of the boundary partition on one rank: the exact centroid
// rule for surface faces (a centroid that floating point puts on the wrong
// side of a leaf plane), leaf centres, and front part assembly (order
// independent of the input order; faces of a leaf not held are an error).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "partition/boundary_front.hpp"
#include "partition/boundary_partition.hpp"
#include "partition/front_part.hpp"

namespace partet {
namespace {

// The uniform tree of level `level` (8^level leaves), classes boundary.
LinearOctree uniform_tree(int level) {
  LinearOctree t;
  const uint32_t n = 1u << level, edge = octant_edge(level);
  for (uint32_t x = 0; x < n; ++x)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t z = 0; z < n; ++z) t.key.push_back(morton_key(x * edge, y * edge, z * edge));
  std::sort(t.key.begin(), t.key.end());
  t.level.assign(t.key.size(), static_cast<uint8_t>(level));
  t.cls.assign(t.key.size(), LeafClass::kBoundary);
  t.owner.assign(t.key.size(), 0);
  return t;
}

TEST(BoundaryFront, CentroidLeafIsExactWhereRoundingIsNot) {
  const LinearOctree tree = uniform_tree(2);
  const RootCube root;  // origin 0, one grid unit = 1
  const double plane = octant_edge(2);  // x = 2^18, between the first two leaf columns
  // x: 3 * plane, -2^-35, 2^-36: the sum is 3 * plane - 2^-36, just below
  // the plane, but in floating point both small terms vanish.
  const double a[3] = {3 * plane, 100, 100}, b[3] = {-std::ldexp(1.0, -35), 100, 400},
               c[3] = {std::ldexp(1.0, -36), 400, 100};
  ASSERT_EQ((a[0] + b[0] + c[0]) / 3, plane);
  const size_t leaf = leaf_of_centroid(tree, root, a, b, c);
  uint32_t x, y, z;
  tree.anchor(leaf, x, y, z);
  EXPECT_EQ(x, 0u);
  EXPECT_EQ(y, 0u);
  EXPECT_EQ(z, 0u);
  // Exactly on the plane: the upper leaf (half-open boxes).
  const double on[3] = {0, 100, 100};
  const size_t upper = leaf_of_centroid(tree, root, a, on, on);
  tree.anchor(upper, x, y, z);
  EXPECT_EQ(x, octant_edge(2));
}

TEST(BoundaryFront, LeafCentresAreLatticePoints) {
  RootCube root;
  root.origin[0] = -8;
  root.unit = 0.5;
  double c[3];
  octant_centre(root, morton_key(0, 0, 0), 1, c);
  EXPECT_EQ(c[0], -8 + 0.5 * octant_edge(2));  // half a level-1 edge, in units of 0.5
  EXPECT_EQ(c[1], 0.5 * octant_edge(2));
  octant_centre(root, morton_key(3, 5, 7), kMaxLevel, c);
  EXPECT_EQ(c[0], -8 + 1.75);
  EXPECT_EQ(c[1], 2.75);
  EXPECT_EQ(c[2], 3.75);
}

// Two leaves, three faces over four vertices, given in a scrambled order.
FaceBatch scrambled_batch(bool reversed) {
  FaceBatch b;
  b.global_ids = {40, 10, 30, 20};
  for (uint64_t id : b.global_ids) b.xyz.insert(b.xyz.end(), {double(id), 0, 0});
  b.leaf_key = {8, 0, 8};
  b.faces = reversed ? std::vector<uint32_t>{3, 2, 1, 1, 2, 3, 0, 1, 2} : std::vector<uint32_t>{0, 1, 2, 1, 2, 3, 3, 2, 1};
  return b;
}

TEST(BoundaryFront, AssemblyOrderDoesNotDependOnTheInputOrder) {
  LinearOctree leaves;
  leaves.key = {0, 8};
  leaves.level = {kMaxLevel, kMaxLevel};
  leaves.cls = {LeafClass::kBoundary, LeafClass::kTooClose};
  const FrontPart a = assemble_front_part(leaves, scrambled_batch(false), 3);
  const FrontPart b = assemble_front_part(leaves, scrambled_batch(true), 3);
  EXPECT_EQ(a.global_ids, (std::vector<uint64_t>{10, 20, 30, 40}));
  EXPECT_EQ(a.leaf_first_face, (std::vector<uint32_t>{0, 1, 3}));
  EXPECT_EQ(a.leaf_work(1), 2u);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.xyz, b.xyz);
  EXPECT_EQ(a.leaves.owner, (std::vector<int32_t>{3, 3}));
  // Leaf 1's faces ordered by their ids as oriented: (20, 30, 10) before (40, 10, 30).
  EXPECT_EQ(std::vector<uint32_t>(a.faces.begin() + 3, a.faces.end()), (std::vector<uint32_t>{1, 2, 0, 3, 0, 2}));
}

TEST(BoundaryFront, AFaceOfALeafNotHeldIsAnError) {
  LinearOctree leaves;
  leaves.key = {0};
  leaves.level = {kMaxLevel};
  leaves.cls = {LeafClass::kBoundary};
  EXPECT_THROW(assemble_front_part(leaves, scrambled_batch(false), 0), InternalError);
}

}  // namespace
}  // namespace partet
