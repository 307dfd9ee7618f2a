// Interior vertex collapse: a free vertex v of a bad tet is merged into one
// of its neighbours w. The tets having both v and w go; every other tet of
// v's star gets w in place of v, so the new tets are the cones from w to
// the faces of v's link that do not have w. v must be free and closed in:
// not frozen, not on a face of one tet (its link is then a closed surface
// around it, and the cones have exactly the star's outer faces), and not a
// vertex this optimizer inserted (collapsing those undid its edge splits).
// The cones tile the star when every one of them is positive by exact
// orient3d (a cone over a link face coplanar with w, which would make an
// edge along the link, is flat and refused). Every neighbour of v is
// tried; the best new worst quality wins and is applied when it pays:
// the star's worst tet improves and either (kShortfall) the shortfall
// below the bar does not grow and no more tets have an angle under 10
// degrees (or over 170), or (kWorstFirst) the smallest dihedral angle does
// not drop and there are no more tets under 10 degrees.
//
// v is left with no tet (its coordinates stay, so indices do not move);
// the caller drops such vertices (drop_unused_vertices) when it writes the
// mesh. What it repairs: an interior vertex stranded a hair from a long
// input edge or a surface vertex (a cap or spindle no move can open: every
// direction flattens another tet of its star), or two interior vertices
// crowding each other.
#pragma once

#include <cstdint>
#include <vector>

#include "optimize/failure_record.hpp"
#include "optimize/insertion.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

// Vertices none of whose collapses paid (failure_record.hpp): a vertex's
// collapses read only its star. The tets of a bad star share its vertices
// and each offered them the same collapses: on handle r1, 72 % of the
// vertices offered had been refused, their stars unchanged (the optimizer
// 0.67 -> 0.59 s, the same meshes byte for byte).
using RefusedCollapses = FailureRecord<&TetTopology::vertex_unchanged_since>;

// Collapses the vertex of tet t whose best collapse pays most; true when
// one was applied. A vertex is free when it has a `frozen` flag and the
// flag is clear (those beyond the flags are the optimizer's own). `bar` is
// the shortfall bar (insertion_bar).
// With `refused` (kept by the caller for one rule and bar), the vertices
// it knows are not tried, and when no collapse pays those tried join it.
bool collapse_vertex(TetTopology& topo, uint32_t t, const std::vector<uint8_t>& frozen, double bar,
                     InsertionRule rule, RefusedCollapses* refused = nullptr);

}  // namespace partet
