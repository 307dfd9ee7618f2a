// Offset gap vertices (front/offset_vertices.hpp): the points added are
// exactly the offset points that the rules keep, checked by brute force
// over every triangle, template vertex, leaf centre and earlier offset
// point; their ids name their surface vertices; on a thin CAD part (lever)
// they add vertices where the leaf centres leave none, the meshes stay valid,
// the command line reports them and --no-offset-vertices leaves them out.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "check/validate.hpp"
#include "core/distance.hpp"
#include "front/gap_vertices.hpp"
#include "front/initial_front.hpp"
#include "front/offset_vertices.hpp"
#include "octree/inside_index.hpp"
#include "front_case.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

double squared(const double* a, const double* b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

// Brute force: the offset point of every surface vertex that the rules of
// offset_vertices.hpp keep, in vertex order; `lattice` holds the template
// vertices and the leaf centres (3 doubles each).
std::vector<std::vector<double>> expected_offsets(const Built& b, const std::vector<double>& lattice, double gap) {
  const SurfaceMesh& s = b.surface;
  std::vector<double> normal(3 * s.num_vertices(), 0.0);
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    const uint32_t* v = &s.tris[3 * t];
    const double *p = s.point(v[0]), *q = s.point(v[1]), *r = s.point(v[2]);
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) normal[3 * v[k] + i] += n[i];
  }
  const RayParityIndex parity(s);
  std::vector<std::vector<double>> kept;
  for (uint32_t v = 0; v < s.num_vertices(); ++v) {
    const double* n = &normal[3 * v];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0)) continue;
    const double size = b.sizing.size[v];
    std::vector<double> p(3);
    for (int i = 0; i < 3; ++i) p[i] = s.point(v)[i] - kOffsetHeight * size / length * n[i];
    const LeafClass cls = b.tree.cls[leaf_of_point(b.tree, b.root, p.data())];
    if (cls != LeafClass::kBoundary && cls != LeafClass::kTooClose) continue;
    bool ok = true;
    const double clear = gap * size, block = kOffsetBlock * size, spacing = kOffsetSpacing * size;
    for (size_t t = 0; t < s.num_triangles() && ok; ++t) {
      const uint32_t* w = &s.tris[3 * t];
      ok = squared_point_triangle_distance(p.data(), s.point(w[0]), s.point(w[1]), s.point(w[2])) >= clear * clear;
    }
    for (size_t i = 0; i < lattice.size() / 3 && ok; ++i) ok = squared(p.data(), &lattice[3 * i]) >= block * block;
    for (const auto& q : kept) ok = ok && squared(p.data(), q.data()) >= spacing * spacing;
    if (ok && parity.inside(p.data())) kept.push_back(p);
  }
  return kept;
}

TEST(OffsetVertices, AreTheOffsetPointsTheRulesKeep) {
  size_t total = 0;
  for (const char* name : {"good/sphere966.off", "good/part.off", "good/spool.off", "good/lever.stl"}) {
    const Built b = build(name);
    const InitialFront front = make_initial_front(b.tree, b.root, b.core, b.surface);
    GapVertices gap = gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.5);
    const size_t centres = gap.size();
    std::vector<double> lattice(front.xyz.begin(), front.xyz.begin() + 3 * front.core_vertices);
    lattice.insert(lattice.end(), gap.xyz.begin(), gap.xyz.end());
    const size_t added = add_offset_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.5, front, gap);
    ASSERT_EQ(gap.size(), centres + added) << name;
    ASSERT_EQ(gap.xyz.size(), 3 * gap.size()) << name;
    ASSERT_EQ(gap.global_ids.size(), gap.size()) << name;
    const auto expected = expected_offsets(b, lattice, 0.5);
    ASSERT_EQ(added, expected.size()) << name;
    std::set<uint64_t> ids;
    for (size_t k = 0; k < added; ++k) {
      const size_t i = centres + k;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(gap.xyz[3 * i + c], expected[k][c]) << name << " offset " << k;
      const uint64_t id = gap.global_ids[i];
      EXPECT_EQ(id & ~uint64_t{0xffffffff}, kOffsetVertexId) << name;
      EXPECT_LT(id & 0xffffffff, b.surface.num_vertices()) << name;
      ids.insert(id);
      EXPECT_EQ(gap.leaf[i], leaf_of_point(b.tree, b.root, &gap.xyz[3 * i])) << name;
    }
    EXPECT_EQ(ids.size(), added) << name;
    total += added;
  }
  EXPECT_GT(total, 0u);
}

TEST(OffsetVertices, NoneWithoutAGap) {
  const Built b = build("good/spool.off");
  const InitialFront front = make_initial_front(b.tree, b.root, b.core, b.surface);
  GapVertices gap;
  EXPECT_EQ(add_offset_vertices(b.tree, b.root, b.surface, b.sizing.size, 0, front, gap), 0u);
  EXPECT_EQ(gap.size(), 0u);
}

// Lever's thin walls hold no leaf centre far enough from both sides; the
// offset points fill in there, and the removals close the front with them.
TEST(OffsetVertices, FillThinWallsAndTheRemovalsCloseWithThem) {
  const Built b = build("good/lever.stl");
  EXPECT_EQ(gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.5).size(), 0u);
  FrontCase c = front_case("good/lever.stl");
  EXPECT_GT(c.gap.size(), 10u);
  TetMesh out = c.b.core.mesh;
  ASSERT_EQ(close_front(c, out), 0u);
  const ValidationResult r = validate_mesh(out, &c.b.surface);
  EXPECT_TRUE(r.valid) << format_text(r);
}

TEST(OffsetVertices, CommandLineReportsThemAndCanLeaveThemOut) {
  const std::string dir = scratch_dir("offset_vertices_cli");
  const std::string in = data_path("good/lever.stl");
  // Meshes lever as `name` with `extra`, checks the mesh, and gives the
  // initial front's counts.
  const auto mesh = [&](const std::string& name, const std::string& extra) {
    auto r = run_partet(in + " -o " + dir + "/" + name + ".vtu -q --report " + dir + "/" + name + ".json " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(run_partet("check " + dir + "/" + name + ".vtu --surface " + in).exit_code, 0);
    return report_step(nlohmann::json::parse(read_text(dir + "/" + name + ".json")), "initial front")["counts"];
  };
  const auto on = mesh("on", ""), off = mesh("off", "--no-offset-vertices");
  EXPECT_GT(on["offset vertices"].get<int>(), 10);
  EXPECT_EQ(off["offset vertices"].get<int>(), 0);
  EXPECT_EQ(on["gap vertices"].get<int>(), off["gap vertices"].get<int>() + on["offset vertices"].get<int>());
}

}  // namespace
}  // namespace partet::test
