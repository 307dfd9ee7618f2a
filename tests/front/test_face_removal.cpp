// Tree-supported face removals after the real pipeline (sizes, octree,
// balance, classification, templates, initial front): a single tet and a
// cube close completely; on the corpus shapes the core plus the new tets
// is always a valid partial mesh (and fills the surface when the front is
// empty), which the tree-less removals complete; faces near leaves owned by another rank wait, and a later call
// with the leaves back on this rank continues the same front; a memo of
// failures spares a later call the faces whose neighbourhood is unchanged;
// two ranks' copies of a front merge into what replaying their tets gives;
// compacting the front between calls changes no tet; a closed cavity of
// four faces too flat for doubles' shape measure still gets its tet; a failed removal
// whose blocker is still there (what lets a call skip rechecking it) still
// fails on the evolving front.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "check/validate.hpp"
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
#include "octree/range_query.hpp"
#include "octree/sizing.hpp"
#include "surface/diagnose.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

struct Meshing {
  SurfaceMesh surface;
  RootCube root;
  VertexSizing sizing;
  LinearOctree tree;
  TemplateCore core;
  InitialFront initial;
};

// The pipeline of src/pipeline/mesh_command.cpp from the root cube around
// `bbox` up to the initial front, on m.surface as it is.
void prepare_from_root(Meshing& m, const double* bbox, double size_factor) {
  m.root = make_root_cube(bbox);
  SizingOptions sizing_options;
  sizing_options.size_factor = size_factor;
  m.sizing = size_vertices(m.surface, m.root, sizing_options);
  const VertexSizing& sizing = m.sizing;
  m.tree = build_octree(sizing.grid, sizing.level);
  refine_for_triangles(m.tree, m.surface, m.root, sizing.level);
  balance_octree(m.tree);
  classify_leaves(m.tree, m.surface, m.root, sizing.size);
  m.core = template_interior(m.tree, m.root);
  m.initial = make_initial_front(m.tree, m.root, m.core, m.surface);
}

// The whole pipeline up to the initial front, the surface diagnosed first.
void prepare(Meshing& m, SurfaceMesh surface, double size_factor) {
  m.surface = std::move(surface);
  const SurfaceSummary summary = diagnose_surface(m.surface, "test surface");
  prepare_from_root(m, summary.bbox, size_factor);
}

// Core plus new tets valid as a partial mesh; filling the surface when the
// front is empty.
void expect_valid(const Meshing& m, const TetMesh& out, size_t faces_left, const std::string& what) {
  ValidationResult partial = validate_mesh(out, nullptr);
  EXPECT_TRUE(partial.valid) << what << ": " << format_text(partial);
  if (faces_left == 0) {
    ValidationResult full = validate_mesh(out, &m.surface);
    EXPECT_TRUE(full.valid) << what << ": " << format_text(full);
  }
}

// near = the front over the leaves that meet the box of the tet (face f,
// apex p) grown by `grow` times its longest side.
void gather_around(const Meshing& m, const Front& front, uint32_t f, uint32_t p, double grow,
                   std::vector<size_t>& leaves, NearFront& near) {
  const uint32_t* t = front.face(f);
  const double* q[4] = {front.point(t[0]), front.point(t[1]), front.point(t[2]), front.point(p)};
  double lo[3], hi[3], longest = 0;
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({q[0][k], q[1][k], q[2][k], q[3][k]});
    hi[k] = std::max({q[0][k], q[1][k], q[2][k], q[3][k]});
    longest = std::max(longest, hi[k] - lo[k]);
  }
  for (int k = 0; k < 3; ++k) {
    lo[k] -= grow * longest;
    hi[k] += grow * longest;
  }
  uint32_t glo[3], ghi[3];
  grid_range(m.root, lo, hi, glo, ghi);
  front.query().leaves_in_range(glo, ghi, leaves);
  gather_near_front(front, leaves, near);
}

SurfaceMesh tet_surface() {
  SurfaceMesh s;
  s.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  s.tris = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1};
  return s;
}

