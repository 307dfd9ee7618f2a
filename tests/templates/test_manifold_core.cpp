// The manifold pass over the interior leaves (templates/manifold_core.hpp).
// The occupancy table agrees, for all 256 octant masks around a point, with
// the topology of the templated core's exposed faces. Hand-made sets (two
// leaves sharing only an edge or a corner, a checkerboard, leaves of two
// levels touching along part of an edge, across a face centre, at a corner)
// and random balanced trees with random interior sets come out with a
// closed 2-manifold core boundary: every front edge used by exactly two
// faces in opposite directions, no pinched vertex. The pass only demotes
// interior leaves to too close, the core still conforms exactly
// (template_trees.hpp), and a second pass changes nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "front/initial_front.hpp"
#include "front_topology.hpp"
#include "template_trees.hpp"
#include "templates/manifold_core.hpp"

namespace partet::test {
namespace {

// Interior where `interior` says so (and away from the root's far faces),
// outside elsewhere.
LinearOctree tree_with_interior(const std::vector<Cell>& cells,
                                const std::function<bool(const Cell&)>& interior) {
  return make_tree(cells, [&](const Cell& c) {
    return interior(c) && !touches_far_root(c) ? LeafClass::kInterior : LeafClass::kOutside;
  });
}

// The core sheet of the initial front (no surface).
FrontTopology core_topology(const LinearOctree& tree) {
  const TemplateCore core = template_interior(tree, unit_root());
  return front_topology(make_initial_front(tree, unit_root(), core, SurfaceMesh{}).faces);
}

// Runs the pass and checks what must hold for any tree: only interior
// leaves are demoted, to too close, as counted; the core conforms and its
// boundary is a closed 2-manifold; a second pass changes nothing.
ManifoldCoreCounts check_pass(LinearOctree& tree, const std::string& label) {
  const std::vector<LeafClass> before = tree.cls;
  const ManifoldCoreCounts counts = make_core_manifold(tree);
  size_t demoted = 0, interior = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    interior += tree.cls[i] == LeafClass::kInterior;
    if (tree.cls[i] == before[i]) continue;
    ++demoted;
    EXPECT_EQ(before[i], LeafClass::kInterior) << label << ": leaf " << i;
    EXPECT_EQ(tree.cls[i], LeafClass::kTooClose) << label << ": leaf " << i;
  }
  EXPECT_EQ(counts.demoted, demoted) << label;
  EXPECT_EQ(counts.interior, interior) << label;
  EXPECT_LE(counts.repaired, counts.demoted) << label;
  EXPECT_LE(counts.rounds, counts.repaired) << label;

  const TemplateCore core = template_interior(tree, unit_root());
  const CoreFacts facts = expect_core_conforms(tree, core, label);
  EXPECT_EQ(facts.non_manifold_edges, 0u) << label;
  const FrontTopology t =
      front_topology(make_initial_front(tree, unit_root(), core, SurfaceMesh{}).faces);
  EXPECT_EQ(t.bad_edges, 0u) << label;
  EXPECT_EQ(t.pinched, 0u) << label;
  EXPECT_EQ(t.faces, facts.boundary_faces) << label;

