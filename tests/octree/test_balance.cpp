// 2:1 balance across faces and edges: brute force over all pairs of leaves
// on small random trees, agreement with a naive split-until-balanced
// reference (the minimal balanced refinement is unique), the neighbour
// queries on balanced trees, and corpus surfaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/neighbours.hpp"
#include "octree/sizing.hpp"
#include "octree_test_util.hpp"
#include "surface/diagnose.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::contact_dimension;
using test::data_path;
using test::grid_box;
using test::random_tree;

// Some pair of leaves sharing a face or a positive length of an edge differs
// by more than one level: the coarser one of the first such pair (or
// kNoLeaf).
size_t first_violation(const LinearOctree& t) {
  std::vector<test::GridBox> boxes;
  for (size_t i = 0; i < t.size(); ++i) boxes.push_back(grid_box(t, i));
  for (size_t i = 0; i < t.size(); ++i)
    for (size_t j = i + 1; j < t.size(); ++j) {
      if (std::abs(int(t.level[i]) - int(t.level[j])) <= 1) continue;
      if (contact_dimension(boxes[i], boxes[j]) >= 1) return t.level[i] < t.level[j] ? i : j;
    }
  return kNoLeaf;
}

// The paper's procedure, naively: split a too-coarse leaf until none is left.
void reference_balance(LinearOctree& t) {
  for (size_t coarse = first_violation(t); coarse != kNoLeaf; coarse = first_violation(t))
    refine_octree(t, {{t.key[coarse], static_cast<uint8_t>(t.level[coarse] + 1)}});
}

TEST(BalanceRandom, MatchesNaiveReferenceAndBruteForce) {
  int unbalanced = 0;
  for (uint32_t seed = 1; seed <= 10; ++seed) {
    const LinearOctree input = random_tree(seed, seed % 3 + 2, 7);
    unbalanced += first_violation(input) != kNoLeaf;
    LinearOctree fast = input;
    balance_octree(fast);
    EXPECT_EQ(first_violation(fast), kNoLeaf) << seed;
    EXPECT_TRUE(is_balanced(fast));
    LinearOctree slow = input;
    reference_balance(slow);
    EXPECT_EQ(fast.key, slow.key) << seed;
    EXPECT_EQ(fast.level, slow.level) << seed;
    // Only refined: each new leaf lies in an input leaf no finer than it.
    for (size_t i = 0; i < fast.size(); ++i) {
      uint32_t x, y, z;
      fast.anchor(i, x, y, z);
      EXPECT_GE(fast.level[i], input.level[input.locate(x, y, z)]);
    }
  }
  EXPECT_GE(unbalanced, 8);
}

TEST(BalanceRandom, BruteForceOnLargerTrees) {
  for (uint32_t seed = 31; seed <= 34; ++seed) {
    LinearOctree t = random_tree(seed, 40, 9);
    const bool was_balanced = first_violation(t) == kNoLeaf;
    EXPECT_EQ(is_balanced(t), was_balanced);
    balance_octree(t);
    EXPECT_EQ(first_violation(t), kNoLeaf) << seed;
    EXPECT_TRUE(is_balanced(t));
    // Idempotent.
    const LinearOctree again = t;
    balance_octree(t);
    EXPECT_EQ(t.key, again.key);
    EXPECT_EQ(t.level, again.level);
  }
}

TEST(BalanceRandom, EdgeOnlyViolationIsFixed) {
  // Two octants that share only an edge: a deep leaf next to the edge
  // x = y = h1 of a level-1 leaf across the diagonal.
  const uint32_t h1 = octant_edge(1);
  LinearOctree t = build_octree({h1 - 1, h1 - 1, 5}, {6});
  // The level-1 leaf at (h1, h1, 0) shares the edge with the deep leaves.
  EXPECT_FALSE(is_balanced(t));
  balance_octree(t);
  EXPECT_TRUE(is_balanced(t));
  EXPECT_EQ(first_violation(t), kNoLeaf);
  const size_t diagonal = t.locate(h1, h1, 0);
  EXPECT_GE(t.level[diagonal], 5);
}

TEST(BalanceNeighbours, FaceNeighboursOnBalancedTrees) {
  for (uint32_t seed = 41; seed <= 43; ++seed) {
    LinearOctree t = random_tree(seed, 20, 7);
    balance_octree(t);
    std::vector<size_t> general;
    for (size_t i = 0; i < t.size(); ++i)
      for (int f = 0; f < kFaceCount; ++f) {
        size_t out[4];
        const int n = face_neighbours(t, i, f, out);
        general.clear();
        append_face_neighbours(t, i, f, general);
        std::sort(general.begin(), general.end());
        ASSERT_EQ(static_cast<size_t>(n), general.size());
        ASSERT_TRUE(n == 0 || n == 1 || n == 4);
        std::vector<size_t> sorted(out, out + n);
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(sorted, general);
        for (int k = 0; k < n; ++k) EXPECT_LE(std::abs(int(t.level[out[k]]) - int(t.level[i])), 1);
        if (n != 4) continue;
        // out[q] lies across quadrant q: upper half along u = (axis + 1) % 3
        // iff bit 0, along v = (axis + 2) % 3 iff bit 1.
        const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
        const auto bi = grid_box(t, i);
        for (int q = 0; q < 4; ++q) {
          const auto bq = grid_box(t, out[q]);
          EXPECT_EQ(bq.lo[u], bi.lo[u] + ((q & 1) ? bi.edge / 2 : 0));
          EXPECT_EQ(bq.lo[v], bi.lo[v] + ((q & 2) ? bi.edge / 2 : 0));
        }
      }
  }
}

TEST(BalanceCorpus, SurfacesTreesAreBalanced) {
  for (const auto& entry : std::filesystem::directory_iterator(data_path("good"))) {
    SCOPED_TRACE(entry.path().string());
    SurfaceMesh s = read_surface_file(entry.path().string());
    const SurfaceSummary sum = diagnose_surface(s, entry.path().string());
    const RootCube root = make_root_cube(sum.bbox);
    const VertexSizing sizes = size_vertices(s, root, {});
    LinearOctree t = build_octree(sizes.grid, sizes.level);
    refine_for_triangles(t, s, root, sizes.level);
    balance_octree(t);
    EXPECT_TRUE(is_balanced(t));
    if (t.size() < 3000) {
      EXPECT_EQ(first_violation(t), kNoLeaf);
    }
  }
}

}  // namespace
}  // namespace partet
