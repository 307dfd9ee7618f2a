// lift_sheet (sheet_lift.hpp) on hand-made sheets: free vertices a hair
// above the base of a pyramid whose base, sides and apex are boundary.
// The flat tets on the base rise well above a degree, every tet stays
// positive, only the sheet's vertices move (along the base's normal), and
// a tet that is not flat, or a sheet with no free vertex, is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "check/quality.hpp"
#include "optimize/sheet_lift.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

using test::add_positive_tet;

constexpr double kDeg = 180 / std::numbers::pi;

// The pyramid over the unit square (A, B, C, D) with apex T at height 1,
// split by base points E = (0.5, 0) and F = (0.5, 1) into two pyramids,
// each coned from one free vertex at (0.25 or 0.75, 0.5, height): the
// tets on the base are flat for tiny heights.
TetMesh split_pyramid(double left_height, double right_height) {
  TetMesh m;
  m.xyz = {0, 0, 0,   1, 0, 0,   1, 1, 0,   0, 1, 0,  0.5, 0.5, 1,  0.5, 0, 0,  0.5, 1, 0,
           0.25, 0.5, left_height,  0.75, 0.5, right_height};
  enum : uint32_t { A, B, C, D, T, E, F, L, R };
  for (const auto& face : {std::array<uint32_t, 3>{A, E, F}, {A, F, D}, {A, E, T}, {E, F, T}, {F, D, T}, {D, A, T}})
    add_positive_tet(m, face[0], face[1], face[2], L);
  for (const auto& face : {std::array<uint32_t, 3>{E, B, C}, {E, C, F}, {E, B, T}, {B, C, T}, {C, F, T}, {F, E, T}})
    add_positive_tet(m, face[0], face[1], face[2], R);
  return m;
}

double smallest_angle_deg(const TetMesh& m) {
  double smallest = 180;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    smallest = std::min(smallest, tet_shape(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])).min_dihedral_rad * kDeg);
  }
  return smallest;
}

uint32_t worst_tet(const TetTopology& topo) {
  uint32_t worst = 0;
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t) && topo.quality(t) < topo.quality(worst)) worst = t;
  return worst;
}

TEST(SheetLift, LiftsFlatTetsOffTheBase) {
  TetMesh mesh = split_pyramid(1e-12, 3e-9);
  const TetMesh before = mesh;
  ASSERT_LT(smallest_angle_deg(mesh), 1e-6);
  TetTopology topo(mesh);
  const std::vector<uint8_t> boundary = topo.boundary_vertices();
  ASSERT_FALSE(boundary[7] || boundary[8]);
  // The worst tet is on the left: its sheet is the left free vertex, which
  // rises straight up; nothing else moves.
  ASSERT_TRUE(lift_sheet(topo, worst_tet(topo), boundary));
  for (uint32_t v = 0; v < 9; ++v) {
    if (v == 7) continue;
    EXPECT_TRUE(std::equal(before.point(v), before.point(v) + 3, mesh.point(v))) << v;
  }
  EXPECT_EQ(mesh.point(7)[0], before.point(7)[0]);
  EXPECT_EQ(mesh.point(7)[1], before.point(7)[1]);
  EXPECT_GT(mesh.point(7)[2], 0.05);
  // Then the right one.
  ASSERT_TRUE(lift_sheet(topo, worst_tet(topo), boundary));
  EXPECT_GT(mesh.point(8)[2], 0.05);
  topo.compact();
  EXPECT_TRUE(test::all_positive(mesh));
  EXPECT_EQ(mesh.tets, before.tets);
  EXPECT_GT(smallest_angle_deg(mesh), 10);
}

TEST(SheetLift, LeavesTetsAboveADegreeAndFrozenSheetsAlone) {
  {
    TetMesh mesh = split_pyramid(0.2, 0.2);
    const TetMesh before = mesh;
    TetTopology topo(mesh);
    ASSERT_GT(smallest_angle_deg(mesh), kSheetAngle);
    EXPECT_FALSE(lift_sheet(topo, worst_tet(topo), topo.boundary_vertices()));
    topo.compact();
    EXPECT_EQ(mesh.xyz, before.xyz);
  }
  {
    TetMesh mesh = split_pyramid(1e-12, 1e-12);
    const TetMesh before = mesh;
    TetTopology topo(mesh);
    const std::vector<uint8_t> all_frozen(mesh.num_vertices(), 1);
    EXPECT_FALSE(lift_sheet(topo, worst_tet(topo), all_frozen));
    topo.compact();
    EXPECT_EQ(mesh.xyz, before.xyz);
  }
}

}  // namespace
}  // namespace partet
