// Tree-less face removals (paper §2.4, pipeline step 10): what the
// tree-supported removals leave is a set of small closed cavities (front
// components). They are closed by removals that may add a vertex inside a
// cavity and delete tets made earlier to reopen a stuck region. Surface
// triangles and surface vertices are never changed: a surface triangle has
// no tet behind it, so it is never reopened, and new vertices are strictly
// inside the unmeshed region.
//
// Rounds, until the front is empty, a round changes nothing, a budget is
// spent (new vertices: 4 x the alive faces at the start + 64; deleted
// tets: 64 x those faces + 1024), or options.stall_rounds (default 64)
// rounds in a row end without a front smaller than every earlier one (the
// call has stalled: a front that diverges, as on thin walls of long skinny
// triangles without a templated core, would otherwise churn for hundreds
// of rounds until a budget runs out). A round splits the alive faces into
// components (faces sharing an edge; where more than two share one, the
// faces across each unmeshed wedge around it: front_cavities.hpp) and,
// for each component of at most
// kMaxCavityFaces faces in order of its lowest face index:
//  1. star fill: q = the deepest point of the component's kernel
//     (kernel_point.hpp; the mean of the face centroids and the mean of the
//     vertices are tried as well). When every face sees q exactly
//     (orient3d > 0), q is added and every face is coned to it, each tet
//     only when check_removal (removal_checks.hpp) says valid against the
//     front gathered over the tet's bounding box;
//  2. growth: otherwise the faces that do not see q and have a tet behind
//     them (they are not surface triangles) are reopened: the tet behind
//     each is deleted (Front::remove_tet), the component grows into it, and
//     step 1 is tried again on the grown component, up to kMaxGrowthSteps times
//     (the component is left for this round when it grows beyond
//     kMaxGrownFaces = 4 kMaxCavityFaces);
//  3. partial cone: when the component still has no star point, q is added
//     and the faces that see it are coned to it where valid (q is dropped
//     again when none is): the cavity is split into smaller ones. When no
//     face is coned, patch cones (below) run on the component.
// Then the components larger than kMaxCavityFaces get
//  4. patch cones: for each of their faces, by increasing sum of squared
//     edge lengths (ties by index), still alive: the breadth-first patch
//     (across the edges of each face in turn, lower face index first) of at most 64, else 24,
//     else 8 of those faces still alive around it, whose deepest kernel
//     point q, when it sees every patch face exactly, is added and coned to
//     the patch faces where valid (as in step 3). A patch is open and its
//     kernel unbounded: when the deepest point in the patch's bounding box
//     is less deep than 0.2 mean edge lengths (kPlainDepth), q is searched
//     in that box lifted along the patch's area-weighted normal by 0.75
//     mean edge lengths (kPatchLift), so that it rises above a nearly flat
//     patch instead of lying almost on it. When that point makes no cone,
//     it is searched again with the alive front faces over the swept box
//     that face the patch (the patch's centre on their unmeshed side)
//     added to the linear program: the point stays in front of them, in
//     the unmeshed region, instead of beyond a thin gap;
//  5. advances: each face still alive, in the same order, gets a tet on a
//     front vertex near the ideal apex (above the centroid at the height of
//     the regular tet) or on a new, well spaced vertex there or lower,
//     where valid, followed by tree-supported removals from the faces near
//     it.
// After each round remove_faces_tree_supported runs over the whole front,
// so that neighbouring faces use the new vertices (it also runs first).
// Points are computed in doubles; every decision on them is exact.
// Deleted tets are removed from `out` at the end (their vertices stay, and
// may end unused: the caller compacts).
//
// Global ids of new vertices: kSteinerVertexId | (front vertex index),
// with bits 63 and 62 set. Lattice keys (core vertices) are below 2^63 and
// surface vertices are kSurfaceVertexId | s with s < 2^32 (bit 62 clear),
// so the three id spaces are disjoint.
//
// Short growth first (options.short_growth_first, on by default): before
// the default, the rounds run with kShortGrowth: at most 4 growth steps per
// fill instead of kMaxGrowthSteps = 8, so that a cavity that is not star-shaped
// is split by its partial cone sooner instead of deleting (and the tree
// pass rebuilding) more of the mesh around it. Where it closes, it closes
// in fewer rounds (the one-round refinements of the CAD parts: t13_data
// 50 -> 12 rounds, spool 13 -> 4); where it churns (pipe r1: the front
// hovers between 250 and 1,000 faces), it stalls after 6 rounds without a
// smaller front (where it closes, a smaller front comes every round or two
// on the corpus refinements, at most 5 rounds apart on pinion r2), and the
// front, `out`, the tree's leaf classes and `memo` are restored for the
// default, as for the rescues below: where short growth fails, the mesh is
// the one the default makes alone. But where it stalls with at most
// options.go_on_faces (64) faces left, a few stuck cavities, the default
// first goes on from there, and the restart comes only when that fails
// too; so does every strategy: one that stalls with at most that many
// faces hands its front to the next in the list (femur r3 with the graded
// tree: short growth left 24 faces, the default going on 4, then the
// restart with the rescues took 45.7 s where undo overgrowth and cone
// first going on close it in 39.6; part r3 9.5 -> 5.4 s). The offset gap
// vertices (offset_vertices.hpp) left t13_data r3's short growth with 10
// faces, and the default from the start then stalled, as did two rescues
// (172 s; going on: 15 s); femur r3 41 -> 32 s. (Going on whatever the faces left closed joint r3 sooner, 36.7 ->
// 25.8 s, when its short growth stalled with 16 faces, but into a mesh
// whose flat sheet the optimizer could not lift then: 3e-10 degrees
// instead of 1.0.)
//
// Rescue: the rounds are chaotic (a change to how a cavity is treated
// closes one input and stalls another), so other strategies run only where
// the default fails. When the default ends with faces left (stalled, a
// budget spent, or a round that changes nothing), the front, `out`, the
// tree's leaf classes and `memo` are restored to what they were at the
// call's start and the rounds run again with the next TreelessStrategy
// (the first options.rescues of these, by default all three; 0: the
// default only):
//  - kUndoOvergrowth: a growth step (step 2) that takes the component
//    beyond kMaxGrownFaces is undone (its tets are made again, newest
//    first, from a face each deletion opened; kept when one of them had all
//    four faces on the front) and the component is left for this round,
//    instead of kept for the tree pass to rebuild every round;
//  - kConeFirst: as kUndoOvergrowth, and a component with no star point is
//    first split by a partial cone (step 3), before any growth;
//  - kSmallCavities: as kDefault, but only components of at most
//    kMaxSmallCavityFaces = 64 faces are filled as one cavity (steps 1-3);
//    the larger ones get patch cones and advances (steps 4 and 5) instead
//    of growing (a thin flat cavity against the surface otherwise grows
//    past kMaxGrownFaces every round and the tree pass rebuilds what it
//    deleted: rotor r3).
// At most options.starts attempts start from the starting state (1: the
// first strategy and those going on from it); it is copied before the
// first attempt runs, unless no attempt can start from it again (one start
// and rerun_best off). The first strategy that closes the front wins. When none does, the attempt that
// left the fewest faces (the earliest on ties; an attempt that went on is
// its whole chain of strategies) is run again from the starting state,
// unless it was the last (the rounds are deterministic;
// keeping a copy of the best attempt instead held one more whole mesh at
// the peak). Inputs the default closes are unchanged: the rescues never
// run.
//
// Termination: each round either changes the mesh, spending budget (a new
// vertex or a deletion) or making tets by tree-supported removal, which
// terminates (face_removal.hpp); a round that changes nothing ends the
// call. Deterministic: fixed orders, ties by index.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tet_mesh.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"

