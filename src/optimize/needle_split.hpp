// Needle splits: the radius-ratio counterpart of the optimizer's angle
// work. On CAD parts with needle surface triangles the removals leave
// needles inside the body (handle r1: half its tets under radius ratio 0.3,
// median edge ratio 6) whose dihedral angles are fair, so the passes, which
// raise the smallest angle, leave them alone; TetGen's radius-edge
// refinement splits them. Here each tet under a radius ratio bar, worst
// first, has its longest edge split at the midpoint when that edge is
// interior (its ring of tets closes): the ring's tets (a, b, r_k, r_k+1)
// become (m, b, ...) and (a, m, ...), every one positive by exact
// orient3d, and the new vertex m is smoothed (smooth_vertex). The split is
// kept when the ring's smallest dihedral angle does not drop, no more of
// its tets are under 10 degrees, and the radius ratios gain at least the
// mesh's mean per tet added (so the mean rises); else the ring is put back
// as it was. Up to four rounds: after the first, over the needles the
// previous round's splits made (the refused rings are unchanged, so trying
// them again would be refused again); within a sweep a refused ring is not
// tried again for another needle around the same edge (FailedSplits: 37 %
// of handle r1's trials). Deterministic; the boundary and the
// frozen vertices are untouched (m is new and free).
#pragma once

#include <cstddef>

#include "optimize/smoothing.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

// One sweep over the tets under radius ratio `bar` at its start (and the
// rounds after it); the number of edges split.
size_t split_needles(TetTopology& topo, double bar, SmoothingScratch& scratch);

}  // namespace partet
