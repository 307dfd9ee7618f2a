// Interior vertex collapse: a vertex crowding another inside a coned cube
// is merged away, leaving the cube coned to one centre, every tet
// positive, the boundary as it was and the collapsed vertex unused; frozen
// vertices are never collapsed; optimize_mesh counts the collapses; the
// screened search picks the collapse an exhaustive one picks, skipping the
// vertices refused before whose stars have not changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "check/validate.hpp"
#include "core/compact_mesh.hpp"
#include "core/predicates.hpp"
#include "optimize/collapse.hpp"
#include "optimize/optimize.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize_test_util.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::all_positive;
using test::boundary_faces;
using test::worst_quality;

// The unit cube's 12 boundary triangles coned to its centre, vertex 8; then
// tet 0 split at vertex 9, a hundredth of the way from the centre to the
// centroid of tet 0's boundary face: four tets, three of them nearly flat.
TetMesh crowded_cube() {
  SurfaceMesh box = test::box_surface();
  TetMesh m;
  m.xyz = box.xyz;
  m.xyz.insert(m.xyz.end(), {0.5, 0.5, 0.5});
  m.tris = box.tris;
  for (size_t t = 0; t < box.num_triangles(); ++t)
    m.tets.insert(m.tets.end(), {box.tris[3 * t], box.tris[3 * t + 2], box.tris[3 * t + 1], 8});
  const uint32_t split[4] = {m.tets[0], m.tets[1], m.tets[2], m.tets[3]};
  double at[3];
  for (int i = 0; i < 3; ++i)
    at[i] = 0.99 * 0.5 + 0.01 * (m.point(split[0])[i] + m.point(split[1])[i] + m.point(split[2])[i]) / 3;
  m.xyz.insert(m.xyz.end(), at, at + 3);
  m.tets.erase(m.tets.begin(), m.tets.begin() + 4);
  for (int k = 0; k < 4; ++k) {
    uint32_t tet[4] = {split[0], split[1], split[2], split[3]};
    tet[k] = 9;
    m.tets.insert(m.tets.end(), tet, tet + 4);
  }
  return m;
}

uint32_t worst_slot(const TetTopology& topo) {
  uint32_t worst = 0;
  for (uint32_t t = 1; t < topo.slots(); ++t)
    if (topo.quality(t) < topo.quality(worst)) worst = t;
  return worst;
}

TEST(Collapse, MergesACrowdingVertexAndLeavesItUnused) {
  TetMesh m = crowded_cube();
  ASSERT_TRUE(all_positive(m));
  ASSERT_EQ(m.num_tets(), 15u);
  const auto boundary = boundary_faces(m);
  const double before = worst_quality(m);
  std::vector<uint8_t> frozen(10, 1);
  frozen[8] = frozen[9] = 0;
  TetTopology topo(m);
  const double bar = insertion_bar(quality_of_angle(40));
  ASSERT_TRUE(collapse_vertex(topo, worst_slot(topo), frozen, bar, InsertionRule::kShortfall));
  topo.compact();
  EXPECT_EQ(m.num_tets(), 12u);
  EXPECT_TRUE(all_positive(m));
  EXPECT_EQ(boundary_faces(m), boundary);
  EXPECT_GT(worst_quality(m), before);
  // The centre stays (its cone is the better one) and vertex 9 is unused.
  EXPECT_EQ(std::count(m.tets.begin(), m.tets.end(), 9u), 0);
  EXPECT_EQ(std::count(m.tets.begin(), m.tets.end(), 8u), 12);
  EXPECT_EQ(drop_unused_vertices(m), 1u);
  ValidationResult r = validate_mesh(m, nullptr);
  EXPECT_TRUE(r.valid) << format_text(r);
  EXPECT_EQ(r.warnings.size(), 0u) << format_text(r);
}

TEST(Collapse, FrozenAndBoundaryVerticesStay) {
  TetMesh m = crowded_cube();
  const TetMesh original = m;
  std::vector<uint8_t> frozen(10, 1);  // every vertex
  TetTopology topo(m);
  const double bar = insertion_bar(quality_of_angle(40));
  EXPECT_FALSE(collapse_vertex(topo, worst_slot(topo), frozen, bar, InsertionRule::kWorstFirst));
  // With no flags at all, no vertex on an open face is collapsed: here the
  // centre's 11 cone tets alone, with the split tet's place left open.
  std::vector<uint8_t> none;
  TetMesh opened = original;
  opened.tets.resize(4 * 11);
  TetTopology open(opened);
  for (uint32_t t = 0; t < open.slots(); ++t)
    EXPECT_FALSE(collapse_vertex(open, t, none, bar, InsertionRule::kShortfall));
  topo.compact();
  EXPECT_EQ(m.tets, original.tets);
}

TEST(Collapse, OptimizeMeshCountsCollapsesAndKeepsTheMeshValid) {
  TetMesh m = crowded_cube();
  const auto boundary = boundary_faces(m);
  OptimizeStats stats = optimize_mesh(m, OptimizeOptions{});
  EXPECT_GE(stats.vertices_collapsed, 1u);
  EXPECT_TRUE(all_positive(m));
  EXPECT_EQ(boundary_faces(m), boundary);
  EXPECT_GT(stats.after.min_dihedral_deg, stats.before.min_dihedral_deg);
  drop_unused_vertices(m);
  ValidationResult r = validate_mesh(m, nullptr);
  EXPECT_TRUE(r.valid) << format_text(r);
}

