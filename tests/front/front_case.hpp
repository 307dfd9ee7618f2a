// The pipeline of src/pipeline/mesh_command.cpp up to the templates
// (Built), on to the initial front with gap vertices, leaf centres and
// offset ones (FrontCase), and the
// removals that close it (close_front), on one rank, for the front's
// tests.
#pragma once

#include <string>
#include <utility>

#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/gap_vertices.hpp"
#include "front/offset_vertices.hpp"
#include "front/initial_front.hpp"
#include "front/treeless_removal.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet::test {

struct Built {
  SurfaceMesh surface;
  RootCube root;
  VertexSizing sizing;
  LinearOctree tree;
  TemplateCore core;
};

// `surface` (named `name` in messages) diagnosed, its octree built,
// classified and templated.
inline Built build_surface(SurfaceMesh surface, const std::string& name) {
  Built b;
  b.surface = std::move(surface);
  const SurfaceSummary summary = diagnose_surface(b.surface, name);
  b.root = make_root_cube(summary.bbox);
  b.sizing = size_vertices(b.surface, b.root, {});
  b.tree = build_octree(b.sizing.grid, b.sizing.level);
  refine_for_triangles(b.tree, b.surface, b.root, b.sizing.level);
  balance_octree(b.tree);
  classify_leaves(b.tree, b.surface, b.root, b.sizing.size);
  b.core = template_interior(b.tree, b.root);
  return b;
}

// The surface `name` under data/, built.
inline Built build(const std::string& name) { return build_surface(read_surface_file(data_path(name)), name); }

struct FrontCase {
  Built b;
  InitialFront initial;
  GapVertices gap;
};

inline FrontCase front_case_of(Built built) {
  FrontCase c{std::move(built), {}, {}};
  c.initial = make_initial_front(c.b.tree, c.b.root, c.b.core, c.b.surface);
  c.gap = gap_vertices(c.b.tree, c.b.root, c.b.surface, c.b.sizing.size, 0.5);
  add_offset_vertices(c.b.tree, c.b.root, c.b.surface, c.b.sizing.size, 0.5, c.initial, c.gap);
  add_free_vertices(c.initial, c.b.tree, c.gap.xyz, c.gap.global_ids, c.gap.leaf);
  return c;
}

inline FrontCase front_case(const std::string& name) { return front_case_of(build(name)); }

// c.initial closed by the removals as the pipeline runs them on one rank
// (tree-supported, free vertices dropped, tree-less); `out` holds the tets
// made before (the core's or the Delaunay fill's) and gets theirs. The
// faces left.
inline size_t close_front(FrontCase& c, TetMesh& out) {
  Front front(c.initial, c.b.tree, c.b.root);
  RemovalMemo memo;
  remove_faces_tree_supported(front, c.b.tree, c.b.root, out, {}, nullptr, &memo);
  drop_free_vertices(front, c.b.tree);
  memo.renumber(front.compact());
  return remove_faces_treeless(front, c.b.tree, c.b.root, out, {}, &memo).faces_left;
}

}  // namespace partet::test
