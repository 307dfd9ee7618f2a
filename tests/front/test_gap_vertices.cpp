// Gap vertices (front/gap_vertices.hpp) and free front vertices: the
// vertices are exactly the too-close and boundary leaf centres inside the
// domain at least the gap from every triangle (checked by brute force over
// all leaves and triangles), with lattice ids disjoint from the template
// vertices'; the front lists them as targets until a tet uses them, no tet
// may contain one, dropping them leaves their leaves; the removals use them
// and the mesh stays valid; the command line reports them and
// --no-gap-vertices leaves them out.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "check/validate.hpp"
#include "core/distance.hpp"
#include "core/predicates.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/gap_vertices.hpp"
#include "front/initial_front.hpp"
#include "front/removal_checks.hpp"
#include "front/treeless_removal.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/inside_index.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "templates/template_mesh.hpp"
#include "front_case.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

double triangle_size(const Built& b, size_t t) {
  const uint32_t* v = &b.surface.tris[3 * t];
  return (b.sizing.size[v[0]] + b.sizing.size[v[1]] + b.sizing.size[v[2]]) / 3;
}

// Brute force: leaf i's centre is a gap vertex.
bool should_be_gap_vertex(const Built& b, const RayParityIndex& parity, size_t i, double gap) {
  if (b.tree.cls[i] != LeafClass::kTooClose && b.tree.cls[i] != LeafClass::kBoundary) return false;
  double lo[3], hi[3], c[3];
  leaf_box(b.tree, b.root, i, lo, hi);
  for (int k = 0; k < 3; ++k) c[k] = (lo[k] + hi[k]) / 2;
  for (size_t t = 0; t < b.surface.num_triangles(); ++t) {
    const uint32_t* v = &b.surface.tris[3 * t];
    const double reach = gap * triangle_size(b, t);
    if (squared_point_triangle_distance(c, b.surface.point(v[0]), b.surface.point(v[1]), b.surface.point(v[2])) <
        reach * reach)
      return false;
  }
  return b.tree.cls[i] == LeafClass::kTooClose || parity.inside(c);
}

TEST(GapVertices, AreTheLeafCentresInsideAndAtLeastTheGapFromTheSurface) {
  size_t boundary = 0;
  for (const char* name : {"good/sphere966.off", "good/eight.off", "good/spool.off"}) {
    const Built b = build(name);
    const GapVertices gap = gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.5);
    ASSERT_GT(gap.size(), 0u) << name;
    ASSERT_EQ(gap.xyz.size(), 3 * gap.size());
    ASSERT_EQ(gap.global_ids.size(), gap.size());
    const RayParityIndex parity(b.surface);
    std::vector<uint32_t> expected;
    for (size_t i = 0; i < b.tree.size(); ++i)
      if (should_be_gap_vertex(b, parity, i, 0.5)) expected.push_back(static_cast<uint32_t>(i));
    EXPECT_EQ(gap.leaf, expected) << name;
    for (size_t k = 0; k < gap.size(); ++k) {
      double lo[3], hi[3];
      leaf_box(b.tree, b.root, gap.leaf[k], lo, hi);
      for (int i = 0; i < 3; ++i) EXPECT_EQ(gap.xyz[3 * k + i], (lo[i] + hi[i]) / 2) << name;
      EXPECT_EQ(leaf_of_point(b.tree, b.root, &gap.xyz[3 * k]), gap.leaf[k]) << name;
      boundary += b.tree.cls[gap.leaf[k]] == LeafClass::kBoundary;
    }
    // Ids: distinct, lattice keys (below 2^63), none a template vertex's.
    std::set<uint64_t> ids(gap.global_ids.begin(), gap.global_ids.end());
    EXPECT_EQ(ids.size(), gap.size()) << name;
    for (uint64_t id : gap.global_ids) EXPECT_LT(id, kSurfaceVertexId) << name;
    for (uint64_t id : b.core.mesh.global_ids) EXPECT_EQ(ids.count(id), 0u) << name;
  }
  EXPECT_GT(boundary, 0u) << "some boundary leaves have centres far enough inside";
}

