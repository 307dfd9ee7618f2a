// The octree's grading radius (balance.hpp): the closure against a naive
// split-until-graded reference on random trees, is_graded against brute
// force, the plain rule at radius 1, and the size held around a deep leaf.
#include <gtest/gtest.h>

#include <algorithm>

#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/neighbours.hpp"
#include "octree_test_util.hpp"

namespace partet {
namespace {

using test::grid_box;
using test::random_tree;

// The first leaf (the coarser of a pair) that breaks grading radius r >= 2:
// a leaf more than one level coarser than some leaf i whose box meets the
// block of i's parent grown by r parent edges, or kNoLeaf.
size_t first_violation(const LinearOctree& t, int r) {
  for (size_t i = 0; i < t.size(); ++i) {
    if (t.level[i] < 2) continue;
    const auto b = grid_box(t, i);
    const int64_t w = 2 * b.edge;  // the parent's edge
    int64_t lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = b.lo[k] / w * w - r * w;
      hi[k] = b.lo[k] / w * w + w + r * w;
    }
    for (size_t j = 0; j < t.size(); ++j) {
      if (t.level[j] + 1 >= t.level[i]) continue;
      const auto c = grid_box(t, j);
      bool meets = true;
      for (int k = 0; k < 3; ++k) meets = meets && std::max(lo[k], c.lo[k]) < std::min(hi[k], c.lo[k] + c.edge);
      if (meets) return j;
    }
  }
  return kNoLeaf;
}

void reference_grading(LinearOctree& t, int r) {
  for (size_t coarse = first_violation(t, r); coarse != kNoLeaf; coarse = first_violation(t, r))
    refine_octree(t, {{t.key[coarse], static_cast<uint8_t>(t.level[coarse] + 1)}});
}

TEST(Grading, ClosureMatchesNaiveReference) {
  int ungraded = 0;
  for (int r = 2; r <= 3; ++r)
    for (uint32_t seed = 1; seed <= 6; ++seed) {
      SCOPED_TRACE(testing::Message() << "radius " << r << " seed " << seed);
      const LinearOctree input = random_tree(seed, seed % 3 + 2, 6);
      ungraded += first_violation(input, r) != kNoLeaf;
      LinearOctree fast = input;
      balance_octree(fast, r);
      EXPECT_EQ(first_violation(fast, r), kNoLeaf);
      EXPECT_TRUE(is_graded(fast, r));
      EXPECT_TRUE(is_balanced(fast));
      LinearOctree slow = input;
      reference_grading(slow, r);
      EXPECT_EQ(fast.key, slow.key);
      EXPECT_EQ(fast.level, slow.level);
      const LinearOctree again = fast;
      balance_octree(fast, r);
      EXPECT_EQ(fast.key, again.key);
    }
  EXPECT_GE(ungraded, 10);
}

TEST(Grading, IsGradedAgreesWithBruteForce) {
  for (uint32_t seed = 11; seed <= 16; ++seed)
    for (int r = 2; r <= 3; ++r) {
      LinearOctree t = random_tree(seed, 6, 6);
      balance_octree(t);  // plain 2:1: mostly not graded at r
      EXPECT_EQ(is_graded(t, r), first_violation(t, r) == kNoLeaf) << seed << " " << r;
      balance_octree(t, r);
      EXPECT_TRUE(is_graded(t, r)) << seed << " " << r;
    }
}

TEST(Grading, RadiusOneIsThePlainBalance) {
  for (uint32_t seed = 21; seed <= 24; ++seed) {
    LinearOctree plain = random_tree(seed, 30, 8), graded = plain;
    balance_octree(plain);
    balance_octree(graded, 1);
    EXPECT_EQ(plain.key, graded.key);
    EXPECT_EQ(plain.level, graded.level);
    EXPECT_EQ(is_graded(plain, 1), is_balanced(plain));
  }
}

// From one leaf of level 9 at the root's centre, along +x: the levels fall
// away from it, each size of levels 4 to 8 holds for at least `r` leaves
// before the next (plain balance: at least one), and a wider radius never
// makes fewer leaves.
TEST(Grading, SizesHoldForTheRadius) {
  const uint32_t c = kGridSize / 2;
  size_t previous = 0;
  for (int r = 1; r <= kMaxGrading; ++r) {
    SCOPED_TRACE(testing::Message() << "radius " << r);
    LinearOctree t = build_octree({c, c, c}, {9});
    balance_octree(t, r);
    EXPECT_TRUE(is_graded(t, r));
    EXPECT_GE(t.size(), previous);
    previous = t.size();
    std::vector<int> count(kMaxLevel + 1, 0);
    int last = kMaxLevel + 1;
    for (uint32_t x = c; x < kGridSize;) {
      const int level = t.level[t.locate(x, c, c)];
      EXPECT_LE(level, last);
      last = level;
      ++count[level];
      x += octant_edge(level);
    }
    EXPECT_EQ(count[9], 2);
    for (int level = 4; level <= 8; ++level) EXPECT_GE(count[level], r) << "level " << level;
  }
}

}  // namespace
}  // namespace partet
