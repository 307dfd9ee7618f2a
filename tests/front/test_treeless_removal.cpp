// Tree-less face removals after tree-supported removals on the real
// pipeline: every surface of data/ (good and fixable) and generated
// multi-shell bodies close completely, and the result with the surface is
// a valid mesh; new vertices carry ids in their own space; two runs give
// the same mesh; the short-growth attempt closes a CAD part in fewer rounds
// than the default; when those leave faces, a rescue strategy closes them
// (starting over, or going on from a few stuck faces) or the best attempt
// is kept. Also the pieces: the deepest
// kernel point of a front, the reopening of a tet (Front::remove_tet) and
// the tet behind a face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <string>
#include <utility>

#include "check/validate.hpp"
#include "core/compact_mesh.hpp"
#include "core/predicates.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "front/kernel_point.hpp"
#include "front/tet_incidence.hpp"
#include "front/treeless_removal.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "surface/midpoint_refine.hpp"
#include "templates/manifold_core.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

// The pipeline of src/pipeline/mesh_command.cpp up to the initial front.
struct Started {
  SurfaceMesh surface;
  RootCube root;
  LinearOctree tree;
  TemplateCore core;
  InitialFront initial;
};

Started start(SurfaceMesh surface, const std::string& name) {
  Started s;
  s.surface = std::move(surface);
  SurfaceSummary summary = diagnose_surface(s.surface, name);
  s.root = make_root_cube(summary.bbox);
  VertexSizing sizing = size_vertices(s.surface, s.root, SizingOptions{});
  s.tree = build_octree(sizing.grid, sizing.level);
  refine_for_triangles(s.tree, s.surface, s.root, sizing.level);
  balance_octree(s.tree);
  classify_leaves(s.tree, s.surface, s.root, sizing.size);
  make_core_manifold(s.tree);
  s.core = template_interior(s.tree, s.root);
  s.initial = make_initial_front(s.tree, s.root, s.core, s.surface);
  return s;
}

struct Meshed {
  TetMesh out;
  size_t faces_left = 0;
  TreelessCounts counts;
};

// Both removal steps, then the checks every result must pass.
Meshed mesh_surface(SurfaceMesh surface, const std::string& name, const RemovalOptions& options = {}) {
  Started s = start(std::move(surface), name);
  Front front(s.initial, s.tree, s.root);
  Meshed r;
  r.out = s.core.mesh;
  const size_t tree_left = remove_faces_tree_supported(front, s.tree, s.root, r.out, options).faces_left;
  const size_t front_vertices = front.num_vertices();
  r.counts = remove_faces_treeless(front, s.tree, s.root, r.out, options);
  r.faces_left = r.counts.faces_left;
  EXPECT_EQ(r.faces_left, front.num_alive_faces());
  EXPECT_EQ(r.out.num_vertices(), front.num_vertices());
  if (!r.out.global_ids.empty()) {
    EXPECT_EQ(r.out.global_ids.size(), r.out.num_vertices());
    for (size_t v = front_vertices; v < r.out.global_ids.size(); ++v)
      EXPECT_EQ(r.out.global_ids[v] & kSteinerVertexId, kSteinerVertexId) << name << " vertex " << v;
    for (size_t v = 0; v < front_vertices; ++v)
      EXPECT_NE(r.out.global_ids[v] & kSteinerVertexId, kSteinerVertexId) << name << " vertex " << v;
  }
  std::printf("[ treeless ] %-28s %zu -> %zu faces, %zu new vertices, %zu tets deleted, %zu star fills\n",
              name.c_str(), tree_left, r.faces_left, r.counts.vertices_added, r.counts.tets_deleted,
              r.counts.star_fills);
  ValidationResult partial = validate_mesh(r.out, nullptr);
  EXPECT_TRUE(partial.valid) << name << ": " << format_text(partial);
  if (r.faces_left == 0) {
    r.out.tris = s.surface.tris;
    for (uint32_t& v : r.out.tris) v += static_cast<uint32_t>(s.initial.core_vertices);
    drop_unused_vertices(r.out);
    ValidationResult full = validate_mesh(r.out, &s.surface);
    EXPECT_TRUE(full.valid) << name << ": " << format_text(full);
    EXPECT_EQ(full.unused_vertices, 0u) << name;
  }
  return r;
}

