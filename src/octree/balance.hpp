// 2:1 balance of a linear octree across octant faces and edges: after it,
// any two leaves that share a face or a positive length of an edge differ by
// at most one level (corners are not constrained). Leaves only get split.
// With a grading radius R >= 2 the rule reaches further: for every leaf of
// level L, the (2R + 1)^3 octants of level L - 1 centred on its parent
// (corners included) exist: around an octant split finer, its size holds
// for R octants in every direction before a coarser leaf (grading 1 is the
// plain rule: the parent's 18 face and edge neighbours).
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
// balanced refinement, the same as the work queue's (with a wider block,
// the same argument: a leaf's siblings share its parent, hence its block).
// Cost: the blocks of the parents sharing a grandparent are gathered in one
// bit mask over the grandparent's (2R + 2)^3 block (so shared octants are
// emitted once), a table of recent keys drops most repeats between
// neighbouring grandparents' blocks, and the required octants are sorted
// once per level: O(n log n) for n leaves, times the block's size.
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

// The widest grading radius accepted.
inline constexpr int kMaxGrading = 4;

// Precondition: `tree` is complete, 1 <= grading <= kMaxGrading. New leaves
// keep their parent's class and owner.
void balance_octree(LinearOctree& tree, int grading = 1);

// The required octants of the leaves of `leaves` (sorted, disjoint; not
// necessarily complete), as refinement requests sorted by key; they may lie
// anywhere in the root cube. balance_octree(t, g) is refine_octree(t,
// balance_requests(t, g)).
std::vector<RefineRequest> balance_requests(const LinearOctree& leaves, int grading = 1);

// True when `tree` is 2:1 balanced across faces and edges (checked with
// neighbour queries on every leaf: its 6 faces and 12 edges).
bool is_balanced(const LinearOctree& tree);

// True when `tree` (complete) meets the rule of grading radius `grading`
// (checked by locating the centre of every octant of each leaf's block).
bool is_graded(const LinearOctree& tree, int grading);

}  // namespace partet
