// Octree construction: leaves tile the root, every point lies in a leaf of
// at least its level, the tree is the coarsest such, refinement splices, and
// refine_for_triangles leaves no leaf meeting a triangle coarser than it asks.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include "io/mesh_file.hpp"
#include "octree/box_triangle.hpp"
#include "octree/build.hpp"
#include "octree/sizing.hpp"
#include "octree_test_util.hpp"
#include "surface/diagnose.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::data_path;

// Sorted, each key aligned to its level, consecutive octants contiguous in
// Morton order from 0 to the end of the root: the leaves tile the root cube
// exactly (disjoint, total volume = root volume).
void expect_tiles_root(const LinearOctree& t) {
  ASSERT_GT(t.size(), 0u);
  ASSERT_EQ(t.level.size(), t.size());
  ASSERT_EQ(t.cls.size(), t.size());
  ASSERT_EQ(t.owner.size(), t.size());
  uint64_t next = 0;
  long double volume = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    ASSERT_LE(t.level[i], kMaxLevel);
    ASSERT_EQ(t.key[i], next) << "leaf " << i;
    ASSERT_EQ(t.key[i] % octant_key_span(t.level[i]), 0u) << "leaf " << i;
    next = t.key[i] + octant_key_span(t.level[i]);
    const long double edge = octant_edge(t.level[i]);
    volume += edge * edge * edge;
  }
  EXPECT_EQ(next, octant_key_span(0));
  const long double root = kGridSize;
  EXPECT_EQ(volume, root * root * root);
}

struct Points {
  std::vector<uint32_t> grid;
  std::vector<uint8_t> level;
};

Points random_points(uint32_t seed, size_t n, int max_level, bool clustered) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> coord(0, kGridSize - 1);
  std::normal_distribution<double> near(0, kGridSize / 64.0);
  std::uniform_int_distribution<int> level(0, max_level);
  Points p;
  const uint32_t centre[3] = {coord(rng), coord(rng), coord(rng)};
  for (size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      double c = clustered ? centre[i] + near(rng) : coord(rng);
      c = std::clamp(c, 0.0, static_cast<double>(kGridSize - 1));
      p.grid.push_back(static_cast<uint32_t>(c));
    }
    p.level.push_back(static_cast<uint8_t>(level(rng)));
  }
  return p;
}

TEST(OctreeBuild, PointsLieInFineEnoughLeavesAndTreeIsCoarsest) {
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    const Points p = random_points(seed, 200, seed % 2 ? 9 : 16, seed > 4);
    const LinearOctree t = build_octree(p.grid, p.level);
    expect_tiles_root(t);
    for (size_t k = 0; k < p.level.size(); ++k) {
      const size_t leaf = t.locate(p.grid[3 * k], p.grid[3 * k + 1], p.grid[3 * k + 2]);
      EXPECT_GE(t.level[leaf], p.level[k]);
    }
    // Coarsest: the parent of every leaf holds a point that asks for the
    // leaf's level or deeper (else the parent would not have been split).
    for (size_t i = 0; i < t.size(); ++i) {
      if (t.level[i] == 0) continue;
      const uint64_t parent = t.key[i] & ~(octant_key_span(t.level[i] - 1) - 1);
      bool needed = false;
      for (size_t k = 0; k < p.level.size() && !needed; ++k) {
        const uint64_t key = morton_key(p.grid[3 * k], p.grid[3 * k + 1], p.grid[3 * k + 2]);
        needed = key >= parent && key < parent + octant_key_span(t.level[i] - 1) && p.level[k] >= t.level[i];
      }
      EXPECT_TRUE(needed) << "leaf " << i;
    }
  }
}

TEST(OctreeBuild, EmptyAndDeepestRequests) {
  const LinearOctree root_only = build_octree({}, {});
  ASSERT_EQ(root_only.size(), 1u);
  EXPECT_EQ(root_only.level[0], 0);
  const LinearOctree deep = build_octree({kGridSize - 1, 0, kGridSize - 1}, {kMaxLevel});
  expect_tiles_root(deep);
  EXPECT_EQ(deep.size(), 1u + 7u * kMaxLevel);
  EXPECT_EQ(deep.level[deep.locate(kGridSize - 1, 0, kGridSize - 1)], kMaxLevel);
}

