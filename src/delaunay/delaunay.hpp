// Delaunay tetrahedralization of a point set by incremental insertion
// (Bowyer-Watson), exact throughout.
//
// The points go in in a biased randomized order (rounds doubling in size,
// each in Morton order; see insertion_order in delaunay.cpp), into an
// enclosing tet whose four corners lie far outside their bounding box.
// Each point is located by a visibility walk from the last tet made
// (exact orient3d; the face tried first rotates from step to step; past a
// step budget, which a Delaunay tetrahedralization's acyclic walks do not
// reach, the tets are scanned). Its cavity is every tet whose circumsphere
// holds it strictly (exact insphere), grown by adjacency from the tet
// holding it. Cospherical points are common here (lattice points of the
// octree's core); a tie counts as outside, and the cavity is still
// star-shaped from the point with every boundary face strictly visible:
// for a face between a tet T in conflict and a tet T' not, the point's
// power with respect to T's sphere minus its power with respect to T''s
// is an affine function vanishing on the face's plane. At the point it is
// negative. At T's opposite vertex it is at most 0 (the vertex is on T's
// sphere, on or outside T''s), and not 0: the function would then vanish
// everywhere, the spheres would be one, and the point inside T's would be
// inside T''s. So the point lies strictly on T's side of the face: every
// new tet (the point coned to a boundary face) is positively oriented, no
// tet is flat, and the result is a Delaunay tetrahedralization (one of
// them when points are cospherical: the one this insertion order gives).
// The new tets are linked to each other through their directed edges in a
// table over the cavity boundary's vertices (delaunay.cpp, make_tets); the
// builder keeps the points in insertion order, so the points of nearby tets
// sit close in memory. Deterministic: fixed order, fixed tie-breaking.
//
// Output: the input points' tets and the enclosing tet's (those using one
// of its corners, vertex indices n .. n+3), compacted, with adjacency.
// Distinct points are required; a point equal to an earlier one throws
// InternalError naming both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet {

constexpr uint32_t kNoNeighbour = UINT32_MAX;

struct DelaunayTets {
  size_t num_points = 0;      // n: the input points; vertices n .. n+3 are the enclosing tet's corners
  std::vector<double> xyz;    // 3 per vertex: the input points, then the corners
  std::vector<uint32_t> tets;  // 4 vertex indices per tet, orient3d > 0
  // 4 per tet: 4 u + j when face i of tet t (opposite its vertex i) is
  // face j of tet u; kNoNeighbour on the enclosing tet's faces.
  std::vector<uint32_t> neighbours;
  size_t walk_steps = 0;      // tets visited by the point locations
  size_t cavity_tets = 0;     // tets replaced by the insertions
  size_t largest_boundary = 0;  // vertices on the boundary of the largest cavity

  size_t num_tets() const { return tets.size() / 4; }
  bool finite(size_t t) const {
    for (int k = 0; k < 4; ++k)
      if (tets[4 * t + k] >= num_points) return false;
    return true;
  }
};

// The Delaunay tetrahedralization of the points `xyz` (3 per point, finite,
// pairwise distinct).
DelaunayTets delaunay_tetrahedralize(const std::vector<double>& xyz);

}  // namespace partet
