// Tree-supported face removals (paper §2.3, pipeline steps 4, 6, 8): each
// alive front face (the base) is connected to an existing front vertex,
// making a tet, when a valid one is found; no vertex is added.
//
// For a base face (a, b, c):
//  - neighbourhood: the box centroid ± reach × longest edge, clipped to the
//    root cube, and the leaves over it (LeafRangeQuery). When one of them
//    is owned by another rank the face is skipped for this call (removals
//    never communicate: it waits for a repartitioning);
//  - targets: the front vertices of those leaves that lie in the box with
//    orient3d(a, b, c, p) > 0;
//  - order: the Delaunay order of gift wrapping. The spheres through a, b
//    and c have their centres on the line through the base's circumcentre
//    along its normal; a target's sphere is the one through it, and its
//    height is that centre's height over the circumcentre, in base
//    circumradii. Lowest first: the first target is the one the sphere
//    meets first as it sweeps from the base's plane to the normal's side,
//    so no other target lies inside its sphere, and the first valid one is
//    the constrained Delaunay choice among the valid ones. Near-ties
//    (co-spherical targets: regular grids, symmetric small bodies) go to
//    closing and shape: score = 0.05 closed + 0.01 q - height, descending,
//    then vertex index, where `closed` counts the tet's other faces whose
//    twins are alive (it closes them) and q = √2 det / l_rms³ (6 × volume
//    over the cube of the root mean square edge, 1 for the regular tet).
//    Tets made in this order agree with each other where a best-shape
//    order leaves gaps no vertex can fill: on the corpus two fifths fewer
//    faces reach the tree-less removals' pockets, and the run is a fifth
//    faster (docs/decisions.md, "Targets in Delaunay order"). Targets with
//    q < min_quality are dropped; with close_flat_cavities, a tet that
//    closes the base's three neighbours across its edges (it fills a
//    closed cavity of four faces, which no other vertex can) stays even
//    when q, measured in doubles, is 0 or below. With shape_order the
//    score is q × (1 + closed) instead (closing preferred unless the shape
//    is much worse): the paper's order, run_mesh's last resort;
//  - the first target passing check_removal (removal_checks.hpp) makes the
//    tet (a, b, c, p) (positively oriented), appended to `out`; the front
//    is updated and boundary or too-close leaves whose front became empty
//    are reclassified kDone. A target is checked against the front over the
//    leaves that meet its tet's box (most faces take their first target);
//    past the first few, against one gather over the whole neighbourhood.
//  - a target the face's last failure (in this call or, with a memo, an
//    earlier one) found blocked is not checked again while its blocker
//    still blocks (still_blocked: the blocking entity is still on the
//    front), so the check would fail again. A third of the checks on the
//    corpus were such repeats; the tets made are the same.
//
// Order and progress. Faces wait in a min-heap by longest edge, smallest
// first, in size classes of a factor 2^(1/4) in length; within a class by
// the Morton key of the centroid's grid cell, then by index. The heap is
// seeded with the alive faces; faces made by removals join it. The classes
// keep the removals' memory accesses local: exact lengths order faces of
// nearly equal size (most of them, on a refined surface) at random over
// the body, and on large fronts the cache misses cost a third of the
// step (docs/decisions.md, "Face queue in Morton order"). A pass empties the heap. In a capped pass a face tries
// its best few targets; a face that finds no valid one waits for the next
// pass, and is retried there only when one of its neighbourhood leaves
// changed since it failed (its answer depends on nothing else). A capped
// pass that makes few tets is followed by a full pass, where faces try
// every target; a full pass that makes few tets ends the call. Termination: every
// tet has positive volume inside the unmeshed region and the tets made are
// interior-disjoint tets on a fixed finite vertex set, so a call makes
// finitely many tets, and every other pass makes at least one.
// Deterministic: no hash iteration, ties broken by index.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/flat_hash_map.hpp"
#include "core/tet_mesh.hpp"
#include "front/front.hpp"
#include "front/removal_checks.hpp"
#include "octree/octree.hpp"