Meshed mesh_file(const std::string& name, const RemovalOptions& options = {}) {
  return mesh_surface(read_surface_file(data_path(name)), name, options);
}

TEST(FrontTreeless, EveryDataSurfaceCloses) {
  for (const char* name :
       {"good/cross.off", "good/cube-meshed.off", "good/cube.off", "good/dragknob.off", "good/eight.off",
        "good/ellipsoid.off", "good/hedra.off", "good/icosahedron.off", "good/joint.off", "good/lever.stl",
        "good/octahedron.off", "good/part.off", "good/pipe.off", "good/sphere966.off", "good/spool.off",
        "good/star.off", "good/tripod.off", "good/u.off", "fixable/blobby-shuffled.off", "fixable/tet-shuffled.off",
        "hard/pinion.off"})
    EXPECT_EQ(mesh_file(name).faces_left, 0u) << name;
}

// run_mesh's last attempt: both removal steps with targets best shape
// first (face_removal.hpp) close the data surfaces too.
TEST(FrontTreeless, TheShapeOrderClosesToo) {
  RemovalOptions shape;
  shape.shape_order = true;
  for (const char* name : {"good/cross.off", "good/joint.off", "good/lever.stl", "good/part.off", "hard/pinion.off"})
    EXPECT_EQ(mesh_file(name, shape).faces_left, 0u) << name;
}

// Refined once, part has flat cavities between exactly coplanar surface
// triangles and the tets above them: they close only when the tets behind
// all the cavity's non-surface faces are reopened (they cycled before).
TEST(FrontTreeless, RefinedSurfacesClose) {
  for (const char* name : {"good/part.off", "good/joint.off"}) {
    const Meshed r = mesh_surface(refine_midpoints(read_surface_file(data_path(name))), std::string(name) + " r1");
    EXPECT_EQ(r.faces_left, 0u) << name;
    EXPECT_LT(r.counts.rounds, 50u) << name;
  }
}

// joint refined twice, the default strategy alone with stall_rounds 1:
// it stops after a round without a smaller front, stalled, and the call
// leaves a valid partial mesh; sphere966 closes unstalled.
TEST(FrontTreeless, StopsWhenTheFrontStallsAndClosesOtherwise) {
  RemovalOptions impatient;
  impatient.stall_rounds = 1;
  impatient.rescues = 0;
  impatient.short_growth_first = false;
  const SurfaceMesh joint = refine_midpoints(refine_midpoints(read_surface_file(data_path("good/joint.off"))));
  const Meshed stopped = mesh_surface(joint, "good/joint.off r2", impatient);
  EXPECT_TRUE(stopped.counts.stalled);
  EXPECT_GT(stopped.faces_left, 0u);
  EXPECT_EQ(stopped.counts.faces_left_by_attempt, std::vector<size_t>{stopped.faces_left});
  EXPECT_EQ(stopped.counts.strategy, TreelessStrategy::kDefault);
  const Meshed closed = mesh_file("good/sphere966.off");
  EXPECT_FALSE(closed.counts.stalled);
  EXPECT_EQ(closed.faces_left, 0u);
}