TEST(OctreeBuild, RefineSplicesAndInheritsClassAndOwner) {
  const Points p = random_points(21, 100, 8, false);
  LinearOctree t = build_octree(p.grid, p.level);
  for (size_t i = 0; i < t.size(); ++i) {
    t.cls[i] = i % 2 ? LeafClass::kInterior : LeafClass::kOutside;
    t.owner[i] = static_cast<int32_t>(i % 5);
  }
  const LinearOctree before = t;
  const Points more = random_points(22, 50, 11, true);
  std::vector<RefineRequest> requests;
  for (size_t k = 0; k < more.level.size(); ++k)
    requests.push_back({morton_key(more.grid[3 * k], more.grid[3 * k + 1], more.grid[3 * k + 2]), more.level[k]});
  refine_octree(t, requests);
  expect_tiles_root(t);
  for (const RefineRequest& r : requests) {
    uint32_t x, y, z;
    morton_decode(r.key, x, y, z);
    EXPECT_GE(t.level[t.locate(x, y, z)], r.level);
  }
  // Every new leaf lies in an old leaf no finer than it, with its class and
  // owner; old leaves that needed no split are unchanged.
  for (size_t i = 0; i < t.size(); ++i) {
    uint32_t x, y, z;
    t.anchor(i, x, y, z);
    const size_t old = before.locate(x, y, z);
    EXPECT_GE(t.level[i], before.level[old]);
    EXPECT_EQ(t.cls[i], before.cls[old]);
    EXPECT_EQ(t.owner[i], before.owner[old]);
  }
  // Refining again with the same requests changes nothing.
  const LinearOctree once = t;
  refine_octree(t, requests);
  EXPECT_EQ(t.key, once.key);
  EXPECT_EQ(t.level, once.level);
}

// Brute force: every leaf whose closed box meets a triangle has at least the
// triangle's level (the minimum of its vertices' levels).
void expect_triangles_refined(const LinearOctree& t, const SurfaceMesh& s, const RootCube& root,
                              const std::vector<uint8_t>& vertex_level) {
  for (size_t i = 0; i < t.size(); ++i) {
    double lo[3], hi[3];
    leaf_box(t, root, i, lo, hi);
    for (size_t k = 0; k < s.num_triangles(); ++k) {
      const uint32_t* v = &s.tris[3 * k];
      const int want = std::min({vertex_level[v[0]], vertex_level[v[1]], vertex_level[v[2]]});
      if (t.level[i] >= want) continue;
      ASSERT_FALSE(box_meets_triangle(lo, hi, s.point(v[0]), s.point(v[1]), s.point(v[2])))
          << "leaf " << i << " level " << int(t.level[i]) << " meets triangle " << k << " of level " << want;
    }
  }
}

TEST(OctreeBuild, RefineForTrianglesOnCorpusSurfaces) {
  for (const char* name : {"cube.off", "tripod.off", "star.off", "u.off", "joint.off", "lever.stl"}) {
    SCOPED_TRACE(name);
    SurfaceMesh s = read_surface_file(data_path(std::string("good/") + name));
    const SurfaceSummary sum = diagnose_surface(s, name);
    const RootCube root = make_root_cube(sum.bbox);
    const VertexSizing sizes = size_vertices(s, root, {});
    LinearOctree t = build_octree(sizes.grid, sizes.level);
    refine_for_triangles(t, s, root, sizes.level);
    expect_tiles_root(t);
    expect_triangles_refined(t, s, root, sizes.level);
    for (size_t v = 0; v < s.num_vertices(); ++v)
      EXPECT_GE(t.level[t.locate(sizes.grid[3 * v], sizes.grid[3 * v + 1], sizes.grid[3 * v + 2])], sizes.level[v]);
  }
}

TEST(OctreeBuild, RefineForALargeTriangleWithFineVertices) {
  // One big slanted triangle whose vertices ask for level 6: the vertex
  // requests alone refine only around the corners.
  SurfaceMesh s;
  s.xyz = {0.05, 0.1, 0.2, 0.9, 0.15, 0.5, 0.3, 0.95, 0.85};
  s.tris = {0, 1, 2};
  const double bbox[6] = {0, 0, 0, 1, 1, 1};
  const RootCube root = make_root_cube(bbox);
  const std::vector<uint8_t> level = {6, 6, 7};
  std::vector<uint32_t> grid(9);
  for (size_t v = 0; v < 3; ++v) grid_cell(root, s.point(v), &grid[3 * v]);
  LinearOctree t = build_octree(grid, level);
  const size_t before = t.size();
  refine_for_triangles(t, s, root, level);
  EXPECT_GT(t.size(), before);
  expect_tiles_root(t);
  expect_triangles_refined(t, s, root, level);
  // Not over-refined: the triangle's level-6 leaves are not split further
  // away from the level-7 vertex.
  size_t deeper = 0;
  for (size_t i = 0; i < t.size(); ++i) deeper += t.level[i] > 7;
  EXPECT_EQ(deeper, 0u);
}

}  // namespace
}  // namespace partet
