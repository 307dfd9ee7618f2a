// Octree conventions and queries: Morton keys, locate on a hand-made tree,
// octant boxes, range queries and neighbour queries against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "octree/neighbours.hpp"
#include "octree/octree.hpp"
#include "octree/range_query.hpp"
#include "octree_test_util.hpp"

namespace partet {
namespace {

using test::contact_dimension;
using test::grid_box;
using test::random_tree;

TEST(OctreeMorton, RoundTripAndOrder) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<uint32_t> coord(0, (1u << 21) - 1);
  for (int k = 0; k < 10000; ++k) {
    const uint32_t x = coord(rng), y = coord(rng), z = coord(rng);
    uint32_t a, b, c;
    morton_decode(morton_key(x, y, z), a, b, c);
    EXPECT_EQ(a, x);
    EXPECT_EQ(b, y);
    EXPECT_EQ(c, z);
  }
  EXPECT_EQ(morton_key(1, 0, 0), 1u);
  EXPECT_EQ(morton_key(0, 1, 0), 2u);
  EXPECT_EQ(morton_key(0, 0, 1), 4u);
  EXPECT_EQ(morton_key(2, 0, 0), 8u);
  // Children of an octant in child order c = x | y << 1 | z << 2 have keys
  // key + c * span.
  const int level = 5;
  const uint32_t h = octant_edge(level + 1);
  const uint64_t parent = morton_key(3 * 2 * h, 5 * 2 * h, 1 * 2 * h);
  for (uint32_t c = 0; c < 8; ++c) {
    const uint64_t child = morton_key(3 * 2 * h + ((c & 1) ? h : 0), 5 * 2 * h + ((c & 2) ? h : 0),
                                      1 * 2 * h + ((c & 4) ? h : 0));
    EXPECT_EQ(child, parent + c * octant_key_span(level + 1));
  }
}

// Root split once, child 0 split once more, child 7 of that split again:
// 7 + 7 + 8 = 22 leaves.
LinearOctree hand_made_tree() {
  LinearOctree t;
  auto add = [&](uint32_t x, uint32_t y, uint32_t z, int level) {
    t.key.push_back(morton_key(x, y, z));
    t.level.push_back(static_cast<uint8_t>(level));
  };
  const uint32_t h1 = octant_edge(1), h2 = octant_edge(2), h3 = octant_edge(3);
  for (uint32_t c = 0; c < 8; ++c) {
    const uint32_t x = (c & 1) ? h1 : 0, y = (c & 2) ? h1 : 0, z = (c & 4) ? h1 : 0;
    if (c != 0) {
      add(x, y, z, 1);
      continue;
    }
    for (uint32_t d = 0; d < 8; ++d) {
      const uint32_t x2 = (d & 1) ? h2 : 0, y2 = (d & 2) ? h2 : 0, z2 = (d & 4) ? h2 : 0;
      if (d != 7) {
        add(x2, y2, z2, 2);
        continue;
      }
      for (uint32_t e = 0; e < 8; ++e) add(x2 + ((e & 1) ? h3 : 0), y2 + ((e & 2) ? h3 : 0), z2 + ((e & 4) ? h3 : 0), 3);
    }
  }
  t.cls.assign(t.key.size(), LeafClass::kUnclassified);
  t.owner.assign(t.key.size(), 0);
  return t;
}

TEST(OctreeLocate, HandMadeTree) {
  const LinearOctree t = hand_made_tree();
  ASSERT_EQ(t.size(), 22u);
  EXPECT_TRUE(std::is_sorted(t.key.begin(), t.key.end()));
  const uint32_t h1 = octant_edge(1), h2 = octant_edge(2), h3 = octant_edge(3);
  // The grid corner is in the first level-2 leaf.
  EXPECT_EQ(t.locate(0, 0, 0), 0u);
  EXPECT_EQ(t.level[t.locate(h2 - 1, h2 - 1, h2 - 1)], 2);
  // The level-3 leaves fill [h2, h1)^3.
  const size_t deep = t.locate(h2, h2, h2);
  EXPECT_EQ(t.level[deep], 3);
  EXPECT_EQ(t.key[deep], morton_key(h2, h2, h2));
  EXPECT_EQ(t.locate(h2 + h3, h2 + h3, h2 + h3), deep + 7);
  EXPECT_EQ(t.locate(h1 - 1, h1 - 1, h1 - 1), deep + 7);
  // The far corner is in the last leaf.
  EXPECT_EQ(t.locate(kGridSize - 1, kGridSize - 1, kGridSize - 1), t.size() - 1);
  // Every anchor locates to its own leaf; every last cell too.
  for (size_t i = 0; i < t.size(); ++i) {
    uint32_t a[3];
    t.anchor(i, a[0], a[1], a[2]);
    const uint32_t e = octant_edge(t.level[i]) - 1;
    EXPECT_EQ(t.locate(a[0], a[1], a[2]), i);
    EXPECT_EQ(t.locate(a[0] + e, a[1] + e, a[2] + e), i);
    LeafRangeQuery q(t);
    EXPECT_EQ(q.locate(a[0] + e, a[1], a[2] + e), i);
  }
}

TEST(OctreeBox, CornersAreExactLatticePoints) {
  double bbox[6] = {-1.3, 0.2, 5.0, 2.7, 1.1, 6.5};
  const RootCube root = make_root_cube(bbox);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(root.origin[i], bbox[i]);
    EXPECT_GT(root.origin[i] + root.edge(), bbox[3 + i]);
  }
  double lo[3], hi[3];
  octant_box(root, 0, 0, 0, 0, lo, hi);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(lo[i], root.origin[i]);
    EXPECT_EQ(hi[i] - lo[i], root.edge());
  }
  const uint32_t h = octant_edge(20);
  octant_box(root, 12345, 777, 99, 20, lo, hi);
  EXPECT_EQ(hi[0] - lo[0], root.unit * h);
  EXPECT_EQ((lo[0] - root.origin[0]) / root.unit, 12345.0);
  EXPECT_EQ((lo[2] - root.origin[2]) / root.unit, 99.0);
}