// The same with the rescues: each starts again from the call's starting
// state, none closes joint r2 at stall_rounds 1, and the attempt that left
// the fewest faces (the earliest on ties) is run again: its mesh, a valid
// partial one (mesh_surface), is what the call leaves. With one start
// (what a refined tree gets first) only the first attempt runs, to the
// same front.
TEST(FrontTreeless, RescuesStartAgainAndTheBestAttemptIsKept) {
  const SurfaceMesh joint = refine_midpoints(refine_midpoints(read_surface_file(data_path("good/joint.off"))));
  RemovalOptions impatient;
  impatient.stall_rounds = 1;
  impatient.short_growth_first = false;
  const Meshed best = mesh_surface(joint, "good/joint.off r2, stall 1", impatient);
  const std::vector<size_t>& left = best.counts.faces_left_by_attempt;
  ASSERT_EQ(left.size(), 4u);
  for (size_t n : left) EXPECT_GT(n, 0u);
  const auto fewest = std::min_element(left.begin(), left.end());
  EXPECT_EQ(best.faces_left, *fewest);
  EXPECT_EQ(best.counts.strategy, fewest == left.begin() ? TreelessStrategy::kDefault
                                                          : kRescueStrategies[fewest - left.begin() - 1]);

  RemovalOptions once = impatient;
  once.starts = 1;
  const Meshed first = mesh_surface(joint, "good/joint.off r2, stall 1, one start", once);
  EXPECT_EQ(first.counts.faces_left_by_attempt, std::vector<size_t>{left.front()});
  EXPECT_EQ(first.faces_left, left.front());
  EXPECT_EQ(first.counts.strategy, TreelessStrategy::kDefault);
}

// Going on: with every stall counted as a few stuck faces, each attempt
// runs the strategies after its first from where the last one stopped (the
// default, then the three rescues: 4 runs; then from the start the rescues
// with those after them: 3, 2, 1), none closes joint r2 at stall_rounds 1,
// and the attempt that left the fewest faces, a chain, is run again from
// the start, chain and all, to the same front.
// Going on past the default: joint r2 at stall_rounds 1 without short
// growth. Starting over, no strategy closes it (4 attempts, above); when
// the default's stall counts as a few stuck faces, the next strategy
// (undo overgrowth) goes on from the default's front and closes it.
TEST(FrontTreeless, AttemptsGoOnThroughTheLaterStrategies) {
  const SurfaceMesh joint = refine_midpoints(refine_midpoints(read_surface_file(data_path("good/joint.off"))));
  RemovalOptions over;
  over.stall_rounds = 1;
  over.short_growth_first = false;
  over.go_on_faces = 0;
  const Meshed restarted = mesh_surface(joint, "good/joint.off r2, stall 1, starting over", over);
  RemovalOptions on = over;
  on.go_on_faces = SIZE_MAX;
  const Meshed went_on = mesh_surface(joint, "good/joint.off r2, stall 1, going on", on);
  ASSERT_EQ(restarted.counts.faces_left_by_attempt.size(), 4u);
  EXPECT_GT(restarted.faces_left, 0u);
  ASSERT_EQ(went_on.counts.faces_left_by_attempt.size(), 2u);
  EXPECT_EQ(went_on.counts.faces_left_by_attempt[0], restarted.counts.faces_left_by_attempt[0]);
  EXPECT_EQ(went_on.faces_left, 0u);
  EXPECT_EQ(went_on.counts.strategy, TreelessStrategy::kUndoOvergrowth);
}

// spool refined once: the short-growth attempt closes it (its fills split
// a cavity that is not star-shaped after 4 growth steps instead of 8), in
// fewer rounds and with fewer tets deleted than the default alone.
TEST(FrontTreeless, ShortGrowthClosesInFewerRounds) {
  const SurfaceMesh spool = refine_midpoints(read_surface_file(data_path("good/spool.off")));
  const Meshed short_first = mesh_surface(spool, "good/spool.off r1", {});
  RemovalOptions without;
  without.short_growth_first = false;
  const Meshed default_only = mesh_surface(spool, "good/spool.off r1, default only", without);
  EXPECT_EQ(short_first.faces_left, 0u);
  EXPECT_EQ(default_only.faces_left, 0u);
  EXPECT_EQ(short_first.counts.strategy, TreelessStrategy::kShortGrowth);
  EXPECT_EQ(short_first.counts.faces_left_by_attempt, std::vector<size_t>{0});
  EXPECT_LT(short_first.counts.rounds, default_only.counts.rounds);
  EXPECT_LT(short_first.counts.tets_deleted, default_only.counts.tets_deleted);
}

