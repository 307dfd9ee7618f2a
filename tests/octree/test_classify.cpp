// Leaf classification: boundary leaves are exactly those meeting a triangle,
// interior / too-close leaves are inside and outside leaves outside (checked
// on sample points by brute-force exact parity over all triangles), the
// too-close rule holds leaf by leaf, and cavities, disjoint bodies and the
// corpus classify as expected.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>

#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/box_triangle.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/inside_index.hpp"
#include "octree/sizing.hpp"
#include "octree_test_util.hpp"
#include "surface/diagnose.hpp"
#include "surface/shell_nesting.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::append_surface;
using test::data_path;
using test::placed_box;

struct Classified {
  SurfaceMesh surface;
  RootCube root;
  VertexSizing sizes;
  LinearOctree tree;
  LeafTriangles bins;
  ClassCounts counts;
};

// The whole single-rank pipeline up to classification.
Classified classify_surface(SurfaceMesh s, const SizingOptions& sizing = {}, const ClassifyOptions& options = {}) {
  Classified c;
  const SurfaceSummary sum = diagnose_surface(s, "test");
  c.surface = std::move(s);
  c.root = make_root_cube(sum.bbox);
  c.sizes = size_vertices(c.surface, c.root, sizing);
  c.tree = build_octree(c.sizes.grid, c.sizes.level);
  refine_for_triangles(c.tree, c.surface, c.root, c.sizes.level);
  balance_octree(c.tree);
  c.bins = bin_triangles(c.tree, c.surface, c.root);
  c.counts = classify_leaves(c.tree, c.surface, c.root, c.sizes.size, c.bins, options);
  return c;
}

bool brute_inside(const SurfaceMesh& s, const double* p) {
  std::vector<uint32_t> all(s.num_triangles());
  std::iota(all.begin(), all.end(), 0u);
  double far = 1;
  for (size_t v = 0; v < s.num_vertices(); ++v)
    for (int i = 0; i < 3; ++i) far = std::max(far, 4 * std::fabs(s.point(v)[i] - p[i]));
  return point_inside_shell(s, all, p, 2 * far);
}

// Checks every leaf against brute force: boundary iff its closed box meets
// a triangle; `samples` random points (and the centre) of every other leaf
// on the right side; too-close leaves within the gap of some triangle and
// interior leaves of none.
void expect_consistent(const Classified& c, int samples, double too_close = ClassifyOptions{}.too_close) {
  const SurfaceMesh& s = c.surface;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0.01, 0.99);
  size_t counted[6] = {0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < c.tree.size(); ++i) {
    const LeafClass cls = c.tree.cls[i];
    ++counted[static_cast<int>(cls)];
    ASSERT_NE(cls, LeafClass::kUnclassified);
    double lo[3], hi[3];
    leaf_box(c.tree, c.root, i, lo, hi);
    bool meets = false;
    for (size_t t = 0; t < s.num_triangles() && !meets; ++t) {
      const uint32_t* v = &s.tris[3 * t];
      meets = box_meets_triangle(lo, hi, s.point(v[0]), s.point(v[1]), s.point(v[2]));
    }
    bool near = false;
    const double h = hi[0] - lo[0];
    for (size_t t = 0; t < s.num_triangles() && !near && !meets && cls != LeafClass::kOutside; ++t) {
      const uint32_t* v = &s.tris[3 * t];
      const double size = (c.sizes.size[v[0]] + c.sizes.size[v[1]] + c.sizes.size[v[2]]) / 3;
      const double cap = octant_edge(c.bins.coarsest[t]) * c.root.unit;
      const double gap = too_close * std::max(size, std::min(0.5 * h, cap));
      near = box_triangle_closer_than(lo, hi, s.point(v[0]), s.point(v[1]), s.point(v[2]), gap);
    }
    ASSERT_EQ(meets, cls == LeafClass::kBoundary) << "leaf " << i;
    if (meets) continue;
    if (cls == LeafClass::kTooClose) {
      EXPECT_TRUE(near) << "leaf " << i;
    }
    if (cls == LeafClass::kInterior) {
      EXPECT_FALSE(near) << "leaf " << i;
    }
    const bool inside = cls != LeafClass::kOutside;
    for (int k = 0; k <= samples; ++k) {
      double p[3];
      for (int a = 0; a < 3; ++a) p[a] = k == 0 ? 0.5 * (lo[a] + hi[a]) : lo[a] + unit(rng) * (hi[a] - lo[a]);
      ASSERT_EQ(brute_inside(s, p), inside) << "leaf " << i << " sample " << k;
    }
  }
  EXPECT_EQ(counted[static_cast<int>(LeafClass::kBoundary)], c.counts.boundary);
  EXPECT_EQ(counted[static_cast<int>(LeafClass::kTooClose)], c.counts.too_close);
  EXPECT_EQ(counted[static_cast<int>(LeafClass::kInterior)], c.counts.interior);
  EXPECT_EQ(counted[static_cast<int>(LeafClass::kOutside)], c.counts.outside);
}

TEST(ClassifyInsideIndex, MatchesBruteForceParity) {
  for (const char* name : {"cube.off", "tripod.off", "spool.off", "lever.stl"}) {
    SCOPED_TRACE(name);
    SurfaceMesh s = read_surface_file(data_path(std::string("good/") + name));
    const SurfaceSummary sum = diagnose_surface(s, name);
    const RayParityIndex index(s);
    std::mt19937 rng(4);
    int inside = 0;
    for (int k = 0; k < 400; ++k) {
      double p[3];
      for (int i = 0; i < 3; ++i) {
        const double ext = sum.bbox[3 + i] - sum.bbox[i];
        p[i] = std::uniform_real_distribution<double>(sum.bbox[i] - 0.2 * ext, sum.bbox[3 + i] + 0.2 * ext)(rng);
      }
      const bool got = index.inside(p);
      ASSERT_EQ(got, brute_inside(s, p)) << k;
      inside += got;
    }
    EXPECT_GT(inside, 0);
  }
}

