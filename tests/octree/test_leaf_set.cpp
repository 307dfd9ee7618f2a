// LeafSet against a plain vector of flags, and range queries restricted to
// a LeafSet against the unrestricted query's leaves that are members.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "octree/leaf_set.hpp"
#include "octree/range_query.hpp"
#include "octree_test_util.hpp"

namespace partet {
namespace {

using test::random_tree;

// Members drawn as runs (the front's leaves come in runs along the
// surface) at the given density, plus scattered singles.
std::vector<uint8_t> random_members(std::mt19937& rng, size_t n, double density) {
  std::vector<uint8_t> member(n, 0);
  std::uniform_int_distribution<size_t> at(0, n - 1), run(1, 300);
  std::bernoulli_distribution single(density / 4);
  for (size_t covered = 0; covered < density * static_cast<double>(n);) {
    const size_t b = at(rng), len = run(rng);
    for (size_t i = b; i < std::min(n, b + len); ++i) member[i] = 1;
    covered += len;
  }
  for (size_t i = 0; i < n; ++i) member[i] |= single(rng) ? 1 : 0;
  return member;
}

TEST(LeafSet, AnyAndForEachMatchFlags) {
  std::mt19937 rng(11);
  for (size_t n : {1, 63, 64, 65, 4095, 4096, 4097, 20000, 300000}) {
    for (double density : {0.0, 0.001, 0.05, 0.6}) {
      const std::vector<uint8_t> member = random_members(rng, n, density);
      LeafSet set(n);
      for (size_t i = 0; i < n; ++i)
        if (member[i]) set.insert(i);
      for (size_t i = 0; i < n; ++i) ASSERT_EQ(set.contains(i), member[i] != 0) << n << " " << i;
      std::uniform_int_distribution<size_t> at(0, n);
      for (int k = 0; k < 200; ++k) {
        size_t b = at(rng), e = at(rng);
        if (k % 4 == 0) e = std::min(n, b + k);  // short ranges too
        if (b > e) std::swap(b, e);
        std::vector<size_t> want;
        for (size_t i = b; i < e; ++i)
          if (member[i]) want.push_back(i);
        std::vector<size_t> got;
        set.for_each(b, e, [&](size_t i) { got.push_back(i); });
        ASSERT_EQ(got, want) << "n " << n << " range [" << b << ", " << e << ")";
        ASSERT_EQ(set.any(b, e), !want.empty()) << "n " << n << " range [" << b << ", " << e << ")";
      }
    }
  }
}

TEST(LeafSet, RestrictedRangeQueryKeepsTheMembersInOrder) {
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const LinearOctree t = random_tree(seed, 600, 9);
    ASSERT_GT(t.size(), 8192u) << "the summary bits span several words";
    const LeafRangeQuery q(t);
    std::mt19937 rng(seed);
    for (double density : {0.0, 0.01, 0.2, 1.0}) {
      const std::vector<uint8_t> member = random_members(rng, t.size(), density);
      LeafSet set(t.size());
      for (size_t i = 0; i < t.size(); ++i)
        if (member[i]) set.insert(i);
      std::vector<size_t> all, got;
      for (int k = 0; k < 200; ++k) {
        uint32_t lo[3], hi[3];
        test::random_grid_box(rng, k % 3 == 0, lo, hi);
        q.leaves_in_range(lo, hi, all);
        q.leaves_in_range(lo, hi, got, set);
        std::vector<size_t> want;
        for (size_t leaf : all)
          if (member[leaf]) want.push_back(leaf);
        ASSERT_EQ(got, want) << "seed " << seed << " density " << density << " query " << k;
      }
    }
  }
}

}  // namespace
}  // namespace partet
