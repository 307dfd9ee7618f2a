// 2:1 balance of a linear octree across octant faces and edges: after it,
// any two leaves that share a face or a positive length of an edge differ by
// at most one level (corners are not constrained). Leaves only get split.
//
// Method (equivalent to the paper's work queue, which splits a too-coarse
// neighbour and queues the children, but without inserting into the sorted
// array one split at a time). Balance holds iff, for every leaf o of level
// L, the 18 face and edge neighbours of o's parent, at level L - 1, exist as
// octants of the tree (are leaves or split): a sibling of o touches each of
// them, and a leaf coarser than L - 1 over one of them would touch that
// sibling. So, level by level from the deepest: the distinct parents of the
// octants required at level L, and their 18 neighbours inside the root, are
// required at level L - 1 (queued as "must exist" octants); all required
// octants are then made to exist in one splice (refine_octree). Every
// required octant is forced by some leaf, so the result is the coarsest
// balanced refinement, the same as the work queue's. Cost: the neighbours of
// the parents sharing a grandparent are gathered in one 4 x 4 x 4 bit mask
// (so shared ones are emitted once), and the required octants are sorted
// once per level: O(n log n) for n leaves.
//
// The required octants of a set of leaves are the union of each leaf's own
// (they depend on the leaf alone), so a distributed tree is balanced by
// computing them per rank and sending each to the rank holding its anchor
// (octree/distributed_build.hpp).
#pragma once

#include <vector>

#include "octree/build.hpp"
#include "octree/octree.hpp"

namespace partet {

// Precondition: `tree` is complete. New leaves keep their parent's class and
// owner.
void balance_octree(LinearOctree& tree);

// The required octants of the leaves of `leaves` (sorted, disjoint; not
// necessarily complete), as refinement requests sorted by key; they may lie
// anywhere in the root cube. balance_octree(t) is refine_octree(t,
// balance_requests(t)).
std::vector<RefineRequest> balance_requests(const LinearOctree& leaves);

// True when `tree` is 2:1 balanced across faces and edges (checked with
// neighbour queries on every leaf: its 6 faces and 12 edges).
bool is_balanced(const LinearOctree& tree);

}  // namespace partet
