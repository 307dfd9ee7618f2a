// The flips on hand-made configurations: 2-3, 3-2, 4-4, edge removal
// around rings of 5 to 10 tets and multi-face removal of polygons of 2 to 5
// faces each improve the worst tet, keep every tet positive, keep the
// boundary faces, and leave a valid mesh; the topology's kept tet
// qualities follow vertex moves and replacements.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "check/validate.hpp"
#include "optimize/flips.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

using test::add_positive_tet;
using test::all_positive;
using test::boundary_faces;
using test::worst_quality;

// Applies `flip` to `mesh` through a topology; checks validity, boundary and improvement.
void apply_and_check(TetMesh& mesh, TetTopology& topo, const Flip& flip) {
  const auto boundary = boundary_faces(mesh);
  const double before = worst_quality(mesh);
  EXPECT_GT(flip.new_quality, flip.old_quality);
  std::vector<uint32_t> created;
  topo.replace(flip.cavity(), flip.replacement(), created);
  EXPECT_EQ(created.size(), static_cast<size_t>(flip.new_count));
  topo.compact();
  EXPECT_TRUE(all_positive(mesh));
  EXPECT_EQ(boundary_faces(mesh), boundary);
  EXPECT_GT(worst_quality(mesh), before);
  EXPECT_NEAR(worst_quality(mesh), flip.new_quality, 1e-12);
  ValidationResult r = validate_mesh(mesh, nullptr);
  EXPECT_TRUE(r.valid) << format_text(r);
}

// A triangle in z = 0 (vertices 0, 1, 2) with apexes 3 at +h and 4 at -h.
TetMesh bipyramid(double h) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0.5, std::sqrt(0.75), 0, 0.5, 0.3, h, 0.5, 0.3, -h};
  return m;
}

double measured(const TetTopology& topo, uint32_t t) {
  const uint32_t* v = topo.tet(t);
  return tet_quality(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3]));
}

TEST(Flips, KeptQualitiesFollowMovesAndReplacements) {
  TetMesh m = bipyramid(0.15);
  add_positive_tet(m, 0, 1, 2, 3);
  add_positive_tet(m, 0, 1, 2, 4);
  TetTopology topo(m);
  const double flat = topo.quality(0);
  EXPECT_EQ(flat, measured(topo, 0));
  EXPECT_EQ(topo.quality(1), measured(topo, 1));
  // Raising apex 3 changes tet 0 only.
  const double raised[3] = {0.5, 0.3, 0.6};
  topo.move_vertex(3, raised);
  EXPECT_GT(topo.quality(0), flat);
  EXPECT_EQ(topo.quality(0), measured(topo, 0));
  EXPECT_EQ(topo.quality(1), measured(topo, 1));
  // A replacement measures its new tets afresh.
  Flip flip;
  for (uint32_t code = 0; code < 8 && flip.new_count == 0; ++code) face_flip(topo, code, flip);
  ASSERT_EQ(flip.new_count, 3);
  std::vector<uint32_t> created;
  topo.replace(flip.cavity(), flip.replacement(), created);
  for (uint32_t t : created) EXPECT_EQ(topo.quality(t), measured(topo, t));
}

TEST(Flips, TwoThreeFlipOfAFlatPair) {
  TetMesh m = bipyramid(0.15);
  add_positive_tet(m, 0, 1, 2, 3);
  add_positive_tet(m, 0, 1, 2, 4);
  TetTopology topo(m);
  Flip flip;
  int found = 0;
  for (uint32_t code = 0; code < 8; ++code)
    if (face_flip(topo, code, flip)) {
      ++found;
      EXPECT_EQ(flip.kind, FlipKind::k23);
      EXPECT_EQ(flip.new_count, 3);
      apply_and_check(m, topo, flip);
      break;
    }
  EXPECT_EQ(found, 1);
  EXPECT_EQ(m.num_tets(), 3u);
}

TEST(Flips, NoTwoThreeFlipOnABoundaryFaceOrAcrossANonConvexPair) {
  TetMesh m = bipyramid(0.35);
  m.xyz[12] = 3;  // apex 4 far outside the prism over the triangle: edge 3-4 misses it
  add_positive_tet(m, 0, 1, 2, 3);
  add_positive_tet(m, 0, 1, 2, 4);
  TetTopology topo(m);
  Flip flip;
  for (uint32_t code = 0; code < 8; ++code) EXPECT_FALSE(face_flip(topo, code, flip)) << code;
}

