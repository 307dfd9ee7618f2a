// Face removals with new vertices after tree-supported removals on the real
// pipeline: the icosahedron and octahedron fronts close completely and fill
// the surface; on sphere966 and blobby-shuffled the front shrinks and the
// core plus all tets stays a valid partial mesh; new vertices carry ids in
// their own space; two runs give the same mesh.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "check/validate.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "front/steiner_removal.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

struct Meshed {
  SurfaceMesh surface;
  TetMesh out;
  size_t tree_left = 0;  // faces left by tree-supported removals
  size_t faces_left = 0;
  size_t front_vertices = 0;  // before new vertices
};

// The pipeline of src/pipeline/mesh_command.cpp through both removal steps.
Meshed mesh_file(const std::string& name) {
  Meshed r;
  r.surface = read_surface_file(data_path(name));
  SurfaceSummary summary = diagnose_surface(r.surface, name);
  RootCube root = make_root_cube(summary.bbox);
  VertexSizing sizing = size_vertices(r.surface, root, SizingOptions{});
  LinearOctree tree = build_octree(sizing.grid, sizing.level);
  refine_for_triangles(tree, r.surface, root, sizing.level);
  balance_octree(tree);
  classify_leaves(tree, r.surface, root, sizing.size);
  TemplateCore core = template_interior(tree, root);
  InitialFront initial = make_initial_front(tree, root, core, r.surface);
  Front front(initial, tree, root);
  r.out = core.mesh;
  r.tree_left = remove_faces_tree_supported(front, tree, root, r.out).faces_left;
  r.front_vertices = front.num_vertices();
  RemovalCounts n = remove_faces_with_new_vertices(front, tree, root, r.out);
  r.faces_left = n.faces_left;
  EXPECT_EQ(n.faces_left, front.num_alive_faces());
  EXPECT_EQ(r.out.num_vertices(), front.num_vertices());
  if (!r.out.global_ids.empty()) {
    EXPECT_EQ(r.out.global_ids.size(), r.out.num_vertices());
    for (size_t v = r.front_vertices; v < r.out.global_ids.size(); ++v)
      EXPECT_EQ(r.out.global_ids[v] & kSteinerVertexId, kSteinerVertexId) << name << " vertex " << v;
    for (size_t v = 0; v < r.front_vertices; ++v)
      EXPECT_NE(r.out.global_ids[v] & kSteinerVertexId, kSteinerVertexId) << name << " vertex " << v;
  }
  std::printf("[ steiner  ] %-28s tree left %zu -> %zu faces, %zu new vertices\n", name.c_str(), r.tree_left,
              r.faces_left, r.out.num_vertices() - r.front_vertices);
  ValidationResult partial = validate_mesh(r.out, nullptr);
  EXPECT_TRUE(partial.valid) << name << ": " << format_text(partial);
  if (r.faces_left == 0) {
    ValidationResult full = validate_mesh(r.out, &r.surface);
    EXPECT_TRUE(full.valid) << name << ": " << format_text(full);
  }
  return r;
}

TEST(FrontSteiner, SmallFrontsClose) {
  for (const char* name : {"good/icosahedron.off", "good/octahedron.off"}) {
    Meshed r = mesh_file(name);
    EXPECT_EQ(r.faces_left, 0u) << name;
  }
  EXPECT_GT(mesh_file("good/icosahedron.off").tree_left, 0u);
}

TEST(FrontSteiner, LargerFrontsShrinkAndStayValid) {
  for (const char* name : {"good/sphere966.off", "fixable/blobby-shuffled.off"}) {
    Meshed r = mesh_file(name);
    EXPECT_LT(r.faces_left, r.tree_left) << name;
  }
}

TEST(FrontSteiner, Deterministic) {
  Meshed a = mesh_file("good/sphere966.off");
  Meshed b = mesh_file("good/sphere966.off");
  EXPECT_EQ(a.out.tets, b.out.tets);
  EXPECT_EQ(a.out.xyz, b.out.xyz);
  EXPECT_EQ(a.out.global_ids, b.out.global_ids);
}

}  // namespace
}  // namespace partet::test