TEST(OctreeRangeQuery, MatchesBruteForce) {
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    const LinearOctree t = random_tree(seed, 60, 7);
    const LeafRangeQuery q(t);
    std::mt19937 rng(seed);
    std::vector<size_t> got;
    for (int k = 0; k < 300; ++k) {
      uint32_t lo[3], hi[3];
      test::random_grid_box(rng, k % 3 == 0, lo, hi);
      q.leaves_in_range(lo, hi, got);
      std::vector<size_t> want;
      for (size_t i = 0; i < t.size(); ++i) {
        const auto b = grid_box(t, i);
        bool overlap = true;
        for (int a = 0; a < 3; ++a) overlap = overlap && b.lo[a] <= hi[a] && b.lo[a] + b.edge - 1 >= lo[a];
        if (overlap) want.push_back(i);
      }
      ASSERT_EQ(got, want) << "seed " << seed << " query " << k;
    }
  }
}

TEST(OctreeNeighbours, EdgeNumbering) {
  // Edge e runs along axis e / 4 between corners that differ on that axis
  // only; each corner is on 3 edges.
  int on[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (int e = 0; e < kEdgeCount; ++e) {
    int c0, c1;
    edge_corners(e, c0, c1);
    EXPECT_EQ(c1 ^ c0, 1 << (e / 4));
    EXPECT_LT(c0, c1);
    ++on[c0];
    ++on[c1];
  }
  for (int c = 0; c < 8; ++c) EXPECT_EQ(on[c], 3);
  int c0, c1;
  edge_corners(3, c0, c1);  // along x at high y and high z
  EXPECT_EQ(c0, 6);
  edge_corners(9, c0, c1);  // along z at high x, low y
  EXPECT_EQ(c0, 1);
  edge_corners(5, c0, c1);  // along y at high z, low x
  EXPECT_EQ(c0, 4);
}

TEST(OctreeNeighbours, FacesAndEdgesMatchBruteForce) {
  for (uint32_t seed = 11; seed <= 14; ++seed) {
    const LinearOctree t = random_tree(seed, 25, 6);
    std::vector<size_t> got;
    for (size_t i = 0; i < t.size(); ++i) {
      const auto bi = grid_box(t, i);
      for (int f = 0; f < kFaceCount; ++f) {
        const int axis = f / 2;
        got.clear();
        append_face_neighbours(t, i, f, got);
        std::sort(got.begin(), got.end());
        std::vector<size_t> want;
        for (size_t j = 0; j < t.size(); ++j) {
          const auto bj = grid_box(t, j);
          if (contact_dimension(bi, bj) != 2) continue;
          const bool across = (f & 1) ? bj.lo[axis] == bi.lo[axis] + bi.edge : bj.lo[axis] + bj.edge == bi.lo[axis];
          if (across) want.push_back(j);
        }
        ASSERT_EQ(got, want) << "leaf " << i << " face " << f;
      }
      for (int e = 0; e < kEdgeCount; ++e) {
        const int axis = e / 4;
        int c0, c1;
        edge_corners(e, c0, c1);
        // The edge as a grid segment.
        int64_t p[3];
        for (int k = 0; k < 3; ++k) p[k] = bi.lo[k] + ((c0 >> k & 1) ? bi.edge : 0);
        bool finer = false;
        for (size_t j = 0; j < t.size(); ++j) {
          if (j == i) continue;
          const auto bj = grid_box(t, j);
          bool shares = true;
          for (int k = 0; k < 3; ++k) {
            if (k == axis) {
              shares = shares && std::max(bj.lo[k], p[k]) < std::min(bj.lo[k] + bj.edge, p[k] + bi.edge);
            } else {
              shares = shares && bj.lo[k] <= p[k] && p[k] <= bj.lo[k] + bj.edge;
            }
          }
          finer = finer || (shares && t.level[j] > t.level[i]);
        }
        ASSERT_EQ(edge_has_finer_leaf(t, i, e), finer) << "leaf " << i << " edge " << e;
      }
    }
  }
}

}  // namespace
}  // namespace partet
