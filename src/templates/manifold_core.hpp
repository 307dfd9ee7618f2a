// Makes the set of interior leaves "manifold", between classification and
// templating: afterwards the union of the closed interior leaf boxes (the
// templated core) is a 3-manifold with boundary, so its boundary, the core
// sheet of the initial front, is a closed 2-manifold: every front edge is
// used by exactly two faces (in opposite directions) and the faces around
// every front vertex form one fan. Two interior leaves touching only along an
// edge or only at a corner would otherwise give edges used by four faces and
// pinched vertices.
//
// Local test. Around a lattice point p, the 8 octants (o: bit k set for the
// octant on the high side of axis k) each lie in one leaf; the occupancy of
// p is the mask of the octants whose leaf is interior. The core is a
// manifold at p iff that mask is empty, full, or its trace on a small sphere
// around p (the octahedron whose faces are the octants) is one closed disk:
// around each of the 6 half-axes from p the occupied octants are not two
// opposite ones (that is the edge test: a diagonal pair of quadrants around
// the edge leaving p along that half-axis), and both the occupied and the
// free octants are connected across octant faces. Only the corners of the
// interior leaves are tested: at any other point of the core, some axis is
// inside every interior leaf containing the point (leaves are aligned to
// their size, so of two leaves containing it the smaller one has it on its
// boundary along every axis where the larger one does), so the occupancy is
// the same along that axis; it is then non-manifold only on a leaf edge
// between two opposite interior quadrants, and such an edge ends at corners
// of interior leaves, whose half-axis test sees it.
//
// Mixed levels. The interior leaves containing a leaf corner p have p as a
// corner, an edge midpoint or a face centre (2:1 balance across faces and
// edges; face_rule.hpp), i.e. as one of their 26 boundary lattice points,
// where each covers 1, 2 or 4 octants. So the occupancy of every such p is
// gathered exactly by letting each interior leaf mark its 26 points at their
// homes (leaf_neighbourhood.hpp), one byte per child anchor of a leaf.
//
// Repair. A non-manifold point is fixed by demoting (to kTooClose: inside
// the domain, left to the advancing front) some of the interior leaves
// around it: the leaves kept are a largest set (most octants, then most
// volume; ties go to the first set, leaves numbered in octant order) whose
// occupancy is manifold. Demoting a leaf clears its octants at its 26
// points, and those of them that are tested (the corners of the leaves that
// were interior when the pass began: a superset of the points to test,
// whose occupancy stays exact since they are leaf corners) are queued for
// the next round; rounds go on until no tested point is non-manifold. Termination: every repair demotes at least one leaf (the full
// occupancy is not manifold, the empty one is), and leaves are only ever
// demoted, so there are at most as many repairs as interior leaves.
// Afterwards every tested point is manifold, so a second pass demotes
// nothing.
//
// Cost: one pass over the interior leaves (7 leaf searches and 26 homes
// each) and one scan of the per-leaf bytes; then work only around
// non-manifold points. Deterministic.
//
// Distributed (make_core_manifold with a Comm): each rank holds a local view
// (octree/ghost_layer.hpp) and tests the points homed on its own leaves,
// whose occupancy its own and layer-1 leaves give exactly. A round repairs
// the queued points in the serial order, which is rank order (leaves are
// Morton-contiguous by rank): rank after rank, each broadcasting the leaves it
// demoted before the next one starts, so every repair sees what it sees
// serially and the classes end as the serial pass leaves them. One
// broadcast per rank with points to repair per round; rounds are few.
#pragma once

#include <cstddef>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"

namespace partet {

struct ManifoldCoreCounts {
  size_t demoted = 0;     // interior leaves made kTooClose
  size_t repaired = 0;    // non-manifold points repaired
  size_t rounds = 0;      // rounds of repairs (0: the interior set was manifold)
  size_t interior = 0;    // interior leaves left
};

// Precondition: `tree` is complete, sorted and 2:1 balanced across faces and
// edges, and classified (classify_leaves). Only changes kInterior to
// kTooClose.
ManifoldCoreCounts make_core_manifold(LinearOctree& tree);

// Collective: the same over all ranks, `view` being this rank's local view
// (ghost_view) of a complete, balanced, classified distributed tree; sets
// the classes of its own and ghost leaves. Counts are summed over ranks.
ManifoldCoreCounts make_core_manifold(const Comm& comm, LinearOctree& view);

// True when the octant occupancy `mask` of a point is a manifold (see above).
bool manifold_occupancy(unsigned mask);

}  // namespace partet
