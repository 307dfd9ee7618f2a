// Target sizes per surface vertex, their levels (round to nearest in log
// space) and grid cells.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "octree/sizing.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::box_surface;

TEST(SizesMeanEdge, BoxSurface) {
  // A unit cube's corners: 3 unit edges and 1 or 2 face diagonals; the mean
  // counts each triangle's two edges at the vertex (each edge in 2 triangles).
  const SurfaceMesh s = box_surface();
  const std::vector<double> mean = mean_incident_edge_length(s);
  ASSERT_EQ(mean.size(), 8u);
  for (size_t v = 0; v < 8; ++v) {
    // Vertices 0 and 7 are on 3 diagonals, the others on 1 (box_surface
    // splits every face through corner 0 or 7).
    const double diagonals = (v == 0 || v == 7) ? 3 : 1;
    const double want = (3 + diagonals * std::sqrt(2.0)) / (3 + diagonals);
    EXPECT_NEAR(mean[v], want, 1e-14) << v;
  }
}

TEST(SizesLevel, RoundsToNearestInLogSpace) {
  const double D = 1024;
  EXPECT_EQ(size_to_level(512, D, kMaxLevel), 1);
  EXPECT_EQ(size_to_level(1, D, kMaxLevel), 10);
  EXPECT_EQ(size_to_level(1.4, D, kMaxLevel), 10);   // log2 ratio 9.51: nearest 10
  EXPECT_EQ(size_to_level(1.42, D, kMaxLevel), 9);   // 9.49: nearest 9
  EXPECT_EQ(size_to_level(0.71, D, kMaxLevel), 10);  // 10.49
  EXPECT_EQ(size_to_level(0.70, D, kMaxLevel), 11);  // 10.51
  // The leaf edge of the level is within a factor sqrt(2) of the target.
  for (double d = 0.01; d < 400; d *= 1.07) {
    const int level = size_to_level(d, D, kMaxLevel);
    const double edge = D / std::ldexp(1.0, level);
    EXPECT_LE(edge / d, std::sqrt(2.0) * (1 + 1e-12)) << d;
    EXPECT_GE(edge / d, 1 / std::sqrt(2.0) * (1 - 1e-12)) << d;
  }
}

TEST(SizesLevel, Clamps) {
  EXPECT_EQ(size_to_level(5000, 1024, kMaxLevel), 1);  // larger than the root
  EXPECT_EQ(size_to_level(1e-30, 1024, kMaxLevel), kMaxLevel);
  EXPECT_EQ(size_to_level(1e-30, 1024, 8), 8);
  EXPECT_EQ(size_to_level(1e-30, 1024, 99), kMaxLevel);
  EXPECT_EQ(size_to_level(1e-30, 1024, -3), 1);
  EXPECT_EQ(size_to_level(0, 1024, 12), 12);
}

TEST(SizesGrid, CellsAndClamping) {
  RootCube root;
  root.origin[0] = -1;
  root.origin[1] = 0;
  root.origin[2] = 2;
  root.unit = 1.0 / 1024;
  uint32_t g[3];
  const double p[3] = {-1, 0.5, 2 + 3.5 / 1024};
  grid_cell(root, p, g);
  EXPECT_EQ(g[0], 0u);
  EXPECT_EQ(g[1], 512u);
  EXPECT_EQ(g[2], 3u);
  const double out[3] = {-5, 1e9, root.origin[2] + root.edge()};
  grid_cell(root, out, g);
  EXPECT_EQ(g[0], 0u);
  EXPECT_EQ(g[1], kGridSize - 1);
  EXPECT_EQ(g[2], kGridSize - 1);
}

TEST(SizesVertices, OptionsApply) {
  const SurfaceMesh s = box_surface(2, 2, 2);
  const double bbox[6] = {0, 0, 0, 2, 2, 2};
  const RootCube root = make_root_cube(bbox);
  const VertexSizing plain = size_vertices(s, root, {});
  ASSERT_EQ(plain.size.size(), 8u);
  ASSERT_EQ(plain.grid.size(), 24u);
  SizingOptions half;
  half.size_factor = 0.5;
  const VertexSizing finer = size_vertices(s, root, half);
  for (size_t v = 0; v < 8; ++v) {
    EXPECT_DOUBLE_EQ(finer.size[v], 0.5 * plain.size[v]);
    EXPECT_EQ(finer.level[v], plain.level[v] + 1);
    for (int i = 0; i < 3; ++i) {
      uint32_t g[3];
      grid_cell(root, s.point(v), g);
      EXPECT_EQ(plain.grid[3 * v + i], g[i]);
    }
  }
  SizingOptions capped;
  capped.max_size = 0.1;
  capped.max_level = 6;
  const VertexSizing c = size_vertices(s, root, capped);
  for (size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(c.size[v], 0.1);
    EXPECT_LE(c.level[v], 6);
    EXPECT_EQ(c.level[v], std::min(6, size_to_level(0.1, root.edge(), kMaxLevel)));
  }
}

TEST(SizesVertices, RejectsBadOptions) {
  const SurfaceMesh s = box_surface();
  const double bbox[6] = {0, 0, 0, 1, 1, 1};
  const RootCube root = make_root_cube(bbox);
  SizingOptions o;
  o.size_factor = 0;
  EXPECT_THROW(size_vertices(s, root, o), InputError);
  o.size_factor = NAN;
  EXPECT_THROW(size_vertices(s, root, o), InputError);
  o = {};
  o.max_size = -1;
  EXPECT_THROW(size_vertices(s, root, o), InputError);
}

}  // namespace
}  // namespace partet
