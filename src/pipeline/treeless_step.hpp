// The pipeline's tree-less face removals (paper §4.1 step 10) on one rank
// or on P (treeless_removal.hpp for the removals themselves):
//  - one rank: remove_faces_treeless on the front the tree-supported
//    removals left, with their memo; on P ranks by default the same on
//    rank 0, with every leaf its own: on 2 ranks that measured faster
//    than the rounds below (docs/decisions.md, "Tree-less removals on rank
//    0 alone by default");
//  - P ranks with `on_ranks` (--treeless-on-ranks), in rounds: rank 0
//    sends every rank the front (its vertices beyond the initial front's,
//    its faces in slot order), the mesh's tets and the memo's failures
//    that still stand (standing_failures), and
//    every rank builds the same front from them. The leaves are owned
//    anew: the front's faces are cut into P equal shares by inertial
//    bisection of their centroids (interface_owners.hpp) and every leaf
//    goes to the side its centre lies on. Each rank runs the default
//    strategy's rounds (run_treeless_rounds) on the components it owns
//    with room around them, touching only its own leaves (new vertices,
//    tets made and tets deleted), so what two ranks do is disjoint and
//    valid together, as for the tree-supported removals (docs/decisions.md,
//    "Tree-less removals on the ranks"). Rank 0 takes in the other ranks'
//    work in rank order: their new vertices (numbered after its own, rank
//    by rank), the tets they deleted and made, and their front changes
//    (Front::merge). Another round follows (at most kTreelessRankRounds)
//    while a round closes more than a quarter of the faces: the next cut
//    crosses the components the last one split. Rank 0 then takes every
//    leaf as its own and runs remove_faces_treeless, with its rescues, on
//    what is left.
// On return `front`, `mesh` and `memo` are rank 0's (the other ranks end
// with no front and an empty mesh), and `note` says how the removals ended
// when they left faces (for the error).
#pragma once

#include <memory>
#include <string>

#include "core/tet_mesh.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "pipeline/report.hpp"

namespace partet {

// Rounds of the tree-less removals on the ranks before rank 0 finishes.
constexpr int kTreelessRankRounds = 3;
// The ranks' rounds stop after this many rounds in a row without a smaller
// front (RemovalOptions::stall_rounds; rank 0's own pass afterwards keeps
// the default): a rank that churns at the edge of what it owns leaves that
// to rank 0 sooner.
constexpr size_t kRankStallRounds = 16;

// Collective. `initial` is the initial front (the same on every rank): the
// vertices of the front and of the mesh, whose numbering the tree-supported
// removals kept. `front`, `mesh` and `memo` are rank 0's after the
// tree-supported removals (null, empty and empty elsewhere). Without
// `on_ranks` (or on one rank) rank 0 makes the removals alone. `options`
// (its strategies: starts, short growth first, rescues) go to rank 0's
// remove_faces_treeless.
ojson treeless_step(const Comm& comm, const InitialFront& initial, LinearOctree& tree, const RootCube& root,
                    TetMesh& mesh, std::unique_ptr<Front>& front, RemovalMemo& memo, std::string& note,
                    bool on_ranks, const RemovalOptions& options);

}  // namespace partet
