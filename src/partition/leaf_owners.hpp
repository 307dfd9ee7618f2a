// Who owns every leaf of the whole tree for the distributed face removals
// (paper §4.1 step 4): the boundary and too-close leaves are owned by the
// rank the boundary partition (step 3) sent them to; every other leaf
// (interior, outside) by the rank whose side of the partition's separators
// its centre lies on (the low side of a separator when exactly on it).
// Interior leaves hold front entities too (the templated core's exposed
// faces and their vertices are listed in the leaf that templated them), so
// each needs one owner: a face removal is made by a rank only when every
// leaf over its neighbourhood is the rank's own, so the removals of two
// ranks never touch the same leaf, and their tets, made apart, are valid
// together (docs/decisions.md, "Face removals on the ranks").
#pragma once

#include <vector>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "partition/recursive_bisection.hpp"

namespace partet {

// The rank whose side of `separators` (from partition_points over P ranks)
// point p lies on.
int rank_of_point(const std::vector<Separator>& separators, int ranks, const double* p);

// Collective. `tree` is the whole tree (the same on every rank); `own` the
// boundary leaves this rank got in step 3 (keys sorted); sets tree.owner on
// every rank, identically.
void set_leaf_owners(const Comm& comm, const LinearOctree& own, const std::vector<Separator>& separators,
                     const RootCube& root, LinearOctree& tree);

}  // namespace partet
