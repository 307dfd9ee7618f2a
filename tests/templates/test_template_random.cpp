// Template meshing of random 2:1 balanced trees (random refinement, then
// the brute-force balance of template_trees.hpp) with random interior sets
// (scattered leaves, balls, everything away from the root's far faces):
// the core conforms exactly (template_trees.hpp), its vertices are the
// lattice points the template promises, and the result is deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "check/quality.hpp"
#include "core/error.hpp"
#include "template_trees.hpp"
#include "templates/face_rule.hpp"
#include "templates/leaf_neighbourhood.hpp"

namespace partet::test {
namespace {

// A random balanced tree: levels 1..kDeepest, refined near random points.
std::vector<Cell> random_cells(std::mt19937_64& rng, int deepest) {
  std::vector<Cell> cells = uniform_cells(2);
  const int refinements = std::uniform_int_distribution<int>(3, 30)(rng);
  for (int r = 0; r < refinements; ++r) {
    size_t i = std::uniform_int_distribution<size_t>(0, cells.size() - 1)(rng);
    if (cells[i].level < deepest) refine(cells, i);
  }
  balance(cells);
  return cells;
}

// Interior sets: 0 scattered leaves, 1 a ball, 2 all leaves away from the far faces.
LeafClass random_class(const Cell& c, int mode, double p, const double* centre, double radius,
                       std::mt19937_64& rng) {
  if (touches_far_root(c)) return LeafClass::kOutside;
  const double draw = std::uniform_real_distribution<double>(0, 1)(rng);
  bool interior = false;
  if (mode == 0) interior = draw < p;
  if (mode == 1) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      double x = (c.a[k] + 0.5 * cell_edge(c)) / kGridSize - centre[k];
      d2 += x * x;
    }
    interior = d2 < radius * radius;
  }
  if (mode == 2) interior = true;
  if (interior) return LeafClass::kInterior;
  return draw < 0.5 ? LeafClass::kBoundary : LeafClass::kOutside;
}

TEST(TemplatesRandom, BalancedTreesConform) {
  std::mt19937_64 rng(7);
  const RootCube root = unit_root();
  double worst_dihedral = 180;
  size_t tets = 0, non_manifold = 0;
  for (int trial = 0; trial < 120; ++trial) {
    std::vector<Cell> cells = random_cells(rng, trial % 4 == 0 ? 6 : 5);
    const int mode = trial % 3;
    const double p = std::uniform_real_distribution<double>(0.3, 0.95)(rng);
    const double centre[3] = {std::uniform_real_distribution<double>(0.2, 0.6)(rng),
                              std::uniform_real_distribution<double>(0.2, 0.6)(rng),
                              std::uniform_real_distribution<double>(0.2, 0.6)(rng)};
    const double radius = std::uniform_real_distribution<double>(0.1, 0.4)(rng);
    LinearOctree tree = make_tree(
        cells, [&](const Cell& c) { return random_class(c, mode, p, centre, radius, rng); });
    TemplateCore core = template_interior(tree, root);
    CoreFacts facts = expect_core_conforms(tree, core, "trial " + std::to_string(trial));
    ValidationResult r = validate_mesh(core.mesh, nullptr);
    if (core.mesh.num_tets() > 0)
      worst_dihedral = std::min(worst_dihedral, r.quality.min_dihedral_deg);
    tets += core.mesh.num_tets();
    non_manifold += facts.non_manifold_edges;
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("random trees: %zu tets, worst dihedral %.6f degrees, %zu non-manifold core edges\n",
              tets, worst_dihedral, non_manifold);
  EXPECT_GT(tets, 100000u);
  EXPECT_NEAR(worst_dihedral, 45.0, 1e-9);
}

TEST(TemplatesRandom, VerticesAreTheTemplatePointsAtTheirHomes) {
  std::mt19937_64 rng(11);
  const RootCube root = unit_root();
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Cell> cells = random_cells(rng, 5);
    LinearOctree tree =
        make_tree(cells, [&](const Cell& c) { return random_class(c, 0, 0.7, nullptr, 0, rng); });
    TemplateCore core = template_interior(tree, root);
    const TetMesh& mesh = core.mesh;
    ASSERT_EQ(core.leaf_first_vertex.size(), tree.size() + 1);
    ASSERT_EQ(core.leaf_first_tet.size(), tree.size() + 1);
    // Keys ascending (numbering by home leaf, then child anchor), each in
    // its home's half-open box at a child anchor, with exact coordinates.
    for (size_t i = 0; i < tree.size(); ++i) {
      const Cell c = tree_cell(tree, i);
      const uint32_t edge = cell_edge(c);
      for (uint32_t v = core.leaf_first_vertex[i]; v < core.leaf_first_vertex[i + 1]; ++v) {
        if (v > 0) {
          EXPECT_LT(mesh.global_ids[v - 1], mesh.global_ids[v]);
        }
        LatticePoint q = lattice_of(core, v);
        for (int k = 0; k < 3; ++k) {
          const int64_t off = q.q[k] - 2 * int64_t{c.a[k]};
          EXPECT_TRUE(off == 0 || off == edge) << "vertex " << v << " off its home's child anchors";
          EXPECT_EQ(mesh.xyz[3 * v + k], static_cast<double>(q.q[k]) / (2.0 * kGridSize));
        }
      }
      // Leaf tets: at most 48, all around the leaf's centre, per face: the
      // face triangles of a coned face; the boundary segments of a paired
      // face, around the axis to the twin's centre, from the lower key only.
      const uint64_t first = core.leaf_first_tet[i], count = core.leaf_first_tet[i + 1] - first;
      if (tree.cls[i] != LeafClass::kInterior) {
        EXPECT_EQ(count, 0u);
        EXPECT_EQ(core.face_case[6 * i], kNoFaceCase);
        continue;
      }
      uint64_t t = first;
      for (int f = 0; f < kLeafFaces; ++f) {
        const int face_case = core.face_case[6 * i + f];
        const uint32_t twin = paired_leaf(tree, i, f);
        const uint64_t made = face_tets(tree, i, f, face_case);
        if (twin == kAbsentLeaf) {
          EXPECT_EQ(made, face_triangulation(f, face_case).count);
        } else {
          const int corners = 4, midpoints = face_case < kDiagonalCase ? __builtin_popcount(face_case) : 0;
          EXPECT_EQ(made, tree.key[i] < tree.key[twin] ? uint64_t(corners + midpoints) : 0u);
          const Cell d = tree_cell(tree, twin);
          for (uint64_t s = t; s < t + made; ++s) {
            LatticePoint other = lattice_of(core, mesh.tets[4 * s + 2]);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(other.q[k], 2 * int64_t{d.a[k]} + edge) << "not the twin's centre";
          }
        }
        t += made;
      }
      EXPECT_EQ(t, first + count);
      EXPECT_LE(count, 48u);
      for (uint64_t s = first; s < first + count; ++s) {
        LatticePoint centre = lattice_of(core, mesh.tets[4 * s + 3]);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(centre.q[k], 2 * int64_t{c.a[k]} + edge);
      }
    }
  }
}