// Some tet of `star` (v's star) has a face through v with no tet behind
// it: v is on the boundary (found from the star, not TetTopology's flags).
bool on_open_face(const TetTopology& topo, uint32_t v, const std::vector<uint32_t>& star) {
  for (uint32_t s : star) {
    const int lv = local_index(topo.tet(s), v);
    for (int f = 0; f < 4; ++f)
      if (f != lv && topo.twin(4 * s + f) == TetTopology::kNone) return true;
  }
  return false;
}

// collapse_vertex without the screening: every neighbour's cones measured
// in star order, the first not above the bar to beat ending it.
bool exhaustive_collapse(TetTopology& topo, uint32_t t, const std::vector<uint8_t>& frozen, double bar,
                         InsertionRule rule) {
  const double ten = quality_of_angle(10);
  double best_quality = -std::numeric_limits<double>::infinity();
  std::vector<uint32_t> best_star, best_quads, star, neighbours, quads, old_quads;
  uint32_t corners[4];
  std::copy_n(topo.tet(t), 4, corners);
  for (uint32_t v : corners) {
    if (v >= frozen.size() || frozen[v]) continue;
    topo.vertex_star(v, star);
    if (on_open_face(topo, v, star)) continue;
    double old_quality = std::numeric_limits<double>::infinity(), old_deficit = 0;
    int old_slivers = 0;
    for (uint32_t s : star) {
      const double q = topo.quality(s);
      old_quality = std::min(old_quality, q);
      old_deficit += std::max(0.0, bar - q);
      old_slivers += q < ten;
    }
    topo.star_neighbours(v, star, neighbours);
    for (uint32_t w : neighbours) {
      const double beat = std::max(old_quality, best_quality);
      double new_quality = std::numeric_limits<double>::infinity(), new_deficit = 0;
      int new_slivers = 0;
      quads.clear();
      bool valid = true;
      for (uint32_t s : star) {
        const uint32_t* tet = topo.tet(s);
        if (local_index(tet, w) >= 0) continue;
        uint32_t cone[4];
        std::copy_n(tet, 4, cone);
        cone[local_index(tet, v)] = w;
        const double* p[4] = {topo.point(cone[0]), topo.point(cone[1]), topo.point(cone[2]), topo.point(cone[3])};
        const double q = tet_quality(p[0], p[1], p[2], p[3]);
        if (!(q > beat) || orient3d(p[0], p[1], p[2], p[3]) <= 0) {
          valid = false;
          break;
        }
        new_quality = std::min(new_quality, q);
        new_deficit += std::max(0.0, bar - q);
        new_slivers += q < ten;
        quads.insert(quads.end(), cone, cone + 4);
      }
      if (!valid) continue;
      if (rule == InsertionRule::kShortfall) {
        if (new_deficit > old_deficit || new_slivers > old_slivers) continue;
      } else {
        topo.tet_vertices(star, old_quads);
        if (!min_angle_no_worse(topo, old_quads, quads)) continue;
      }
      best_quality = new_quality;
      best_star = star;
      best_quads = quads;
    }
  }
  if (best_star.empty()) return false;
  std::vector<uint32_t> created;
  topo.replace(best_star, best_quads, created);
  return true;
}

// A Kuhn lattice of 5^3 cubes with its 64 interior vertices jittered by up
// to 0.35 (every tet still positive): crowded and flat tets everywhere.
TetMesh crowded_lattice(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  for (;;) {
    TetMesh m = test::kuhn_lattice(5);
    for (int z = 1; z < 5; ++z)
      for (int y = 1; y < 5; ++y)
        for (int x = 1; x < 5; ++x)
          for (int i = 0; i < 3; ++i) m.xyz[3 * (x + 6 * (y + 6 * z)) + i] += jitter(rng);
    if (all_positive(m)) return m;
  }
}

TEST(Collapse, ScreenedSearchPicksTheExhaustiveSearchsCollapse) {
  std::mt19937 rng(7);
  const double bar = insertion_bar(quality_of_angle(40));
  size_t applied = 0, skipped = 0;
  for (int trial = 0; trial < 4; ++trial)
    for (InsertionRule rule : {InsertionRule::kShortfall, InsertionRule::kWorstFirst}) {
      TetMesh a = crowded_lattice(rng);
      TetMesh b = a;
      std::vector<uint8_t> frozen(a.num_vertices(), 1);
      for (int z = 1; z < 5; ++z)
        for (int y = 1; y < 5; ++y)
          for (int x = 1; x < 5; ++x) frozen[x + 6 * (y + 6 * z)] = 0;
      TetTopology screened(a), exhaustive(b);
      // The screened search also skips the vertices it has seen refused.
      RefusedCollapses refused;
      for (uint32_t t = 0; t < screened.slots(); ++t) {
        if (!screened.alive(t) || screened.quality(t) >= bar) continue;
        for (int k = 0; k < 4; ++k) skipped += refused.known(screened, screened.tet(t)[k]);
        const bool did = collapse_vertex(screened, t, frozen, bar, rule, &refused);
        ASSERT_EQ(did, exhaustive_collapse(exhaustive, t, frozen, bar, rule)) << "tet " << t;
        applied += did;
      }
      screened.compact();
      exhaustive.compact();
      EXPECT_EQ(a.tets, b.tets);
      EXPECT_TRUE(all_positive(a));
    }
  EXPECT_GT(applied, 8u);   // the searches met many collapses that pay
  EXPECT_GT(skipped, 8u);   // and vertices refused before, unchanged
}

}  // namespace
}  // namespace partet