// Three tets around the long edge 3-4 of a tall bipyramid.
TEST(Flips, ThreeTwoFlipOfANeedleRing) {
  TetMesh m = bipyramid(1.5);
  add_positive_tet(m, 3, 4, 0, 1);
  add_positive_tet(m, 3, 4, 1, 2);
  add_positive_tet(m, 3, 4, 2, 0);
  TetTopology topo(m);
  Flip flip;
  ASSERT_TRUE(edge_removal(topo, 0, 0, 1, flip));
  EXPECT_EQ(flip.kind, FlipKind::k32);
  EXPECT_EQ(flip.old_count, 3);
  EXPECT_EQ(flip.new_count, 2);
  apply_and_check(m, topo, flip);
}

// A ring of n vertices (radii rx, ry) in z = 0 around the edge from
// (0, 0, -h) to (0, 0, h): vertices 0..n-1 on the ring, n and n+1 the edge.
TetMesh ring_mesh(int n, double rx, double ry, double h) {
  TetMesh m;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * k / n;
    m.xyz.insert(m.xyz.end(), {rx * std::cos(angle), ry * std::sin(angle), 0.01 * (k % 2)});
  }
  m.xyz.insert(m.xyz.end(), {0, 0, -h, 0, 0, h});
  const uint32_t a = static_cast<uint32_t>(n), b = a + 1;
  for (int k = 0; k < n; ++k) add_positive_tet(m, a, b, static_cast<uint32_t>(k), static_cast<uint32_t>((k + 1) % n));
  return m;
}

TEST(Flips, FourFourFlipTurnsTheAxisOfAThinOctahedron) {
  TetMesh m = ring_mesh(4, 1, 0.3, 1);
  TetTopology topo(m);
  const uint32_t* v = topo.tet(0);
  Flip flip;
  ASSERT_TRUE(edge_removal(topo, 0, local_index(v, 4), local_index(v, 5), flip));
  EXPECT_EQ(flip.kind, FlipKind::k44);
  EXPECT_EQ(flip.new_count, 4);
  apply_and_check(m, topo, flip);
}

// The edge removal of a ring_mesh's axis (its vertices n and n + 1).
bool remove_axis(const TetTopology& topo, int n, Flip& flip) {
  const uint32_t* v = topo.tet(0);
  return edge_removal(topo, 0, local_index(v, static_cast<uint32_t>(n)), local_index(v, static_cast<uint32_t>(n + 1)),
                      flip);
}

class EdgeRemoval : public testing::TestWithParam<int> {};

TEST_P(EdgeRemoval, RemovesALongEdgeThroughARing) {
  const int n = GetParam();
  // The longer the ring, the longer the axis must be for its needles to be
  // worse than the polygon's tets.
  TetMesh m = ring_mesh(n, 1, 0.8, n <= 8 ? 4 : 8);
  TetTopology topo(m);
  Flip flip;
  ASSERT_TRUE(remove_axis(topo, n, flip));
  EXPECT_EQ(flip.kind, FlipKind::kEdgeRemoval);
  EXPECT_EQ(flip.old_count, n);
  EXPECT_EQ(flip.new_count, 2 * (n - 2));
  apply_and_check(m, topo, flip);
}

INSTANTIATE_TEST_SUITE_P(Flips, EdgeRemoval, testing::Values(5, 6, 7, 8, 9, 10));

TEST(Flips, NoEdgeRemovalOnABoundaryEdgeOrALongRing) {
  constexpr int n = TetTopology::kMaxRing + 1;
  TetMesh m = ring_mesh(n, 1, 1, 0.25);
  TetTopology topo(m);
  const uint32_t* v = topo.tet(0);
  Flip flip;
  EXPECT_FALSE(edge_removal(topo, 0, local_index(v, n), local_index(v, n + 1), flip));  // kMaxRing + 1 tets
  // Every other edge of the ring tets lies on the boundary.
  EXPECT_FALSE(edge_removal(topo, 0, local_index(v, n), local_index(v, 0), flip));
}

// Multi-face removal undoes an edge removal that made things worse: around
// an edge of a fat ring the n tets are better than the 2(n - 2) of any
// triangulated polygon, so from any sandwiched face the polygon is grown
// back to all n - 2 faces and the n tets around the edge return.
class MultiFaceRemoval : public testing::TestWithParam<int> {};