namespace partet {

struct RemovalOptions {
  int rank = 0;             // leaves owned by another rank are off limits
  double reach = 0.6;       // neighbourhood half-size in longest base edges
  double ahead = 0.5;       // its centre's height above the base face, the same unit
  double min_quality = 0;   // targets whose tet has q below this are ignored
  // Keep as a target a tet that closes a cavity of four faces when its q
  // measures 0 or less in doubles (see above). Only the tree-less rounds'
  // last pass sets it: such a tet, too flat for any point to lie inside
  // it, is the only way to close that cavity (a 2-rank run left one, a
  // positive tet 1e-18 high, on stress-check seed 1790), but made in every
  // pass it turns the CAD parts' flat cavities into tets the tree-less
  // rounds then grow around (pinion r2 31 -> 57 s, t13 r2 14 -> 34 s).
  bool close_flat_cavities = false;
  // Targets best shape first (score q × (1 + closed), the paper's order)
  // instead of in Delaunay order: run_mesh's last attempt, for a front the
  // Delaunay order's attempts could not close (stress-check seed 673 closes
  // this way only).
  bool shape_order = false;
  // Tree-less removals only: rounds in a row without a smaller front before
  // they give up (treeless_removal.hpp; the corpus closes in at most 25
  // rounds; t13 r2 closes in 132, with new smallest fronts more than 32
  // rounds apart).
  size_t stall_rounds = 64;
  // Tree-less removals only: when the default strategy leaves faces, the
  // call starts again from its starting state with each of the first
  // `rescues` rescue strategies in turn (treeless_removal.hpp; at most 3,
  // 0: the default strategy only).
  int rescues = 3;
  // Tree-less removals only: try TreelessStrategy::kShortGrowth before the
  // default strategy (treeless_removal.hpp, "Short growth first").
  bool short_growth_first = true;
  // Tree-less removals only: when a strategy stalls with at most this many
  // faces left, the next one goes on from there before the attempts start
  // over (treeless_removal.hpp, "Short growth first").
  size_t go_on_faces = 64;
  // Tree-less removals only: at most this many attempts from the call's
  // starting state (each a strategy and those going on from it); 1 for a
  // first try whose failure the caller discards (run_mesh on a tree
  // refined for a thin core: short growth, the default going on from a
  // few faces, and no more).
  size_t starts = SIZE_MAX;
  // Tree-less removals only: when no strategy closes the front, run the one
  // that left the fewest faces again (its mesh and front are what the call
  // leaves); false when the caller discards them anyway.
  bool rerun_best = true;
};

// A failure time no face has: never failed.
inline constexpr uint32_t kNeverFailed = UINT32_MAX;

// What earlier calls learnt, so that a call after a local change costs
// what changed, not the whole front. A record per face slot that ever
// failed (about one in eight; a face that never failed has none, so the
// memo grows with the failures, not with every face slot made):
//  - the front's change counter when the face last failed a capped pass
//    (a full failure counts as one too) and a full pass, under
//    `min_quality`. A face whose neighbourhood leaves have not changed
//    since is not retried (its answer depends on nothing else). Valid for
//    one front and one set of RemovalOptions; a call with another
//    min_quality starts these afresh;
//  - why its latest failed try failed, target by target (a run [first,
//    first + count) of `blocked_pool`): a target whose blocker still
//    blocks (still_blocked) is not checked again. Exact on every later
//    front, whatever min_quality: face slots are never reused and a vertex
//    that was ever on the front keeps its index and point, so a blocker
//    still on the front still blocks. The tree-less rounds retry every
//    face near a change; most of their targets are such repeats. Runs of
//    closed or retried faces are garbage, dropped (with the records of
//    closed faces) when the pool holds twice the live runs.
struct RemovalMemo {
  double min_quality = 0;

  struct Blocked {
    uint32_t target;
    RemovalBlocker why;
  };
  struct Record {
    uint32_t failed_capped_at = kNeverFailed;  // 32 bits: 4e9 tets are far beyond one rank
    uint32_t failed_full_at = kNeverFailed;
    uint32_t first = kNoIndex;  // the latest failure's run in blocked_pool
    uint32_t count = 0;
  };
  struct SlotTraits {
    static uint32_t empty() { return kNoIndex; }
    static uint64_t hash(uint32_t f);
  };
  FlatHashMap<uint32_t, Record, SlotTraits> records;
  std::vector<uint32_t> recorded;  // the slots with a record, in the order first recorded
  std::vector<Blocked> blocked_pool;
  size_t live_blocked = 0;