TEST(ClassifyInsideIndex, GrazingRaysFallBack) {
  // Points on the planes of the box's faces and diagonals (seen from the
  // ray direction, many rays pass through edges and vertices).
  const SurfaceMesh s = placed_box(0, 0, 0, 1, 4);
  const RayParityIndex index(s);
  for (int i = -2; i <= 10; ++i)
    for (int j = -2; j <= 10; ++j)
      for (int k = -2; k <= 10; ++k) {
        const double p[3] = {i / 8.0 + 1.0 / 16, j / 8.0, k / 8.0 + 1.0 / 16};
        if (p[1] == 0 || p[1] == 1) continue;  // on the surface
        EXPECT_EQ(index.inside(p), brute_inside(s, p));
      }
}

TEST(ClassifyBox, LeavesAreConsistent) {
  const Classified c = classify_surface(placed_box(0.5, -0.25, 1, 2, 6));
  EXPECT_GT(c.counts.boundary, 0u);
  EXPECT_GT(c.counts.interior, 0u);
  EXPECT_GT(c.counts.outside, 0u);
  EXPECT_EQ(c.counts.groups, 2u);  // the inside and the outside
  expect_consistent(c, 2);
}

TEST(ClassifyBox, NoTooCloseWhenDisabledAndMoreWhenWider) {
  ClassifyOptions none;
  none.too_close = 0;
  const Classified off = classify_surface(placed_box(0, 0, 0, 1, 6), {}, none);
  EXPECT_EQ(off.counts.too_close, 0u);
  expect_consistent(off, 1, 0);
  ClassifyOptions wide;
  wide.too_close = 1.5;
  const Classified more = classify_surface(placed_box(0, 0, 0, 1, 6), {}, wide);
  const Classified normal = classify_surface(placed_box(0, 0, 0, 1, 6));
  EXPECT_GT(more.counts.too_close, normal.counts.too_close);
  EXPECT_EQ(off.counts.interior, normal.counts.interior + normal.counts.too_close);
  expect_consistent(more, 1, 1.5);
}

TEST(ClassifyCavity, CavityLeavesAreOutside) {
  SurfaceMesh s = placed_box(0, 0, 0, 6, 12);
  append_surface(s, placed_box(2, 2, 2, 2, 4));  // diagnosis turns it into a cavity
  const Classified c = classify_surface(std::move(s));
  EXPECT_GT(c.counts.interior, 0u);
  EXPECT_GE(c.counts.groups, 3u);
  // The cavity's centre is in an outside leaf; a point in the wall interior.
  uint32_t g[3];
  const double centre[3] = {3, 3, 3};
  grid_cell(c.root, centre, g);
  EXPECT_EQ(c.tree.cls[c.tree.locate(g[0], g[1], g[2])], LeafClass::kOutside);
  const double wall[3] = {1, 3, 3};
  grid_cell(c.root, wall, g);
  const LeafClass w = c.tree.cls[c.tree.locate(g[0], g[1], g[2])];
  EXPECT_TRUE(w == LeafClass::kInterior || w == LeafClass::kTooClose);
  expect_consistent(c, 1);
}

TEST(ClassifyTwoBodies, BothAreFilled) {
  SurfaceMesh s = placed_box(0, 0, 0, 1, 6);
  append_surface(s, placed_box(2.5, 0.5, 0.25, 1, 6));
  SizingOptions finer;
  finer.size_factor = 0.5;
  const Classified c = classify_surface(std::move(s), finer);
  size_t first = 0, second = 0;
  for (size_t i = 0; i < c.tree.size(); ++i) {
    if (c.tree.cls[i] != LeafClass::kInterior) continue;
    double lo[3], hi[3];
    leaf_box(c.tree, c.root, i, lo, hi);
    (lo[0] < 1.5 ? first : second)++;
  }
  EXPECT_GT(first, 0u);
  EXPECT_GT(second, 0u);
  expect_consistent(c, 1);
}

// "Big enough": an enclosed volume of at least 1000 cubes of the mean target
// size (a ball about 12 sizes across); below that the gap left for the front
// can take the whole volume.
TEST(ClassifyCorpus, EverySurfaceClassifies) {
  for (const auto& entry : std::filesystem::directory_iterator(data_path("good"))) {
    for (double factor : {1.0, 0.25}) {
      SCOPED_TRACE(entry.path().string() + " size factor " + std::to_string(factor));
      SurfaceMesh s = read_surface_file(entry.path().string());
      const double volume = diagnose_surface(s, "test").volume;
      SizingOptions sizing;
      sizing.size_factor = factor;
      const Classified c = classify_surface(std::move(s), sizing);
      EXPECT_GT(c.counts.boundary, 0u);
      double mean = 0;
      for (double x : c.sizes.size) mean += x / c.sizes.size.size();
      if (volume >= 1000 * mean * mean * mean) {
        EXPECT_GT(c.counts.interior, 0u);
        EXPECT_GT(c.counts.outside, 0u);
      }
      if (c.tree.size() < 3000) expect_consistent(c, 0);
    }
  }
}

TEST(ClassifyCorpus, Deterministic) {
  const Classified a = classify_surface(read_surface_file(data_path("good/lever.stl")));
  const Classified b = classify_surface(read_surface_file(data_path("good/lever.stl")));
  EXPECT_EQ(a.tree.key, b.tree.key);
  EXPECT_EQ(a.tree.cls, b.tree.cls);
}

}  // namespace
}  // namespace partet
