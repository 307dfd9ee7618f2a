// The pipeline of src/pipeline/mesh_command.cpp up to the templates
// (Built) and on to the initial front with gap vertices (FrontCase), on
// one rank, for the front's tests.
#pragma once

#include <string>
#include <utility>

#include "front/gap_vertices.hpp"
#include "front/initial_front.hpp"
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
  add_free_vertices(c.initial, c.b.tree, c.gap.xyz, c.gap.global_ids, c.gap.leaf);
  return c;
}

inline FrontCase front_case(const std::string& name) { return front_case_of(build(name)); }

}  // namespace partet::test