  // Face f's record, or nullptr.
  const Record* find(uint32_t f) const { return records.find(f); }
  // Face f's record, made empty when it has none.
  Record& record(uint32_t f);
  // When face f last failed a full (`full`) or capped pass, or kNeverFailed.
  uint32_t failed_at(uint32_t f, bool full) const;
  // Sets `min_quality`; another one than the memo's forgets every failure
  // time (the runs stay: they hold whatever min_quality).
  void use_min_quality(double q);
  // Follows Front::compact: `new_face` maps old face slots to new ones. A
  // record whose blocking face was closed is dropped (its target is
  // checked again).
  void renumber(const std::vector<uint32_t>& new_face);
};

struct RemovalCounts {
  size_t tets = 0;           // tets made
  size_t faces_left = 0;     // alive faces at the end
  size_t foreign_faces = 0;  // of those, faces skipped for a leaf owned elsewhere
  size_t passes = 0;
  size_t checks = 0;         // candidate tets checked
  size_t skipped_checks = 0; // candidates known to fail again (their blocker is still there)
};

// The neighbourhood box of face f (above), clipped to the root cube.
void removal_neighbourhood(const Front& front, const RootCube& root, uint32_t f, const RemovalOptions& options,
                           double* lo, double* hi);
// The leaves over that box (replacing `leaves`): those a removal on f reads
// and writes, and whose owners decide whether a rank may make it; with
// `listed_only`, only those of Front::listed_leaves (enough for the faces,
// vertices and change stamps there, not for the owners).
void removal_neighbourhood_leaves(const Front& front, const RootCube& root, uint32_t f, const RemovalOptions& options,
                                  std::vector<size_t>& leaves, bool listed_only = false);

// The alive faces whose latest failure `memo` holds (in a full pass with
// `full`, else in a capped one) still stands: none of their neighbourhood
// leaves changed since. A face's answer depends on nothing else, so a copy
// of the front equal to this one over those leaves fails them too.
std::vector<uint32_t> standing_failures(const Front& front, const RootCube& root, const RemovalOptions& options,
                                        const RemovalMemo& memo, bool full);
// Records `faces` as failed now in `memo` (a capped pass, and with `full` a
// full one too), under `min_quality`: failures another copy of the front
// found standing (standing_failures), so that this copy's passes skip them.
void record_failures(const Front& front, const std::vector<uint32_t>& faces, bool full, double min_quality,
                     RemovalMemo& memo);

// Makes tet (base face f, p): appends it to `out`, updates the front
// (`added`: faces made; `shrunk`: leaves whose front lost faces) and
// reclassifies boundary or too-close leaves whose front became empty as
// kDone. Shared by every kind of removal. `cover`: see Front::apply_tet.
void make_removal_tet(Front& front, LinearOctree& tree, TetMesh& out, uint32_t f, uint32_t p,
                      std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk, const LeafCover* cover = nullptr);

// Reclassifies the boundary and too-close leaves of `shrunk` whose front
// is empty as kDone.
void mark_done_leaves(const Front& front, LinearOctree& tree, const std::vector<uint32_t>& shrunk);

// Front::drop_free_vertices, then mark_done_leaves; the number dropped.
size_t drop_free_vertices(Front& front, LinearOctree& tree);

// `front` must be built over `tree` and `root`. `out` receives the tets,
// numbered in the front's vertex numbering: its vertices must be a prefix
// of the front's (e.g. the template core, or empty); the missing front
// vertices are appended (coordinates, and global ids when `out` has them).
//
// With `seeds`, the queue starts with those faces (the alive ones, in the
// given order) instead of every alive face: a local pass after a change.
// With `memo`, failures recorded by earlier calls on the same front are
// used and this call's are added.
RemovalCounts remove_faces_tree_supported(Front& front, LinearOctree& tree, const RootCube& root,
                                          TetMesh& out, const RemovalOptions& options = {},
                                          const std::vector<uint32_t>* seeds = nullptr,
                                          RemovalMemo* memo = nullptr);

}  // namespace partet
