// The pipeline's tree-supported face removals (paper §4.1 step 4, and the
// finishing steps on rank 0), on one rank or on P:
//  - one rank: a pass taking only well-shaped tets (kShapedRemovalQuality),
//    then one taking any valid tet, over the whole front;
//  - P ranks: every rank holds the whole tree, core and initial front
//    (gathered everywhere) and the leaves' owners (leaf_owners.hpp: the
//    boundary partition's, the separators' for the other leaves). The
//    shaped pass, then the plain one, each runs over the whole front as on
//    one rank, in rounds: each rank runs the pass on its copy, making only
//    the removals whose neighbourhood leaves are all its own (removals
//    never communicate), so two ranks' tets never touch one leaf and are
//    valid together; then every rank merges the other ranks' front changes
//    into its copy, in rank order (Front::merge: the front their tets would
//    give if made again there), so that the copies hold the same faces
//    again. The faces none could remove for a leaf of another rank (the
//    interfaces along the cuts) are spread over the ranks by new owners
//    (interface_owners.hpp: the paper's repartitioning of the face, edge
//    and vertex interfaces, steps 5-9), and the ranks run the pass again
//    from those faces, up to kInterfaceRounds times while the interfaces
//    shrink; then rank 0 alone runs it from the faces still across the
//    ranks, and the others take in its changes. At the end rank 0 appends
//    the other ranks' tets to its mesh and records the failures their
//    plain passes found that still stand (standing_failures), so that the
//    tree-less removals do not try those faces again.
// Afterwards, on rank 0, the gap vertices no tet took are dropped and the
// front is compacted; the other ranks end with no front and an empty mesh.
// The counts: the tets, faces left, passes and checks of the step; on P > 1
// ranks also, per rank, the tets its passes made, the faces its copy had
// left after the first round and how many of those it skipped for a leaf
// of another rank (the faces of the other ranks' leaves among them), its
// passes' and its merges' wall time; per pass the interface faces after
// each round, and the tets and time of rank 0's passes alone.
#pragma once

#include <memory>
#include <vector>

#include "core/tet_mesh.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "partition/recursive_bisection.hpp"
#include "pipeline/report.hpp"

namespace partet {

// Targets of the first pass make tets at least this well shaped (q of
// face_removal.hpp).
constexpr double kShapedRemovalQuality = 0.05;

// Rounds on the interfaces after the first on P > 1 ranks (face, then edge
// interfaces; what the last leaves is finished on rank 0).
constexpr int kInterfaceRounds = 2;

// The boundary partition's result, for P > 1 ranks.
struct RankLeaves {
  const LinearOctree* own = nullptr;             // this rank's boundary leaves after step 3
  const std::vector<Separator>* separators = nullptr;
};

// Collective. `initial`, `tree` and `mesh` (the templated core, in the
// front's vertex numbering) are whole on every rank that takes part (on one
// rank, on it). On return `front` is rank 0's front (null elsewhere),
// `mesh` rank 0's tets (empty elsewhere) and `memo` what rank 0's passes
// learnt. `ranks` is ignored on one rank. `shape_order`: targets best
// shape first (RemovalOptions::shape_order). `on_root`: on P > 1 ranks,
// rank 0 alone makes the removals over its whole front, as on one rank
// (run_mesh's retries: the front it leaves is one rank's), and `ranks` is
// ignored.
ojson tree_removal_step(const Comm& comm, const InitialFront& initial, LinearOctree& tree, const RootCube& root,
                        TetMesh& mesh, const RankLeaves& ranks, std::unique_ptr<Front>& front, RemovalMemo& memo,
                        bool shape_order, bool on_root);

}  // namespace partet
