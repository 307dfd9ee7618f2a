// Every configuration 2:1 balance allows around a leaf, templated and
// checked exactly (template_trees.hpp). The centre leaf C is the level-2
// cell (1,1,1) of a uniform level-2 tree; its 6 face neighbours and 12 edge
// neighbours are each left alone or refined once (any mix is balanced:
// all cells are at level 2 or 3). The points of V on a face of C come only
// from the 9 cells around that face (the cell across it, the 4 face
// neighbours beside it, the 4 edge neighbours along its edges), and the
// points on an edge of C from the 3 cells around that edge, which are
// among them: so enumerating, for each face of C, all 2^9 refinements of
// its 9 cells visits every face and edge configuration of C. Then the
// cells across a face are made partly interior in every way, and a sample
// of joint configurations of all 18 neighbours with random interior sets
// covers the combinations.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "template_trees.hpp"
#include "templates/face_rule.hpp"

namespace partet::test {
namespace {

constexpr int kLevel = 2;
constexpr uint32_t kStep = 1u << (kMaxLevel - kLevel);  // edge of a level-2 cell

struct Offset {
  int d[3];
};

// The 18 face and edge neighbour offsets of C.
std::vector<Offset> neighbour_offsets() {
  std::vector<Offset> offsets;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        int nonzero = (x != 0) + (y != 0) + (z != 0);
        if (nonzero == 1 || nonzero == 2) offsets.push_back({{x, y, z}});
      }
  return offsets;
}

// The 9 offsets whose refinement can put points on face f of C.
std::vector<int> face_cells(const std::vector<Offset>& offsets, int f) {
  const int axis = f >> 1, sign = (f & 1) ? 1 : -1;
  std::vector<int> cells;
  for (size_t k = 0; k < offsets.size(); ++k) {
    const int* d = offsets[k].d;
    bool beside = d[axis] == 0 && (d[0] != 0) + (d[1] != 0) + (d[2] != 0) == 1;
    if (d[axis] == sign || beside) cells.push_back(static_cast<int>(k));
  }
  return cells;
}

// Whether a cell lies in the 3x3x3 block of level-2 cells around C.
bool in_block(const Cell& c) {
  return c.a[0] < 3 * kStep && c.a[1] < 3 * kStep && c.a[2] < 3 * kStep;
}

// The tree with the neighbours in `refined` split, and the block interior
// where `interior` says so (the rest of the tree outside).
LinearOctree configured_tree(const std::vector<Offset>& offsets, uint32_t refined,
                             const std::function<bool(const Cell&)>& interior) {
  std::vector<Cell> cells = uniform_cells(kLevel);
  for (size_t k = 0; k < offsets.size(); ++k) {
    if (!(refined >> k & 1)) continue;
    const int* d = offsets[k].d;
    long i = find_cell(cells, (1 + d[0]) * kStep, (1 + d[1]) * kStep, (1 + d[2]) * kStep, kLevel);
    refine(cells, static_cast<size_t>(i));
  }
  return make_tree(cells, [&](const Cell& c) {
    return in_block(c) && interior(c) ? LeafClass::kInterior : LeafClass::kOutside;
  });
}

std::string config_label(const char* what, int f, uint32_t refined, uint32_t extra) {
  return std::string(what) + " face " + std::to_string(f) + " refined " + std::to_string(refined) +
         " extra " + std::to_string(extra);
}

// The two layers of the block on either side of face f of C: C's layer
// and the layer across f, which hold the 9 cells around f.
std::function<bool(const Cell&)> slab(int f) {
  return [f](const Cell& c) {
    const int axis = f >> 1;
    const uint32_t layer = c.a[axis] / kStep;
    return layer == 1 || layer == ((f & 1) ? 2u : 0u);
  };
}

TEST(TemplatesEnumerate, EveryFaceAndEdgeConfigurationAllInterior) {
  // Interior: the slab of the 18 block cells on both sides of the face.
  const std::vector<Offset> offsets = neighbour_offsets();
  ASSERT_EQ(offsets.size(), 18u);
  const RootCube root = unit_root();
  size_t fanned_faces_of_c = 0;
  for (int f = 0; f < 6; ++f) {
    const std::vector<int> cells = face_cells(offsets, f);
    ASSERT_EQ(cells.size(), 9u);
    for (uint32_t pattern = 0; pattern < (1u << 9); ++pattern) {
      uint32_t refined = 0;
      for (int k = 0; k < 9; ++k)
        if (pattern >> k & 1) refined |= 1u << cells[k];
      LinearOctree tree = configured_tree(offsets, refined, slab(f));
      TemplateCore core = template_interior(tree, root);
      expect_core_conforms(tree, core, config_label("all interior", f, refined, 0));
      const size_t c = tree.locate(kStep, kStep, kStep);
      fanned_faces_of_c += core.face_case[6 * c + f] < kDiagonalCase;
      if (::testing::Test::HasFailure()) return;
    }
  }
  // Each of the 9 cells puts a point of V on f when refined (the cell
  // across: f's centre and midpoints; a cell beside f or along one of its
  // edges: that edge's midpoint), so f is diagonal in one pattern only.
  EXPECT_EQ(fanned_faces_of_c, 6u * 511u);
}

TEST(TemplatesEnumerate, CellAcrossAFacePartlyInterior) {
  const std::vector<Offset> offsets = neighbour_offsets();
  const RootCube root = unit_root();
  for (int f = 0; f < 6; ++f) {
    const int axis = f >> 1, sign = (f & 1) ? 1 : -1;
    // The cell across f, refined; its 8 children interior in every way; the
    // 4 edge neighbours along f refined or not.
    uint32_t across = 0, edges = 0;
    for (size_t k = 0; k < offsets.size(); ++k) {
      const int* d = offsets[k].d;
      int nonzero = (d[0] != 0) + (d[1] != 0) + (d[2] != 0);
      if (d[axis] == sign) (nonzero == 1 ? across : edges) |= 1u << k;
    }
    const std::function<bool(const Cell&)> in_slab = slab(f);
    uint32_t n[3] = {kStep, kStep, kStep};
    n[axis] = static_cast<uint32_t>(static_cast<int>(kStep) + sign * static_cast<int>(kStep));
    for (uint32_t children = 0; children < 256; ++children)
      for (uint32_t refined : {across, across | edges}) {
        auto interior = [&](const Cell& c) {
          if (!in_slab(c)) return false;
          if (c.level == kLevel) return true;
          if (c.a[0] / kStep != n[0] / kStep || c.a[1] / kStep != n[1] / kStep ||
              c.a[2] / kStep != n[2] / kStep)
            return true;
          uint32_t b = (c.a[0] - n[0]) / (kStep / 2) | (c.a[1] - n[1]) / (kStep / 2) << 1 |
                       (c.a[2] - n[2]) / (kStep / 2) << 2;
          return (children >> b & 1) != 0;
        };
        LinearOctree tree = configured_tree(offsets, refined, interior);
        TemplateCore core = template_interior(tree, root);
        expect_core_conforms(tree, core, config_label("partly interior", f, refined, children));
        if (::testing::Test::HasFailure()) return;
      }
  }
}

TEST(TemplatesEnumerate, JointConfigurationsWithRandomInteriorSets) {
  const std::vector<Offset> offsets = neighbour_offsets();
  const RootCube root = unit_root();
  std::mt19937_64 rng(20240601);
  for (int sample = 0; sample < 1000; ++sample) {
    const uint32_t refined = static_cast<uint32_t>(rng()) & ((1u << 18) - 1);
    const double p = sample % 3 == 0 ? 1.0 : sample % 3 == 1 ? 0.8 : 0.5;
    // One draw per level-3 cell position and level.
    std::vector<char> draws(2 * 512);
    for (char& d : draws) d = std::uniform_real_distribution<double>(0, 1)(rng) < p;
    auto interior = [&](const Cell& c) {
      const int shift = kMaxLevel - kLevel - 1;
      uint32_t cell = (c.a[0] >> shift) + 8 * ((c.a[1] >> shift) + 8 * (c.a[2] >> shift));
      return draws[cell * 2 + (c.level == kLevel)] != 0;
    };
    LinearOctree tree = configured_tree(offsets, refined, interior);
    TemplateCore core = template_interior(tree, root);
    expect_core_conforms(tree, core,
                         config_label("joint", -1, refined, static_cast<uint32_t>(sample)));
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace partet::test