namespace partet {

constexpr uint64_t kSteinerVertexId = kSurfaceVertexId | (uint64_t{1} << 62);

// How the rounds treat the components one star point does not close
// (steps 1-5 above); a call tries them in this order (see Short growth
// first and Rescue).
enum class TreelessStrategy : uint8_t {
  kShortGrowth,     // as kDefault, with at most 4 growth steps and a stall after 6 rounds
  kDefault,         // a growth step past kMaxGrownFaces is kept
  kUndoOvergrowth,  // a growth step past kMaxGrownFaces is undone
  kConeFirst,       // as kUndoOvergrowth, and a partial cone before the first growth
  kSmallCavities,   // as kDefault, with components of at most 64 faces filled as one cavity
};
// Growth steps per fill (step 2 above), but with kShortGrowth.
constexpr int kMaxGrowthSteps = 8;
// TreelessStrategy::kShortGrowth: growth steps per fill, and rounds in a
// row without a smaller front before the attempt gives up (at most
// RemovalOptions::stall_rounds).
constexpr int kShortGrowthSteps = 4;
constexpr size_t kShortGrowthStall = 6;
// The growth steps a fill may take with `strategy`.
int growth_steps(TreelessStrategy strategy);
// The rounds in a row without a smaller front after which an attempt with
// `strategy` stalls, given RemovalOptions::stall_rounds.
size_t stall_rounds(TreelessStrategy strategy, size_t option);
constexpr TreelessStrategy kRescueStrategies[] = {TreelessStrategy::kUndoOvergrowth, TreelessStrategy::kConeFirst,
                                                  TreelessStrategy::kSmallCavities};
const char* strategy_name(TreelessStrategy strategy);

struct TreelessCounts {
  size_t tree_tets = 0;        // made by the tree-supported runs inside
  size_t new_vertex_tets = 0;  // made on new vertices
  size_t vertices_added = 0;
  size_t tets_deleted = 0;
  size_t star_fills = 0;       // components closed by one star point
  size_t partial_cones = 0;
  size_t advances = 0;         // tets on a new vertex above one face
  size_t rounds = 0;
  size_t checks = 0;
  size_t faces_left = 0;
  size_t foreign_faces = 0;    // of those, skipped for a leaf owned elsewhere (last tree run)
  bool stalled = false;        // ended by stall_rounds rounds without a smaller front
  TreelessStrategy strategy = TreelessStrategy::kDefault;  // of the attempt these counts are from
  std::vector<size_t> faces_left_by_attempt;  // per strategy run (from the start or going on), in order
};

// Same contract as remove_faces_tree_supported on `front`, `tree`, `root`
// and `out`: new vertices are appended to the front and to `out` (with
// global ids when `out` has them). `memo` carries the tree-supported
// removals' failures from an earlier call on the same front and options
// into the tree-supported runs inside (face_removal.hpp).
TreelessCounts remove_faces_treeless(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                     const RemovalOptions& options = {}, RemovalMemo* memo = nullptr);

}  // namespace partet