// spool with short growth stalling after one round without a smaller
// front: it stops with 52 faces left. With go_on_faces under that the
// default starts over from the call's start; at 52 or more it goes on
// from where short growth stopped, and closes with fewer fills and fewer
// tets deleted than from the start (6 and 146 against 22 and 326).
TEST(FrontTreeless, TheDefaultGoesOnFromAFewStuckFaces) {
  const SurfaceMesh spool = read_surface_file(data_path("good/spool.off"));
  RemovalOptions restart;
  restart.stall_rounds = 1;
  restart.rescues = 0;
  restart.go_on_faces = 51;
  const Meshed over = mesh_surface(spool, "good/spool.off, stall 1, start over", restart);
  RemovalOptions go_on = restart;
  go_on.go_on_faces = 52;
  const Meshed on = mesh_surface(spool, "good/spool.off, stall 1, go on", go_on);
  EXPECT_EQ(over.counts.faces_left_by_attempt, (std::vector<size_t>{52, 0}));
  EXPECT_EQ(on.counts.faces_left_by_attempt, (std::vector<size_t>{52, 0}));
  EXPECT_EQ(over.counts.strategy, TreelessStrategy::kDefault);
  EXPECT_EQ(on.counts.strategy, TreelessStrategy::kDefault);
  EXPECT_LT(on.counts.star_fills, over.counts.star_fills);
  EXPECT_LT(on.counts.tets_deleted, over.counts.tets_deleted);
  EXPECT_EQ(on.faces_left, 0u);
}

// `s` scaled by `factor` about the origin, then moved by (dx, dy, dz).
SurfaceMesh placed(SurfaceMesh s, double factor, double dx, double dy, double dz) {
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    s.xyz[3 * v] = s.xyz[3 * v] * factor + dx;
    s.xyz[3 * v + 1] = s.xyz[3 * v + 1] * factor + dy;
    s.xyz[3 * v + 2] = s.xyz[3 * v + 2] * factor + dz;
  }
  return s;
}

TEST(FrontTreeless, MultiShellBodiesClose) {
  // sphere966 is a ball of radius 10 about the origin; the diagnosis turns
  // inner shells into cavities.
  const SurfaceMesh ball = read_surface_file(data_path("good/sphere966.off"));
  const SurfaceMesh ico = read_surface_file(data_path("good/icosahedron.off"));
  SurfaceMesh hollow = ball;
  append(hollow, placed(ball, 0.45, 1, 0.5, 0.25));
  EXPECT_EQ(mesh_surface(hollow, "ball with a ball cavity").faces_left, 0u);
  SurfaceMesh two = ball;
  append(two, placed(ball, 0.6, 17, 3, 1));
  EXPECT_EQ(mesh_surface(two, "two disjoint balls").faces_left, 0u);
  SurfaceMesh three = ball;
  append(three, placed(ico, 2.5, -4.5, 0.3, 0.1));
  append(three, placed(ico, 2, 4, 1, -0.2));
  append(three, placed(ball, 0.2, 0.5, -5, 1));
  EXPECT_EQ(mesh_surface(three, "ball with three cavities").faces_left, 0u);
}

TEST(FrontTreeless, Deterministic) {
  Meshed a = mesh_file("good/sphere966.off");
  Meshed b = mesh_file("good/sphere966.off");
  EXPECT_EQ(a.out.tets, b.out.tets);
  EXPECT_EQ(a.out.xyz, b.out.xyz);
  EXPECT_EQ(a.out.global_ids, b.out.global_ids);
}