TEST(GapVertices, AWiderGapKeepsFewerAndNoneWithoutOne) {
  const Built b = build("good/sphere966.off");
  const size_t half = gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.5).size();
  const size_t wide = gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0.8).size();
  EXPECT_LT(wide, half);
  EXPECT_EQ(gap_vertices(b.tree, b.root, b.surface, b.sizing.size, 0).size(), 0u);
}

bool listed_in_leaf(const Front& front, uint32_t v) {
  for (uint32_t u = front.first_vertex(front.vertex_leaf(v)); u != kNoIndex; u = front.next_vertex(u))
    if (u == v) return true;
  return false;
}

TEST(GapVertices, FreeVerticesAreTargetsUntilATetUsesThem) {
  FrontCase c = front_case("good/sphere966.off");
  const size_t n = c.gap.size();
  ASSERT_EQ(c.initial.free_vertices, n);
  const size_t first = c.initial.vertex_leaf.size() - n;
  Front front(c.initial, c.b.tree, c.b.root);
  EXPECT_EQ(front.num_free_vertices(), n);
  for (uint32_t v = static_cast<uint32_t>(first); v < front.num_vertices(); ++v) {
    EXPECT_EQ(front.vertex_uses(v), 1u);
    EXPECT_TRUE(listed_in_leaf(front, v));
    EXPECT_FALSE(front.leaf_front_empty(front.vertex_leaf(v)));
  }
  // The removals take them: a used one is an ordinary front vertex, the
  // tets are a valid partial mesh and none holds a free vertex (a check
  // refuses a tet with a front vertex inside).
  TetMesh out = c.b.core.mesh;
  remove_faces_tree_supported(front, c.b.tree, c.b.root, out);
  EXPECT_LT(front.num_free_vertices(), n / 2);
  std::vector<uint8_t> used(front.num_vertices(), 0);
  for (uint32_t v : out.tets) used[v] = 1;
  size_t taken = 0;
  for (uint32_t v = static_cast<uint32_t>(first); v < front.num_vertices(); ++v) {
    taken += used[v];
    if (!used[v]) {
      EXPECT_EQ(front.vertex_uses(v), 1u) << "vertex " << v << " is free";
    }
  }
  EXPECT_EQ(taken, n - front.num_free_vertices());
  EXPECT_TRUE(validate_mesh(out, nullptr).valid);
  // Dropping the rest takes them off the front.
  std::vector<uint32_t> shrunk;
  const size_t left = front.num_free_vertices();
  EXPECT_EQ(front.drop_free_vertices(shrunk), left);
  EXPECT_EQ(front.num_free_vertices(), 0u);
  for (uint32_t v = static_cast<uint32_t>(first); v < front.num_vertices(); ++v)
    if (!used[v]) {
      EXPECT_EQ(front.vertex_uses(v), 0u);
      EXPECT_FALSE(listed_in_leaf(front, v));
    }
  EXPECT_EQ(shrunk.size(), left);
}