TEST(FrontRemoval, SingleTetSurfaceMakesOneTet) {
  Meshing m;
  prepare(m, tet_surface(), 1);
  ASSERT_EQ(m.core.mesh.num_tets(), 0u);
  Front front(m.initial, m.tree, m.root);
  TetMesh out = m.core.mesh;
  RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out);
  EXPECT_EQ(n.tets, 1u);
  EXPECT_EQ(n.faces_left, 0u);
  EXPECT_EQ(front.num_alive_faces(), 0u);
  expect_valid(m, out, n.faces_left, "tet");
  for (size_t leaf = 0; leaf < m.tree.size(); ++leaf) {
    EXPECT_TRUE(front.leaf_front_empty(leaf));
    EXPECT_NE(m.tree.cls[leaf], LeafClass::kBoundary) << "leaf " << leaf;
  }
}

// The four faces a 2-rank run left on a random surface (stress-check seed
// 1790): a positive tet (exact orient3d 3e-21) whose height, about 1e-18,
// is under the rounding of its coordinates, so no point lies inside it.
// Only its own tet closes it (the tree-less rounds' last pass makes it),
// and in the root cube of that run the fourth
// vertex lies in one face's neighbourhood box only, where its shape
// measures -7e-20 in doubles. As a surface of its own it is flat to
// doubles (diagnose_surface would orient it by the rounding of its
// volume), so the front is made from it as given.
TEST(FrontRemoval, FlatClosedCavityGetsItsTet) {
  Meshing m;
  m.surface = test::flat_tet_of_seed_1790();
  const SurfaceMesh& s = m.surface;
  ASSERT_LT(orient3d(s.point(0), s.point(2), s.point(1), s.point(3)), 0);
  // The root cube of the whole surface the run meshed.
  const double bbox[6] = {-0.25379256, -0.15558668, -0.31315987, 0.25379256, 0.15558668, 0.31315987};
  prepare_from_root(m, bbox, 1);
  ASSERT_EQ(m.core.mesh.num_tets(), 0u);
  // The removals' passes leave it (their shape measure says flat) ...
  {
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    const RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out);
    EXPECT_EQ(n.tets, 0u);
    EXPECT_EQ(n.faces_left, 4u);
  }
  // ... a pass that closes flat cavities makes its tet ...
  {
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    RemovalOptions options;
    options.close_flat_cavities = true;
    const RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out, options);
    EXPECT_EQ(n.tets, 1u);
    EXPECT_EQ(n.faces_left, 0u);
    ValidationResult partial = validate_mesh(out, nullptr);
    EXPECT_TRUE(partial.valid) << format_text(partial);
  }
  // ... and the tree-less removals, whose rounds find no point inside it,
  // end with that pass.
  {
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    const TreelessCounts n = remove_faces_treeless(front, m.tree, m.root, out);
    EXPECT_EQ(n.faces_left, 0u);
    EXPECT_EQ(n.vertices_added, 0u);
    EXPECT_EQ(out.num_tets(), 1u);
  }
}

TEST(FrontRemoval, CubeSurfaceIsFilled) {
  for (double factor : {1.0, 0.25}) {
    Meshing m;
    prepare(m, box_surface(), factor);
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out);
    EXPECT_GT(n.tets, 0u);
    EXPECT_EQ(n.faces_left, front.num_alive_faces());
    EXPECT_EQ(out.num_tets(), m.core.mesh.num_tets() + n.tets);
    if (factor == 1.0) {
      EXPECT_EQ(n.faces_left, 0u);
    }
    expect_valid(m, out, n.faces_left, "cube x" + std::to_string(factor));
  }
}

TEST(FrontRemoval, CorpusShapesStayValid) {
  for (const char* name : {"octahedron.off", "icosahedron.off", "ellipsoid.off", "sphere966.off"})
    for (double factor : {1.0, 0.5}) {
      Meshing m;
      prepare(m, read_surface_file(data_path(std::string("good/") + name)), factor);
      Front front(m.initial, m.tree, m.root);
      TetMesh out = m.core.mesh;
      const auto start = std::chrono::steady_clock::now();
      RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("[ corpus   ] %-16s x%.1f: front %zu -> %zu faces, %zu tets, %zu passes, %zu checks, %.3f s"
                  " (%.0f tets/s)\n",
                  name, factor, m.initial.num_faces(), n.faces_left, n.tets, n.passes, n.checks, seconds,
                  n.tets / std::max(seconds, 1e-9));
      EXPECT_EQ(n.foreign_faces, 0u);
      // Targets are looked for within 0.6 longest edges of a face: across
      // a small polyhedron with no templated core there are none, and the
      // tree-less removals close it all.
      if (m.core.mesh.num_tets() > 0) {
        EXPECT_LT(n.faces_left, m.initial.num_faces()) << name;
      }
      expect_valid(m, out, n.faces_left, std::string(name) + " x" + std::to_string(factor));
      const TreelessCounts rest = remove_faces_treeless(front, m.tree, m.root, out);
      EXPECT_EQ(rest.faces_left, 0u) << name;
      expect_valid(m, out, rest.faces_left, std::string(name) + " x" + std::to_string(factor) + " closed");
    }
}

