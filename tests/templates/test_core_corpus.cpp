// End to end up to the initial front, as the pipeline runs it (size the
// vertices, build and refine the octree, 2:1 balance, classify, make the
// interior manifold, template, initial front), on every surface of
// data/good at size factors 1, 1/2 and 1/4 and on generated multi-shell
// surfaces (a box with a box cavity, two disjoint boxes, a box with three
// cavities) at factors 1 to 1/16. Each time the core is a valid conforming mesh of exactly the
// interior leaves (validate_mesh, exact lattice volume: template_trees.hpp)
// and the front is closed and consistently oriented: every edge used by
// exactly two faces, in opposite directions, and the faces around every
// vertex form one fan, with the surface sheet and the core sheet sharing
// no vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "front/initial_front.hpp"
#include "front_topology.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "template_trees.hpp"
#include "templates/manifold_core.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

using test::append;
using test::shifted_box;

struct CorpusTotals {
  size_t cases = 0, leaves = 0, interior = 0, demoted = 0, front_faces = 0;
};

// The pipeline's steps on a diagnosed surface, and the checks above.
void check_core(const SurfaceMesh& surface, const SurfaceSummary& summary, double factor,
                const std::string& label, CorpusTotals& totals) {
  const RootCube root = make_root_cube(summary.bbox);
  SizingOptions sizing_options;
  sizing_options.size_factor = factor;
  const VertexSizing sizing = size_vertices(surface, root, sizing_options);
  LinearOctree tree = build_octree(sizing.grid, sizing.level);
  refine_for_triangles(tree, surface, root, sizing.level);
  balance_octree(tree);
  classify_leaves(tree, surface, root, sizing.size);
  const ManifoldCoreCounts counts = make_core_manifold(tree);
  const TemplateCore core = template_interior(tree, root);
  const InitialFront front = make_initial_front(tree, root, core, surface);

  expect_core_conforms(tree, core, label);
  const FrontTopology t = front_topology(front.faces);
  EXPECT_EQ(t.bad_edges, 0u) << label;
  EXPECT_EQ(t.pinched, 0u) << label;
  EXPECT_EQ(front.surface_faces, surface.num_triangles()) << label;
  size_t crossing = 0;
  for (size_t f = 0; f < front.num_faces(); ++f) {
    const bool on_surface = f < front.surface_faces;
    for (int k = 0; k < 3; ++k)
      crossing += (front.faces[3 * f + k] >= front.core_vertices) != on_surface;
  }
  EXPECT_EQ(crossing, 0u) << label << ": a face with vertices of the other sheet";

  std::printf("%-24s x%-6g %7zu leaves %6zu interior %4zu demoted (%zu repairs, %zu rounds) "
              "%6zu faces\n",
              label.c_str(), factor, tree.size(), counts.interior, counts.demoted, counts.repaired,
              counts.rounds, front.num_faces());
  ++totals.cases;
  totals.leaves += tree.size();
  totals.interior += counts.interior;
  totals.demoted += counts.demoted;
  totals.front_faces += front.num_faces();
}

void check_factors(SurfaceMesh surface, const std::string& label,
                   const std::vector<double>& factors, CorpusTotals& totals) {
  const SurfaceSummary summary = diagnose_surface(surface, label);
  for (double factor : factors) {
    check_core(surface, summary, factor, label, totals);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(CoreCorpus, GoodSurfaces) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(data_path("good")))
    files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  CorpusTotals totals;
  for (const std::string& file : files) {
    check_factors(read_surface_file(file), std::filesystem::path(file).filename().string(),
                  {1.0, 0.5, 0.25}, totals);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("corpus: %zu cases, %zu leaves, %zu interior, %zu demoted, %zu front faces\n",
              totals.cases, totals.leaves, totals.interior, totals.demoted, totals.front_faces);
  EXPECT_EQ(totals.cases, 3 * files.size());
  EXPECT_GT(totals.interior, 0u);
  EXPECT_GT(totals.demoted, 0u);  // the finer cases need the manifold pass
}

TEST(CoreCorpus, MultiShellSurfaces) {
  // Twelve triangles per box: the finer factors put a core between the shells.
  const std::vector<double> factors = {1.0, 0.5, 0.25, 0.125, 0.0625};
  CorpusTotals totals;
  SurfaceMesh cavity = shifted_box(0, 4);
  append(cavity, shifted_box(1, 2));
  check_factors(cavity, "box with a cavity", factors, totals);

  SurfaceMesh two = shifted_box(0, 1);
  append(two, shifted_box(1.5, 1));
  check_factors(two, "two boxes", factors, totals);

  SurfaceMesh three = shifted_box(0, 10);
  append(three, shifted_box(1, 2));
  append(three, shifted_box(4, 2));
  append(three, shifted_box(7, 2.5));
  check_factors(three, "box with three cavities", factors, totals);
  EXPECT_EQ(totals.cases, 3 * factors.size());
  EXPECT_GT(totals.interior, 0u);
}

}  // namespace
}  // namespace partet::test