TEST(GapVertices, ATetHoldingAFreeVertexIsRefusedUntilItIsDropped) {
  FrontCase c = front_case("good/sphere966.off");
  Front front(c.initial, c.b.tree, c.b.root);
  const uint32_t v = static_cast<uint32_t>(front.num_vertices() - 1);  // a free vertex
  // The front face nearest v that v sees, and an apex on the ray from its
  // centroid through v, three times as far: v lies inside that tet.
  uint32_t best = kNoIndex;
  double nearest = 1e300;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    const uint32_t* t = front.face(f);
    if (orient3d(front.point(t[0]), front.point(t[1]), front.point(t[2]), front.point(v)) <= 0) continue;
    const double d = squared_point_triangle_distance(front.point(v), front.point(t[0]), front.point(t[1]),
                                                     front.point(t[2]));
    if (d < nearest) {
      nearest = d;
      best = f;
    }
  }
  ASSERT_NE(best, kNoIndex);
  const uint32_t* t = front.face(best);
  double beyond[3];
  for (int k = 0; k < 3; ++k) {
    const double centroid = (front.point(t[0])[k] + front.point(t[1])[k] + front.point(t[2])[k]) / 3;
    beyond[k] = centroid + 3 * (front.point(v)[k] - centroid);
  }
  const uint32_t apex = front.add_vertex(beyond, 0);
  const NearFront none;
  Suspects suspects;
  suspects.vertices = {v};
  RemovalBlocker why;
  EXPECT_EQ(check_removal(front, best, apex, none, &why, &suspects), RemovalVerdict::kVertexInside);
  EXPECT_EQ(why.entity, v);
  std::vector<uint32_t> shrunk;
  front.drop_free_vertices(shrunk);
  EXPECT_EQ(check_removal(front, best, apex, none, &why, &suspects), RemovalVerdict::kValid);
}

TEST(GapVertices, TheRemovalsCloseTheFrontWithThem) {
  for (const char* name : {"good/sphere966.off", "good/eight.off", "good/spool.off"}) {
    FrontCase c = front_case(name);
    TetMesh out = c.b.core.mesh;
    ASSERT_EQ(close_front(c, out), 0u) << name;
    const ValidationResult r = validate_mesh(out, &c.b.surface);
    EXPECT_TRUE(r.valid) << name << ": " << format_text(r);
  }
}

TEST(GapVertices, CommandLineReportsThemAndCanLeaveThemOut) {
  const std::string dir = scratch_dir("gap_vertices_cli");
  const std::string in = data_path("good/sphere966.off");
  // The removals take gap vertices as targets when they fill the gap
  // themselves: without the Delaunay fill, which uses them all.
  auto on = run_partet(in + " -o " + dir + "/on.vtu -q --no-delaunay-fill --report " + dir + "/on.json");
  ASSERT_EQ(on.exit_code, 0) << on.output;
  auto again = run_partet(in + " -o " + dir + "/again.vtu -q --no-delaunay-fill");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  auto off = run_partet(in + " -o " + dir + "/off.vtu -q --no-gap-vertices --no-delaunay-fill --report " + dir + "/off.json");
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_EQ(read_text(dir + "/on.vtu"), read_text(dir + "/again.vtu"));
  EXPECT_EQ(run_partet("check " + dir + "/on.vtu --surface " + in).exit_code, 0);
  const auto step = [&](const std::string& file, const char* name) {
    const nlohmann::json report = nlohmann::json::parse(read_text(dir + "/" + file));
    for (const auto& s : report["steps"])
      if (s["name"] == name) return nlohmann::json(s["counts"]);
    return nlohmann::json();
  };
  const size_t given = step("on.json", "initial front")["gap vertices"].get<size_t>();
  EXPECT_GT(given, 0u);
  const size_t used = step("on.json", "face removals (tree)")["gap vertices used"].get<size_t>();
  EXPECT_GT(used, given / 2);
  EXPECT_LE(used, given);
  EXPECT_EQ(step("off.json", "initial front")["gap vertices"].get<size_t>(), 0u);
  // Every vertex of the written mesh is used: dropped gap vertices are gone.
  EXPECT_TRUE(validate_mesh(read_volume_file(dir + "/on.vtu"), nullptr).valid);
  const TetMesh mesh = read_volume_file(dir + "/on.vtu");
  std::vector<uint8_t> used_vertex(mesh.num_vertices(), 0);
  for (uint32_t v : mesh.tets) used_vertex[v] = 1;
  EXPECT_EQ(std::count(used_vertex.begin(), used_vertex.end(), 0), 0);
}

}  // namespace
}  // namespace partet::test