TEST(FrontTreeless, DeepestKernelPointOfABox) {
  // The front of a box with no core is the box seen from inside: its
  // deepest point is the centre, at half the shortest side.
  Started s = start(box_surface(2, 4, 6), "box");
  Front front(s.initial, s.tree, s.root);
  std::vector<uint32_t> faces;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f)
    if (front.alive(f)) faces.push_back(f);
  ASSERT_EQ(s.core.mesh.num_tets(), 0u);
  KernelPoint k = deepest_kernel_point(front, faces);
  ASSERT_TRUE(k.found);
  EXPECT_NEAR(k.depth, 1.0, 1e-9);
  EXPECT_NEAR(k.point[0], 1.0, 1e-9);
  for (uint32_t f : faces) {
    const uint32_t* t = front.face(f);
    EXPECT_GT(orient3d(front.point(t[0]), front.point(t[1]), front.point(t[2]), k.point), 0);
  }
}

TEST(FrontTreeless, RemovingATetReopensItsFaces) {
  Started s = start(box_surface(), "box");
  Front front(s.initial, s.tree, s.root);
  TetMesh out = s.core.mesh;
  const size_t faces_before = front.num_alive_faces();
  // One tet on the first face, then its removal: the front is back.
  RemovalCounts n = remove_faces_tree_supported(front, s.tree, s.root, out);
  ASSERT_GT(n.tets, 0u);
  ASSERT_EQ(front.num_alive_faces(), 0u);
  TetIncidence incidence(out);
  // Behind a surface face (it looks into the body) lies no tet; behind its
  // reverse lies the tet on it.
  const uint32_t* t0 = s.initial.faces.data();
  EXPECT_EQ(incidence.tet_behind(out, t0[0], t0[1], t0[2]), kNoTet);
  EXPECT_NE(incidence.tet_behind(out, t0[0], t0[2], t0[1]), kNoTet);
  std::vector<uint32_t> added, shrunk;
  const size_t tets = out.num_tets();
  for (uint32_t t = 0; t < tets; ++t) {
    front.remove_tet(&out.tets[4 * size_t{t}], added, shrunk);
    incidence.kill(t);
  }
  EXPECT_EQ(front.num_alive_faces(), faces_before);
  EXPECT_EQ(incidence.num_dead(), tets);
  incidence.drop_dead_tets(out);
  EXPECT_EQ(out.num_tets(), 0u);
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    EXPECT_EQ(front.find_face(front.face(f)[0], front.face(f)[1], front.face(f)[2]), f);
  }
}

TEST(FrontTreeless, TetBehindAFace) {
  TetMesh cube = cube_tets();
  TetIncidence incidence(cube);
  for (uint32_t t = 0; t < cube.num_tets(); ++t) {
    const uint32_t* q = &cube.tets[4 * size_t{t}];
    // q3 is on the positive side of (q0, q1, q2), so on the negative side
    // of (q0, q2, q1): t lies behind (q0, q2, q1).
    EXPECT_EQ(incidence.tet_behind(cube, q[0], q[2], q[1]), t);
  }
}

TEST(CompactMesh, DropsUnusedVerticesAndRenumbers) {
  TetMesh m;
  m.xyz = {9, 9, 9, 0, 0, 0, 1, 0, 0, 8, 8, 8, 0, 1, 0, 0, 0, 1};
  m.tets = {1, 2, 4, 5};
  m.tris = {1, 4, 2};
  m.global_ids = {10, 11, 12, 13, 14, 15};
  EXPECT_EQ(drop_unused_vertices(m), 2u);
  EXPECT_EQ(m.tets, (std::vector<uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(m.tris, (std::vector<uint32_t>{0, 2, 1}));
  EXPECT_EQ(m.global_ids, (std::vector<uint64_t>{11, 12, 14, 15}));
  EXPECT_EQ(m.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(drop_unused_vertices(m), 0u);
}


}  // namespace
}  // namespace partet::test