TEST(FrontRemoval, ForeignLeavesWait) {
  Meshing m;
  prepare(m, read_surface_file(data_path("good/sphere966.off")), 1);
  // Leaves in the upper half (anchor z at or above the middle) belong to rank 1.
  for (size_t leaf = 0; leaf < m.tree.size(); ++leaf) {
    uint32_t x, y, z;
    m.tree.anchor(leaf, x, y, z);
    if (z >= kGridSize / 2) m.tree.owner[leaf] = 1;
  }
  Front front(m.initial, m.tree, m.root);
  TetMesh out = m.core.mesh;
  const size_t core_tets = out.num_tets();
  RemovalCounts n = remove_faces_tree_supported(front, m.tree, m.root, out);
  EXPECT_GT(n.tets, 0u);
  EXPECT_GT(n.foreign_faces, 0u);
  EXPECT_LE(n.foreign_faces, n.faces_left);
  // Every new tet stays in rank 0's leaves.
  for (size_t t = core_tets; t < out.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(m.tree.owner[front.vertex_leaf(out.tets[4 * t + k])], 0);
  expect_valid(m, out, n.faces_left, "half owned");

  // Back on this rank: the same front goes on.
  for (int32_t& owner : m.tree.owner) owner = 0;
  RemovalCounts more = remove_faces_tree_supported(front, m.tree, m.root, out);
  EXPECT_GT(more.tets, 0u);
  EXPECT_EQ(more.foreign_faces, 0u);
  EXPECT_LT(more.faces_left, n.faces_left);
  expect_valid(m, out, more.faces_left, "all owned");
}

// Alive faces rotated to start at their smallest vertex (orientation kept),
// sorted; the front edges' use counts; the vertices' use counts.
struct FrontState {
  std::vector<std::array<uint32_t, 3>> faces;
  std::vector<uint32_t> edge_uses, vertex_uses;
  size_t free = 0;
  bool operator==(const FrontState&) const = default;
};

FrontState state_of(const Front& front) {
  FrontState s;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    std::array<uint32_t, 3> t = {front.face(f)[0], front.face(f)[1], front.face(f)[2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    s.faces.push_back(t);
  }
  std::sort(s.faces.begin(), s.faces.end());
  for (const auto& t : s.faces)
    for (int k = 0; k < 3; ++k) s.edge_uses.push_back(front.edge_uses(t[k], t[(k + 1) % 3]));
  for (uint32_t v = 0; v < front.num_vertices(); ++v) s.vertex_uses.push_back(front.vertex_uses(v));
  s.free = front.num_free_vertices();
  return s;
}

// Two copies of one front (with gap vertices), the lower half of the
// leaves rank 0's and the upper half rank 1's, each removing faces on its
// own: rank 1's changes merged into rank 0's front give the front that
// making rank 1's tets again gives, and the front then closes to a valid
// mesh with both ranks' tets.
TEST(FrontRemoval, RanksFrontChangesMergeAsTheirTetsReplay) {
  Meshing m;
  prepare(m, read_surface_file(data_path("good/sphere966.off")), 1);
  const GapVertices gap = gap_vertices(m.tree, m.root, m.surface, m.sizing.size, 0.5);
  ASSERT_GT(gap.size(), 0u);
  add_free_vertices(m.initial, m.tree, gap.xyz, gap.global_ids, gap.leaf);
  for (size_t leaf = 0; leaf < m.tree.size(); ++leaf) {
    uint32_t x, y, z;
    m.tree.anchor(leaf, x, y, z);
    if (z >= kGridSize / 2) m.tree.owner[leaf] = 1;
  }
  LinearOctree tree0 = m.tree, tree1 = m.tree;
  Front front0(m.initial, tree0, m.root), front1(m.initial, tree1, m.root);
  const Front::Snapshot start = front1.snapshot();
  TetMesh out0 = m.core.mesh, out1 = m.core.mesh;
  const size_t core_tets = out0.num_tets();
  RemovalOptions rank1;
  rank1.rank = 1;
  ASSERT_GT(remove_faces_tree_supported(front0, tree0, m.root, out0).tets, 0u);
  ASSERT_GT(remove_faces_tree_supported(front1, tree1, m.root, out1, rank1).tets, 0u);

  Front replayed = front0;
  LinearOctree tree_replayed = tree0;
  std::vector<uint32_t> added, shrunk;
  for (size_t t = core_tets; t < out1.num_tets(); ++t) {
    const uint32_t* v = &out1.tets[4 * t];
    const uint32_t f = replayed.find_face(v[0], v[1], v[2]);
    ASSERT_NE(f, kNoIndex) << t;
    make_removal_tet(replayed, tree_replayed, out0, f, v[3], added, shrunk);
  }
  const Front::Changes changes = front1.changes_since(start);
  EXPECT_FALSE(changes.closed.empty());
  EXPECT_FALSE(changes.added.empty());
  EXPECT_FALSE(changes.taken.empty());
  shrunk.clear();
  front0.merge(changes, shrunk);
  EXPECT_TRUE(state_of(front0) == state_of(replayed));

  // out0 now holds rank 0's tets and rank 1's (made again above).
  for (int32_t& owner : tree0.owner) owner = 0;
  mark_done_leaves(front0, tree0, shrunk);
  const RemovalCounts rest = remove_faces_tree_supported(front0, tree0, m.root, out0);
  EXPECT_GT(rest.tets, 0u);
  expect_valid(m, out0, rest.faces_left, "merged");
}

// Calls with `memo` until one makes no tet (the last pass of a call may
// still make a few, after some faces failed); that call's counts.
RemovalCounts remove_until_stuck(Meshing& m, Front& front, TetMesh& out, RemovalMemo& memo) {
  RemovalCounts last;
  for (int call = 0; call < 100; ++call) {
    last = remove_faces_tree_supported(front, m.tree, m.root, out, {}, nullptr, &memo);
    if (last.tets == 0) break;
  }
  return last;
}

TEST(FrontRemoval, MemoSkipsUnchangedNeighbourhoods) {
  size_t stuck_inputs = 0;
  for (const char* name : {"joint.off", "pipe.off", "spool.off"}) {
    Meshing m;
    prepare(m, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    RemovalMemo memo;
    const RemovalCounts first = remove_until_stuck(m, front, out, memo);
    EXPECT_EQ(first.tets, 0u) << name;
    // The memo keeps a record only for faces that failed: under half the
    // face slots made even on these CAD parts (it was an array over all of
    // them), and every face left alive, having failed, has one.
    EXPECT_EQ(memo.recorded.size(), memo.records.size()) << name;
    EXPECT_LT(memo.records.size() * 2, front.num_face_slots()) << name;
    size_t left_with_record = 0;
    for (uint32_t f = 0; f < front.num_face_slots(); ++f)
      left_with_record += front.alive(f) && memo.failed_at(f, false) != kNeverFailed;
    EXPECT_EQ(left_with_record, first.faces_left) << name;
    if (first.faces_left == 0) continue;
    ++stuck_inputs;
    // Nothing changed since every face left failed: with the memo no face
    // is tried; without it every face is, and fails again.
    const RemovalCounts again = remove_faces_tree_supported(front, m.tree, m.root, out, {}, nullptr, &memo);
    EXPECT_EQ(again.checks, 0u) << name;
    EXPECT_EQ(again.tets, 0u) << name;
    const RemovalCounts fresh = remove_faces_tree_supported(front, m.tree, m.root, out);
    EXPECT_GT(fresh.checks, 0u) << name;
    EXPECT_EQ(fresh.tets, 0u) << name;
    // Another min_quality is another question: the memo starts afresh.
    RemovalOptions shaped;
    shaped.min_quality = 0.05;
    const RemovalCounts other = remove_faces_tree_supported(front, m.tree, m.root, out, shaped, nullptr, &memo);
    EXPECT_GT(other.checks, 0u) << name;
    EXPECT_EQ(memo.min_quality, 0.05) << name;
    expect_valid(m, out, again.faces_left, name);
  }
  EXPECT_GT(stuck_inputs, 0u) << "no input left faces to retry";
}

// The failures a memo holds that still stand, recorded in another copy of
// the front's memo (as the ranks hand theirs to rank 0), spare that copy
// every check the first copy already failed; a change near a face takes it
// off the standing ones.
TEST(FrontRemoval, StandingFailuresCarryOverToACopy) {
  size_t stuck_inputs = 0;
  for (const char* name : {"joint.off", "pipe.off", "spool.off"}) {
    Meshing m;
    prepare(m, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    RemovalMemo memo;
    remove_until_stuck(m, front, out, memo);
    if (front.num_alive_faces() == 0) continue;
    ++stuck_inputs;
    // Every face left failed a full pass and nothing changed since.
    const std::vector<uint32_t> standing = standing_failures(front, m.root, {}, memo, true);
    EXPECT_EQ(standing.size(), front.num_alive_faces()) << name;
    EXPECT_EQ(standing_failures(front, m.root, {}, RemovalMemo{}, true).size(), 0u) << name;

    Front copy = front;
    LinearOctree tree_copy = m.tree;
    TetMesh out_copy = out;
    RemovalMemo taken;
    record_failures(copy, standing, true, 0, taken);
    const RemovalCounts skipped = remove_faces_tree_supported(copy, tree_copy, m.root, out_copy, {}, nullptr, &taken);
    EXPECT_EQ(skipped.checks, 0u) << name;
    EXPECT_EQ(skipped.tets, 0u) << name;
    // Taken under another min_quality they do not count.
    RemovalMemo shaped;
    record_failures(copy, standing, true, 0.05, shaped);
    EXPECT_GT(remove_faces_tree_supported(copy, tree_copy, m.root, out_copy, {}, nullptr, &shaped).checks, 0u) << name;

    // A tet on the first standing face, to a new vertex just above it (its
    // validity does not matter here, only that the front changed there):
    // the faces near it, whose neighbourhood leaves changed, stand no more.
    std::vector<uint32_t> added, shrunk;
    double centre[3];
    const uint32_t* t = front.face(standing.front());
    for (int k = 0; k < 3; ++k)
      centre[k] = (front.point(t[0])[k] + front.point(t[1])[k] + front.point(t[2])[k]) / 3;
    double lift[3];
    {
      const double *a = front.point(t[0]), *b = front.point(t[1]), *c = front.point(t[2]);
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      lift[0] = (u[1] * w[2] - u[2] * w[1]) * 1e-3;
      lift[1] = (u[2] * w[0] - u[0] * w[2]) * 1e-3;
      lift[2] = (u[0] * w[1] - u[1] * w[0]) * 1e-3;
    }
    for (int k = 0; k < 3; ++k) centre[k] += lift[k];
    ASSERT_GT(orient3d(front.point(t[0]), front.point(t[1]), front.point(t[2]), centre), 0) << name;
    const uint32_t v = front.add_vertex(centre, kSteinerVertexId | front.num_vertices());
    out.xyz.insert(out.xyz.end(), centre, centre + 3);
    make_removal_tet(front, m.tree, out, standing.front(), v, added, shrunk);
    const std::vector<uint32_t> after = standing_failures(front, m.root, {}, memo, true);
    EXPECT_LT(after.size(), standing.size() - 1) << name;
  }
  EXPECT_GT(stuck_inputs, 0u) << "no input left faces to retry";
}

// Compacting the front between calls (as the pipeline does before the
// tree-less removals) renumbers its faces in order: the calls after it make
// the same tets as without it.
TEST(FrontRemoval, CompactionChangesNoTet) {
  size_t compacted_inputs = 0;
  for (const char* name : {"joint.off", "pipe.off", "spool.off"}) {
    Meshing plain, compacted;
    prepare(plain, read_surface_file(data_path(std::string("good/") + name)), 1);
    prepare(compacted, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front a(plain.initial, plain.tree, plain.root), b(compacted.initial, compacted.tree, compacted.root);
    TetMesh out_a = plain.core.mesh, out_b = compacted.core.mesh;
    RemovalMemo memo_a, memo_b;
    RemovalOptions shaped;
    shaped.min_quality = 0.05;
    remove_faces_tree_supported(a, plain.tree, plain.root, out_a, shaped, nullptr, &memo_a);
    remove_faces_tree_supported(b, compacted.tree, compacted.root, out_b, shaped, nullptr, &memo_b);
    const size_t alive = b.num_alive_faces();
    compacted_inputs += alive < b.num_face_slots();
    const std::vector<uint32_t> new_face = b.compact();
    memo_b.renumber(new_face);
    EXPECT_EQ(b.num_face_slots(), alive) << name;
    EXPECT_LE(memo_b.recorded.size(), alive) << name;
    EXPECT_EQ(memo_b.recorded.size(), memo_b.records.size()) << name;
    for (uint32_t f = 0; f < a.num_face_slots(); ++f) {
      ASSERT_EQ(a.alive(f), new_face[f] != kNoIndex) << name;
      if (!a.alive(f)) continue;
      const uint32_t* t = b.face(new_face[f]);
      EXPECT_TRUE(std::equal(t, t + 3, a.face(f))) << name;
      EXPECT_EQ(b.find_face(t[2], t[0], t[1]), new_face[f]) << name;
      EXPECT_EQ(b.edge_uses(t[0], t[1]), a.edge_uses(t[0], t[1])) << name;
      EXPECT_EQ(memo_b.failed_at(new_face[f], false), memo_a.failed_at(f, false)) << name;
      EXPECT_EQ(memo_b.failed_at(new_face[f], true), memo_a.failed_at(f, true)) << name;
    }
    const RemovalCounts na = remove_faces_tree_supported(a, plain.tree, plain.root, out_a, {}, nullptr, &memo_a);
    const RemovalCounts nb =
        remove_faces_tree_supported(b, compacted.tree, compacted.root, out_b, {}, nullptr, &memo_b);
    EXPECT_EQ(na.tets, nb.tets) << name;
    EXPECT_EQ(na.faces_left, nb.faces_left) << name;
    EXPECT_EQ(out_a.tets, out_b.tets) << name;
  }
  EXPECT_GT(compacted_inputs, 0u) << "no input had closed faces to drop";
}

// The removals list new faces from the neighbourhood's leaves (a
// LeafCover) instead of a range query: replaying their tets on a second
// front without a cover gives every leaf the same face lists, in the same
// order.
TEST(FrontRemoval, LeafCoverListsFacesAsTheRangeQuery) {
  for (const char* name : {"joint.off", "spool.off", "sphere966.off"}) {
    Meshing m;
    prepare(m, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front covered(m.initial, m.tree, m.root), plain(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    const size_t core_tets = out.num_tets();
    LinearOctree tree = m.tree;
    const RemovalCounts counts = remove_faces_tree_supported(covered, tree, m.root, out, {}, nullptr, nullptr);
    ASSERT_GT(counts.tets, 100u) << name;
    std::vector<uint32_t> added, shrunk;
    for (size_t t = core_tets; t < out.num_tets(); ++t) {
      const uint32_t* v = &out.tets[4 * t];
      const uint32_t f = plain.find_face(v[0], v[1], v[2]);
      ASSERT_NE(f, kNoIndex) << name << " tet " << t;
      plain.apply_tet(f, v[3], added, shrunk);
    }
    ASSERT_EQ(plain.num_face_slots(), covered.num_face_slots()) << name;
    for (size_t leaf = 0; leaf < m.tree.size(); ++leaf) {
      uint32_t e = covered.first_face_entry(leaf), g = plain.first_face_entry(leaf);
      for (; e != kNoIndex && g != kNoIndex; e = covered.next_entry(e), g = plain.next_entry(g))
        ASSERT_EQ(covered.entry_face(e), plain.entry_face(g)) << name << " leaf " << leaf;
      ASSERT_EQ(e == kNoIndex, g == kNoIndex) << name << " leaf " << leaf;
    }
  }
}

// Soundness of still_blocked, on real fronts as tets are applied: every
// failed removal (f, p) whose blocker still_blocked keeps must fail again
// when checked from scratch. Both outcomes must occur, of each kind.
// Suspects change no verdict either: with what blocked the earlier checks
// tested first (some of it closed by the tets applied since), every check
// agrees with the plain one, and the suspects alone refuse many.
TEST(FrontRemoval, StillBlockedAndSuspectsAgreeWithFreshChecks) {
  struct Failed {
    uint32_t f, p;
    RemovalBlocker why;
  };
  size_t kept = 0, released = 0, refused_by_suspects = 0, stale = 0;
  for (const char* name : {"joint.off", "spool.off"}) {
    Meshing m;
    prepare(m, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    NearFront near;
    std::vector<size_t> leaves;
    std::vector<uint32_t> added, shrunk;
    // The front within `grow` longest edges of the tet (a, b, c, p)'s box.
    auto gather = [&](uint32_t f, uint32_t p, double grow) { gather_around(m, front, f, p, grow, leaves, near); };
    std::vector<Failed> failed;
    Suspects suspects;
    const NearFront none;
    size_t applied = 0;
    for (uint32_t f = 0; f < front.num_face_slots() && applied < 400; ++f) {
      if (!front.alive(f)) continue;
      gather(f, front.face(f)[0], 1.0);
      const std::vector<uint32_t> candidates = near.vertices;
      for (uint32_t p : candidates) {
        gather(f, p, 0);
        RemovalBlocker why;
        const bool valid = check_removal(front, f, p, near, &why) == RemovalVerdict::kValid;
        ASSERT_EQ(check_removal(front, f, p, near, nullptr, &suspects) == RemovalVerdict::kValid, valid)
            << name << ": face " << f << " target " << p;
        refused_by_suspects += check_removal(front, f, p, none, nullptr, &suspects) != RemovalVerdict::kValid;
        if (!valid) {
          failed.push_back({f, p, why});
          suspects.add(why);
          continue;
        }
        make_removal_tet(front, m.tree, out, f, p, added, shrunk);
        ++applied;
        std::vector<Failed> still;
        for (const Failed& x : failed) {
          if (!front.alive(x.f) || front.vertex_uses(x.p) == 0) continue;
          if (!still_blocked(front, x.f, x.p, x.why)) {
            ++released;
            continue;
          }
          ++kept;
          gather(x.f, x.p, 0);
          ASSERT_NE(check_removal(front, x.f, x.p, near), RemovalVerdict::kValid)
              << name << ": face " << x.f << " target " << x.p << " was blocked by "
              << verdict_name(x.why.verdict) << " " << x.why.entity << ", still there, and is valid now";
          still.push_back(x);
        }
        failed.swap(still);
        break;
      }
    }
    EXPECT_GT(applied, 100u) << name;
    for (uint32_t g : suspects.faces) stale += !front.alive(g);
    out.xyz = front.xyz();  // the core's vertices are the front's first ones
    out.global_ids.clear();
    expect_valid(m, out, front.num_alive_faces(), name);
  }
  EXPECT_GT(kept, 1000u);
  EXPECT_GT(released, 100u);
  EXPECT_GT(refused_by_suspects, 100u);
  EXPECT_GT(stale, 10u);
}

// The memo's blocked records outlive a call: after a compaction (face
// slots renumbered) and deletions of tets (faces reopened, as the tree-less
// removals do), every record whose blocker still_blocked keeps must still
// fail when checked from scratch.
TEST(FrontRemoval, BlockedRecordsStaySoundAfterCompactionAndDeletions) {
  size_t kept = 0, dropped = 0;
  for (const char* name : {"joint.off", "pipe.off", "spool.off"}) {
    Meshing m;
    prepare(m, read_surface_file(data_path(std::string("good/") + name)), 1);
    Front front(m.initial, m.tree, m.root);
    TetMesh out = m.core.mesh;
    const size_t core_tets = out.num_tets();
    RemovalMemo memo;
    remove_faces_tree_supported(front, m.tree, m.root, out, {}, nullptr, &memo);
    memo.renumber(front.compact());
    ASSERT_FALSE(memo.recorded.empty()) << name;
    // Reopen every fifth tet the removals made, newest first.
    std::vector<uint32_t> added, shrunk;
    for (size_t t = out.num_tets(); t-- > core_tets;)
      if (t % 5 == 0) front.remove_tet(&out.tets[4 * t], added, shrunk);
    NearFront near;
    std::vector<size_t> leaves;
    for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
      const RemovalMemo::Record* failure = memo.find(f);
      if (!front.alive(f) || !failure) continue;
      for (uint32_t k = 0; k < failure->count; ++k) {
        const RemovalMemo::Blocked& b = memo.blocked_pool[failure->first + k];
        if (front.vertex_uses(b.target) == 0 || !still_blocked(front, f, b.target, b.why)) {
          ++dropped;
          continue;
        }
        ++kept;
        gather_around(m, front, f, b.target, 0, leaves, near);
        ASSERT_NE(check_removal(front, f, b.target, near), RemovalVerdict::kValid)
            << name << ": face " << f << " target " << b.target << " was blocked by " << verdict_name(b.why.verdict)
            << " " << b.why.entity << ", still there, and is valid now";
      }
    }
  }
  EXPECT_GT(kept, 1000u);
  EXPECT_GT(dropped, 10u);
}

}  // namespace
}  // namespace partet::test