  const std::vector<LeafClass> after = tree.cls;
  const ManifoldCoreCounts again = make_core_manifold(tree);
  EXPECT_EQ(again.demoted, 0u) << label;
  EXPECT_EQ(again.rounds, 0u) << label;
  EXPECT_EQ(again.interior, interior) << label;
  EXPECT_TRUE(tree.cls == after) << label;
  return counts;
}

// The class of the level-l leaf with anchor (x, y, z) in units of its edge.
LeafClass class_at(const LinearOctree& tree, uint32_t x, uint32_t y, uint32_t z, int level) {
  const uint32_t h = octant_edge(level);
  const size_t i = tree.locate(x * h, y * h, z * h);
  EXPECT_EQ(tree.level[i], level);
  return tree.cls[i];
}

TEST(ManifoldCore, OccupancyTableMatchesTheCore) {
  // The 8 level-2 cells around the point (1/2, 1/2, 1/2): octant o is the
  // cell (1 + o_x, 1 + o_y, 1 + o_z).
  const uint32_t h = octant_edge(2);
  size_t manifold_masks = 0;
  for (unsigned mask = 0; mask < 256; ++mask) {
    LinearOctree tree = tree_with_interior(uniform_cells(2), [&](const Cell& c) {
      unsigned o = 0;
      for (int k = 0; k < 3; ++k) {
        const uint32_t x = c.a[k] / h;
        if (x < 1 || x > 2) return false;
        o |= (x - 1) << k;
      }
      return (mask >> o & 1) != 0;
    });
    const std::string label = "mask " + std::to_string(mask);
    const bool manifold = core_topology(tree).manifold();
    EXPECT_EQ(manifold_occupancy(mask), manifold) << label;
    manifold_masks += manifold;
    const ManifoldCoreCounts counts = check_pass(tree, label);
    EXPECT_EQ(counts.demoted == 0, manifold) << label;
  }
  std::printf("manifold octant masks: %zu of 256\n", manifold_masks);
  EXPECT_EQ(manifold_occupancy(0x81), false);  // two opposite octants
  EXPECT_EQ(manifold_occupancy(0x03), true);   // two octants sharing a face
}

TEST(ManifoldCore, TwoLeavesSharingOnlyAnEdge) {
  LinearOctree tree = tree_with_interior(uniform_cells(3), [](const Cell& c) {
    const uint32_t h = cell_edge(c);
    return (c.a[0] == 2 * h && c.a[1] == 2 * h && c.a[2] == 2 * h) ||
           (c.a[0] == 3 * h && c.a[1] == 3 * h && c.a[2] == 2 * h);
  });
  const FrontTopology before = core_topology(tree);
  EXPECT_GT(before.bad_edges, 0u);
  const ManifoldCoreCounts counts = check_pass(tree, "edge");
  EXPECT_EQ(counts.demoted, 1u);
  EXPECT_EQ(counts.interior, 1u);
}

TEST(ManifoldCore, TwoLeavesSharingOnlyACorner) {
  LinearOctree tree = tree_with_interior(uniform_cells(3), [](const Cell& c) {
    const uint32_t h = cell_edge(c);
    return (c.a[0] == 2 * h && c.a[1] == 2 * h && c.a[2] == 2 * h) ||
           (c.a[0] == 3 * h && c.a[1] == 3 * h && c.a[2] == 3 * h);
  });
  const FrontTopology before = core_topology(tree);
  EXPECT_EQ(before.bad_edges, 0u);
  EXPECT_EQ(before.pinched, 1u);
  const ManifoldCoreCounts counts = check_pass(tree, "corner");
  EXPECT_EQ(counts.demoted, 1u);
  EXPECT_EQ(counts.repaired, 1u);
  EXPECT_EQ(counts.interior, 1u);
}

TEST(ManifoldCore, Checkerboard) {
  // Level-3 cells 1..6 on each axis with an even coordinate sum: every two
  // of them touch along an edge or not at all.
  LinearOctree tree = tree_with_interior(uniform_cells(3), [](const Cell& c) {
    const uint32_t h = cell_edge(c);
    uint32_t sum = 0;
    for (int k = 0; k < 3; ++k) {
      if (c.a[k] < h || c.a[k] > 6 * h) return false;
      sum += c.a[k] / h;
    }
    return sum % 2 == 0;
  });
  const FrontTopology before = core_topology(tree);
  EXPECT_GT(before.bad_edges, 0u);
  const ManifoldCoreCounts counts = check_pass(tree, "checkerboard");
  EXPECT_GT(counts.demoted, 0u);
  EXPECT_GT(counts.interior, 0u);
  EXPECT_EQ(counts.demoted + counts.interior, 108u);
  // What is left touches along no edge: no two kept cells one step apart
  // along two axes.
  for (uint32_t x = 1; x < 6; ++x)
    for (uint32_t y = 1; y < 6; ++y)
      for (uint32_t z = 1; z <= 6; ++z) {
        const bool a = class_at(tree, x, y, z, 3) == LeafClass::kInterior;
        const bool b = class_at(tree, x + 1, y + 1, z, 3) == LeafClass::kInterior;
        EXPECT_FALSE(a && b) << x << " " << y << " " << z;
      }
}

TEST(ManifoldCore, BoxOfLeavesIsLeftAlone) {
  LinearOctree tree = tree_with_interior(uniform_cells(3), [](const Cell& c) {
    const uint32_t h = cell_edge(c);
    return c.a[0] >= h && c.a[0] <= 5 * h && c.a[1] >= 2 * h && c.a[1] <= 4 * h && c.a[2] >= h &&
           c.a[2] <= 3 * h;
  });
  EXPECT_TRUE(core_topology(tree).manifold());
  const ManifoldCoreCounts counts = check_pass(tree, "box");
  EXPECT_EQ(counts.demoted, 0u);
  EXPECT_EQ(counts.rounds, 0u);
  EXPECT_EQ(counts.interior, 5u * 3u * 3u);
}

// A level-2 leaf B at cell (1, 1, 1) and level-3 leaves from the refined
// level-2 cell `fine` (cell units), interior where `child_interior` says
// (level-3 cell units).
using ChildPredicate = std::function<bool(uint32_t, uint32_t, uint32_t)>;
LinearOctree two_level_tree(const uint32_t* fine, const ChildPredicate& child_interior) {
  const uint32_t h2 = octant_edge(2), h3 = octant_edge(3);
  std::vector<Cell> cells = uniform_cells(2);
  refine(cells, static_cast<size_t>(find_cell(cells, fine[0] * h2, fine[1] * h2, fine[2] * h2, 2)));
  balance(cells);
  return tree_with_interior(cells, [&](const Cell& c) {
    if (c.level == 2) return c.a[0] == h2 && c.a[1] == h2 && c.a[2] == h2;
    return c.level == 3 && child_interior(c.a[0] / h3, c.a[1] / h3, c.a[2] / h3);
  });
}

TEST(ManifoldCore, MixedLevelsAlongPartOfAnEdge) {
  // B's edge x = y = 1/2, z in [1/4, 1/2]; the level-3 leaf at (4, 4, 2)
  // has the lower half of it as its own edge, in the opposite quadrant.
  const uint32_t fine[3] = {2, 2, 1};
  LinearOctree tree = two_level_tree(
      fine, [](uint32_t x, uint32_t y, uint32_t z) { return x == 4 && y == 4 && z == 2; });
  EXPECT_GT(core_topology(tree).bad_edges, 0u);
  const ManifoldCoreCounts counts = check_pass(tree, "part of an edge");
  EXPECT_EQ(counts.demoted, 1u);
  EXPECT_EQ(class_at(tree, 1, 1, 1, 2), LeafClass::kInterior);  // the larger leaf is kept
  EXPECT_EQ(class_at(tree, 4, 4, 2, 3), LeafClass::kTooClose);
}

TEST(ManifoldCore, MixedLevelsAcrossAFaceCentre) {
  // Across B's +x face, two level-3 leaves in opposite quadrants: each
  // shares a quarter of B's face, but they meet each other along an edge
  // only, leaving B's face centre with two opposite octants on the +x side.
  const uint32_t fine[3] = {2, 1, 1};
  LinearOctree tree = two_level_tree(fine, [](uint32_t x, uint32_t y, uint32_t z) {
    return x == 4 && ((y == 2 && z == 2) || (y == 3 && z == 3));
  });
  EXPECT_FALSE(core_topology(tree).manifold());
  const ManifoldCoreCounts counts = check_pass(tree, "face centre");
  EXPECT_EQ(counts.demoted, 1u);
  EXPECT_EQ(counts.interior, 2u);
  EXPECT_EQ(class_at(tree, 1, 1, 1, 2), LeafClass::kInterior);
}

TEST(ManifoldCore, MixedLevelsAtACorner) {
  const uint32_t fine[3] = {2, 2, 2};
  LinearOctree tree = two_level_tree(
      fine, [](uint32_t x, uint32_t y, uint32_t z) { return x == 4 && y == 4 && z == 4; });
  EXPECT_EQ(core_topology(tree).pinched, 1u);
  const ManifoldCoreCounts counts = check_pass(tree, "mixed corner");
  EXPECT_EQ(counts.demoted, 1u);
  EXPECT_EQ(class_at(tree, 1, 1, 1, 2), LeafClass::kInterior);
  EXPECT_EQ(class_at(tree, 4, 4, 4, 3), LeafClass::kTooClose);
}

// A random balanced tree: levels 2..deepest, refined at random leaves.
std::vector<Cell> random_cells(std::mt19937_64& rng, int deepest) {
  std::vector<Cell> cells = uniform_cells(2);
  const int refinements = std::uniform_int_distribution<int>(3, 40)(rng);
  for (int r = 0; r < refinements; ++r) {
    const size_t i = std::uniform_int_distribution<size_t>(0, cells.size() - 1)(rng);
    if (cells[i].level < deepest) refine(cells, i);
  }
  balance(cells);
  return cells;
}

TEST(ManifoldCore, RandomTreesBecomeManifold) {
  std::mt19937_64 rng(23);
  size_t demoted = 0, repaired = 0, untouched = 0, leaves = 0, max_rounds = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<Cell> cells = random_cells(rng, trial % 5 == 0 ? 6 : 5);
    // Interior sets: scattered leaves with probability p, or a noisy ball.
    const double p = std::uniform_real_distribution<double>(0.2, 0.95)(rng);
    const bool ball = trial % 3 == 2;
    std::uniform_real_distribution<double> unit(0, 1);
    const double centre[3] = {0.2 + 0.4 * unit(rng), 0.2 + 0.4 * unit(rng), 0.2 + 0.4 * unit(rng)};
    const double radius = 0.1 + 0.3 * unit(rng);
    LinearOctree tree = tree_with_interior(cells, [&](const Cell& c) {
      const double draw = unit(rng);
      if (!ball) return draw < p;
      double d2 = 0;
      for (int k = 0; k < 3; ++k) {
        const double x = (c.a[k] + 0.5 * cell_edge(c)) / kGridSize - centre[k];
        d2 += x * x;
      }
      return d2 < radius * radius && draw < 0.97;
    });
    const ManifoldCoreCounts counts = check_pass(tree, "trial " + std::to_string(trial));
    demoted += counts.demoted;
    repaired += counts.repaired;
    untouched += counts.demoted == 0;
    leaves += tree.size();
    max_rounds = std::max(max_rounds, counts.rounds);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("random trees: %zu leaves, %zu repairs, %zu demoted, %zu trees untouched, "
              "at most %zu rounds\n",
              leaves, repaired, demoted, untouched, max_rounds);
  EXPECT_GT(demoted, 1000u);
  EXPECT_GT(untouched, 0u);
}

TEST(ManifoldCore, Deterministic) {
  std::mt19937_64 rng(3);
  const std::vector<Cell> cells = random_cells(rng, 5);
  std::vector<char> draws;
  LinearOctree a = tree_with_interior(cells, [&](const Cell&) {
    draws.push_back(std::uniform_real_distribution<double>(0, 1)(rng) < 0.6);
    return draws.back() != 0;
  });
  LinearOctree b = a;
  const ManifoldCoreCounts ca = make_core_manifold(a);
  const ManifoldCoreCounts cb = make_core_manifold(b);
  EXPECT_GT(ca.demoted, 0u);
  EXPECT_EQ(ca.demoted, cb.demoted);
  EXPECT_TRUE(a.cls == b.cls);
}

}  // namespace
}  // namespace partet::test
