// Parallel recursive bisection of weighted points (paper §4.1): ROB, RIB and
// MROB. Used to partition the boundary octants (their centroids, weighted by
// a work estimate) and, with RIB, the final tets.
//
// Contract: collective over `comm` (P ranks). Each rank passes its own points
// (xyz: 3 doubles per point, finite; weight: finite, >= 0). The rank set
// [0, P) is split into floor(P/2) low ranks and ceil(P/2) high ranks; the low
// ranks take the points on the low side of a plane (normal·x <= offset) and
// the high ranks those on the high side (normal·x >= offset), with the low
// side's weight as close as points allow to floor(P/2)/P of the total; both
// halves are split again the same way until every rank set is one rank.
// Points do not move: the result says where each goes (see
// parallel/migrate.hpp to move them). The result depends only on the global
// set of (point, weight) pairs and P, not on how the points are spread over
// the ranks or ordered on them; only exact duplicates (same coordinates and
// weight) are told apart by their global index (rank order, then local order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

enum class BisectionMethod {
  kRob,   // coordinate axes in turn: x at depth 0, y at depth 1, z at 2, x...
  kRib,   // the principal axis of inertia of the weighted points
  kMrob,  // the coordinate axis closest to the principal axis of inertia
};

// One cut of the recursion: ranks [first_rank, mid_rank) got the points with
// normal·x <= offset (project() below), ranks [mid_rank, last_rank) those
// with normal·x >= offset. Points exactly on the plane may be on either side.
struct Separator {
  double normal[3];  // unit; a coordinate axis for ROB and MROB
  double offset;     // midway between the last low point and the first high one
  int axis;          // 0, 1, 2 when normal is that coordinate axis; -1 otherwise
  int first_rank, mid_rank, last_rank;
  int depth;         // 0 for the first cut, log2(P) - 1 (rounded up) for the last
};

struct PartitionResult {
  std::vector<int32_t> destination;   // per local point: the rank it goes to
  std::vector<Separator> separators;  // every cut, depth by depth, by first_rank
};

// normal·x, evaluated the same way everywhere the side of a point is decided.
inline double project(const double normal[3], const double x[3]) {
  return normal[0] * x[0] + normal[1] * x[1] + normal[2] * x[2];
}

PartitionResult partition_points(const Comm& comm, const double* xyz, const double* weight, size_t n,
                                 BisectionMethod method = BisectionMethod::kMrob);

}  // namespace partet
