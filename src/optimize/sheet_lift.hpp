// Sheet lifting: free vertices that sit a hair off one plane, in nearly
// flat tets with vertices on that plane, moved together along its normal.
//
// The tree-less removals can leave such a sheet on a flat part of the
// surface (oblong r2: 16 vertices 1e-12 to 7e-6 above a planar pocket
// ceiling, in 107 tets under 1e-6 degrees). No single vertex can rise:
// each shares a flat tet with another vertex of the sheet that lifting it
// alone would invert; a flip, an insertion or a collapse inverts or flattens
// tets too, and the joint smoothing's gradients of such tets are useless.
//
// Moving the vertices v_1..v_k by s_1..s_k along one unit direction n, a
// tet's orientation determinant is an affine function of the s: the
// determinant is linear in each of its rows, and every term with two rows
// along n vanishes. So the displacements that maximise the smallest
// determinant over the tets around the vertices, each divided by its sine
// scale (max over its edges of 4 A_i A_j / l_e, the areas of the two faces
// at the edge and its length, taken at the current shape: the quotient is
// then the smallest sine of its dihedral angles), solve a linear program
// (core/linear_program.hpp) with |s_i| at most half the mean edge length
// at v_i. The move is kept only when every tet around the vertices is
// positive by exact orient3d, their smallest dihedral angle rises and no
// more of them have one under 10 degrees (a move of half or a quarter of
// the solution is tried when the whole one is not kept).
#pragma once

#include <cstdint>
#include <vector>

#include "optimize/tet_topology.hpp"

namespace partet {

// Tets with a dihedral angle under this many degrees are flat enough for
// lift_sheet to take their free corners in.
constexpr double kSheetAngle = 1;

// Lifts the sheet of tet `worst`: its free corners (not `frozen`: one flag
// per vertex, those beyond are free) and, breadth first, the free corners
// of the tets under kSheetAngle in their stars, at most 64, moved along the
// normal of the largest face of `worst` as above. True if they moved.
bool lift_sheet(TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen);

}  // namespace partet
