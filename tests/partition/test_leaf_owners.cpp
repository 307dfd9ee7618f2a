// rank_of_point and set_leaf_owners on one rank: points go down the
// separators' tree to the rank whose side they lie on (the low side when
// exactly on a plane), and on one rank every leaf is rank 0's.
#include <gtest/gtest.h>

#include <vector>

#include "parallel/comm.hpp"
#include "partition/leaf_owners.hpp"

namespace partet {
namespace {

Separator cut(int axis, double offset, int first, int mid, int last, int depth) {
  Separator s{};
  s.normal[axis] = 1;
  s.offset = offset;
  s.axis = axis;
  s.first_rank = first;
  s.mid_rank = mid;
  s.last_rank = last;
  s.depth = depth;
  return s;
}

TEST(LeafOwners, PointsFollowTheSeparators) {
  // Three ranks: x <= 0 is rank 0; x > 0 splits at y <= 1 into ranks 1 and 2.
  const std::vector<Separator> separators = {cut(0, 0, 0, 1, 3, 0), cut(1, 1, 1, 2, 3, 1)};
  const double a[3] = {-1, 5, 0}, b[3] = {2, 0, 0}, c[3] = {2, 3, 0}, on_x[3] = {0, 9, 9}, on_y[3] = {1, 1, 0};
  EXPECT_EQ(rank_of_point(separators, 3, a), 0);
  EXPECT_EQ(rank_of_point(separators, 3, b), 1);
  EXPECT_EQ(rank_of_point(separators, 3, c), 2);
  EXPECT_EQ(rank_of_point(separators, 3, on_x), 0);
  EXPECT_EQ(rank_of_point(separators, 3, on_y), 1);
  EXPECT_EQ(rank_of_point({}, 1, a), 0);
}

TEST(LeafOwners, OneRankOwnsEveryLeaf) {
  LinearOctree tree;
  for (uint32_t i = 0; i < 8; ++i) {
    const uint32_t e = octant_edge(1);
    tree.key.push_back(morton_key((i & 1) * e, ((i >> 1) & 1) * e, (i >> 2) * e));
  }
  tree.level.assign(8, 1);
  tree.cls.assign(8, LeafClass::kInterior);
  tree.owner.assign(8, 7);
  LinearOctree own;
  own.key = {tree.key[3]};
  set_leaf_owners(Comm::world(), own, {}, RootCube{}, tree);
  EXPECT_EQ(tree.owner, std::vector<int32_t>(8, 0));
}

}  // namespace
}  // namespace partet
