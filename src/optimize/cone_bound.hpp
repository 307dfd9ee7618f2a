// An upper bound on what inserting a vertex into a cavity can achieve,
// whatever the vertex's position: the insertion (insertion.hpp) cones a
// new vertex to the cavity's outer faces and keeps it only when the worst
// new tet beats the cavity's worst, so a cavity whose bound does not beat
// its worst tet is not tried at all (no trial point, no kernel point).
//
// The bound: where exactly two outer faces meet at an edge, the two cones
// on them share the face through the edge and the new vertex, so their
// dihedral angles at the edge sum to the cavity's interior angle phi there
// (the sum of its tets' dihedral angles at the edge), and the smaller of
// the two sines is at most sin(phi / 2). Hence no cone set has a worst
// tet_quality above kRegularSineScale * sin(phi / 2) at any such edge; a
// single regular tet, whose centroid cones reach it, shows it is tight.
#pragma once

#include <cstdint>
#include <span>

#include "optimize/tet_topology.hpp"

namespace partet {

// kRegularSineScale * sin(phi / 2), minimised over the edges where exactly
// two outer faces of `cavity` (alive, distinct tets) meet; +infinity when
// there is none. Doubles (atan2 of the angles): for tests and reports.
double cone_quality_bound(const TetTopology& topo, std::span<const uint32_t> cavity);

// False when the bound is below `worst` by a margin that covers rounding
// (a relative 1e-6 of the angle, and no verdict for worst under 1e-4 or
// over a 45-degree tet's quality): then no vertex in `cavity` can make
// tets whose worst quality is above `worst`. The angles are summed as
// unit complex numbers (no trigonometry per edge).
bool cones_can_beat(const TetTopology& topo, std::span<const uint32_t> cavity, double worst);
// The same for the cavity of a closed ring of tets around an edge (the
// insertion's and the needle splits' edge splits), read from the ring.
bool cones_can_beat(const TetTopology& topo, const TetTopology::Ring& ring, double worst);

// The same bound on angles: the smallest dihedral angle of a cone set is
// at most phi / 2 at every such edge. False when some edge's phi (in
// [0, pi]) is under twice `angle` (radians) by a relative margin of 1e-6:
// then no vertex in `cavity` can make tets whose smallest dihedral angle
// reaches `angle`. No verdict (true) for `angle` under 1e-6 or over pi / 2.
bool cones_can_keep_angle(const TetTopology& topo, std::span<const uint32_t> cavity, double angle);
bool cones_can_keep_angle(const TetTopology& topo, const TetTopology::Ring& ring, double angle);

}  // namespace partet