TEST_P(MultiFaceRemoval, RestoresTheTetsAroundAnEdge) {
  const int n = GetParam();
  TetMesh m = ring_mesh(n, 1, 1, 0.7);
  TetTopology topo(m);
  Flip removal;
  ASSERT_TRUE(remove_axis(topo, n, removal));
  ASSERT_LT(removal.new_quality, removal.old_quality) << "the ring must be better around its edge";
  std::vector<uint32_t> created;
  topo.replace(removal.cavity(), removal.replacement(), created);
  ASSERT_EQ(created.size(), static_cast<size_t>(2 * (n - 2)));
  // A face between two polygon triangles' tets: apexes n and n + 1.
  int found = 0;
  for (uint32_t t : created) {
    for (uint32_t f = 0; f < 4; ++f) {
      const uint32_t apex = topo.tet(t)[f];
      if (apex != static_cast<uint32_t>(n) || topo.twin(4 * t + f) == TetTopology::kNone) continue;
      Flip flip;
      ASSERT_TRUE(multi_face_removal(topo, 4 * t + f, flip)) << "tet " << t;
      EXPECT_EQ(flip.kind, FlipKind::kMultiFace);
      // The whole polygon, unless a part of it gives still better tets
      // (on the 7-ring, where a chord makes a good tet).
      EXPECT_GE(flip.new_quality, removal.old_quality - 1e-12);
      if (n < 7) {
        EXPECT_EQ(flip.old_count, 2 * (n - 2));
        EXPECT_EQ(flip.new_count, n);
        EXPECT_NEAR(flip.new_quality, removal.old_quality, 1e-12);
      }
      const double beat = flip.new_quality;
      Flip none;
      EXPECT_FALSE(multi_face_removal(topo, 4 * t + f, none, &beat)) << "nothing beats the best";
      ++found;
      if (found == 1) {
        TetMesh copy = m;
        TetTopology again(copy);
        Flip same;
        ASSERT_TRUE(multi_face_removal(again, 4 * t + f, same));
        if (n < 7) {
          apply_and_check(copy, again, same);
        } else {
          // A part of the polygon: the mesh's worst tet may lie outside it.
          const auto boundary = boundary_faces(copy);
          std::vector<uint32_t> made;
          again.replace(same.cavity(), same.replacement(), made);
          again.compact();
          EXPECT_TRUE(all_positive(copy));
          EXPECT_EQ(boundary_faces(copy), boundary);
          ValidationResult r = validate_mesh(copy, nullptr);
          EXPECT_TRUE(r.valid) << format_text(r);
        }
      }
    }
  }
  EXPECT_EQ(found, n - 2);
}

INSTANTIATE_TEST_SUITE_P(Flips, MultiFaceRemoval, testing::Values(4, 5, 6, 7));

// With a bar to beat, edge removal prunes: sub-polygons not above it, and
// whole rings by the half-angle bound of their tets. On a jittered lattice,
// for bars just below, well below and just above the best retriangulation
// (found without a bar, so unpruned), it finds a flip exactly when the best
// one beats the bar and the ring's worst tet, and then one as good.
TEST(Flips, EdgeRemovalWithABarFindsTheBestRetriangulationAboveIt) {
  TetMesh m = test::kuhn_lattice(3);
  for (size_t i = 0; i < m.xyz.size(); ++i) {
    const double x = m.xyz[i];
    if (x > 0 && x < 3) m.xyz[i] += 0.3 * std::sin(12.9898 * static_cast<double>(i) + 4.1414);
  }
  ASSERT_TRUE(all_positive(m));
  TetTopology topo(m);
  constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  int improving = 0, just_below = 0;
  for (uint32_t t = 0; t < topo.slots(); ++t) {
    for (const auto& e : kEdges) {
      Flip full;
      if (!edge_removal(topo, t, e[0], e[1], full)) continue;
      improving += full.new_quality > full.old_quality;
      for (const double bar : {full.new_quality - 1e-6, full.new_quality - 0.05, full.new_quality + 1e-6, 0.0}) {
        Flip pruned;
        const bool expected = full.new_quality > std::max(bar, full.old_quality);
        ASSERT_EQ(edge_removal(topo, t, e[0], e[1], pruned, &bar), expected) << "tet " << t << " bar " << bar;
        if (!expected) continue;
        EXPECT_EQ(pruned.new_quality, full.new_quality);
        just_below += bar == full.new_quality - 1e-6;
      }
    }
  }
  EXPECT_GT(improving, 20);
  EXPECT_GT(just_below, 20);
}

TEST(Flips, NoMultiFaceRemovalOnABoundaryFace) {
  TetMesh m = bipyramid(0.5);
  add_positive_tet(m, 0, 1, 2, 3);
  TetTopology topo(m);
  Flip flip;
  for (uint32_t code = 0; code < 4; ++code) EXPECT_FALSE(multi_face_removal(topo, code, flip)) << code;
}

}  // namespace
}  // namespace partet
