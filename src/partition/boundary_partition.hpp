// Step 3 of the pipeline (paper §4.1): the boundary leaves, the leaves left
// to the advancing front, partitioned by recursive bisection of their
// centres weighted by their work (front_part.hpp: the number of front faces
// a leaf owns). The partition only decides where each leaf goes;
// migrate_front_part moves it there with its faces and vertices.
//
// Why that weight: face removals take the front faces one by one, and a
// removal's cost is local (a neighbourhood of the face's size), so the work
// of a rank is about the number of faces in its leaves. Leaves with no face
// (too-close leaves deep in the gap) weigh nothing: they go with the side
// their centre falls on and only cost a record to move.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "partition/front_part.hpp"
#include "partition/recursive_bisection.hpp"

namespace partet {

// The centre of the octant with anchor key `key` and level `level`: a
// lattice point, so exact.
void octant_centre(const RootCube& root, uint64_t key, int level, double* centre);

// Collective: partition_points over every rank's leaves of `part` (their
// centres, weights leaf_work). destination[i] is where leaf i goes.
PartitionResult partition_front_leaves(const Comm& comm, const FrontPart& part, const RootCube& root,
                                       BisectionMethod method);

// Collective: the largest rank total of the leaves' work over the mean rank
// total (1 when there is no work at all).
double work_imbalance(const Comm& comm, const FrontPart& part);

}  // namespace partet