TEST(TemplatesRandom, UniformBlockIsTheBodyCentredCubicLattice) {
  // A 6 x 6 x 6 block of interior level-3 leaves: the 540 faces inside it
  // are paired, 4 tets each, all of the body-centred cubic lattice; the
  // 216 faces on its surface are coned, 2 tets each.
  const RootCube root = unit_root();
  const uint32_t h = octant_edge(3);
  LinearOctree tree = make_tree(uniform_cells(3), [&](const Cell& c) {
    for (uint32_t k : c.a)
      if (k == 0 || k == 7 * h) return LeafClass::kOutside;
    return LeafClass::kInterior;
  });
  TemplateCore core = template_interior(tree, root);
  expect_core_conforms(tree, core, "uniform block");
  ASSERT_EQ(core.mesh.num_tets(), 540u * 4 + 216u * 2);
  const double pi = std::acos(-1.0);
  size_t lattice_tets = 0;
  for (size_t t = 0; t < core.mesh.num_tets(); ++t) {
    const uint32_t* v = &core.mesh.tets[4 * t];
    const TetShape shape = tet_shape(core.mesh.point(v[0]), core.mesh.point(v[1]), core.mesh.point(v[2]),
                                     core.mesh.point(v[3]));
    EXPECT_GT(shape.volume, 0);
    if (std::abs(shape.min_dihedral_rad - pi / 3) < 1e-9 && std::abs(shape.max_dihedral_rad - pi / 2) < 1e-9) {
      EXPECT_NEAR(shape.radius_ratio, 0.9486832980505138, 1e-9);
      ++lattice_tets;
    }
  }
  EXPECT_EQ(lattice_tets, 540u * 4);
}

TEST(TemplatesRandom, Deterministic) {
  std::mt19937_64 rng(5);
  std::vector<Cell> cells = random_cells(rng, 5);
  LinearOctree tree =
      make_tree(cells, [&](const Cell& c) { return random_class(c, 0, 0.8, nullptr, 0, rng); });
  TemplateCore a = template_interior(tree, unit_root());
  TemplateCore b = template_interior(tree, unit_root());
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.mesh.xyz, b.mesh.xyz);
  EXPECT_EQ(a.mesh.global_ids, b.mesh.global_ids);
}

TEST(TemplatesRandom, UnbalancedTreeIsAnInternalError) {
  // Cell (1,1,1) of level 2 refined twice at its anchor: a level-4 leaf
  // there, whose -x neighbour, the level-2 cell (0,1,1), is interior and
  // finds it as its +x upper cell.
  const uint32_t step = 1u << 18;
  std::vector<Cell> cells = uniform_cells(2);
  const size_t i = static_cast<size_t>(find_cell(cells, step, step, step, 2));
  refine(cells, i);
  refine(cells, i);
  LinearOctree tree = make_tree(cells, [&](const Cell& c) {
    bool west = c.level == 2 && c.a[0] == 0 && c.a[1] == step && c.a[2] == step;
    return west ? LeafClass::kInterior : LeafClass::kOutside;
  });
  EXPECT_THROW(template_interior(tree, unit_root()), InternalError);
}

}  // namespace
}  // namespace partet::test
