// Exact inside/outside test of points against a whole closed surface (all its
// shells: inside = an odd number of crossings, so cavities and disjoint
// bodies work), accelerated for many queries.
//
// A ray from p in one fixed direction d crosses only triangles whose
// projection along d contains the projection of p. The projections (onto a
// plane orthogonal to d, in floating point) of the triangles are binned
// into a uniform 2-D grid, with their bounding rectangles grown by a margin
// far above the rounding error, so the cell of p lists a superset of the
// crossed triangles; the crossings themselves are decided exactly (orient3d
// on the segment from p to a point far along d). A ray that touches an edge or
// a vertex falls back to the unaccelerated exact test of shell_nesting
// (point_inside_shell, which tries other directions).
#pragma once

#include <cstdint>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace partet {

class RayParityIndex {
 public:
  // Keeps a reference to `surface` (closed, non-self-intersecting).
  explicit RayParityIndex(const SurfaceMesh& surface);

  // Exact: point p, not on the surface, lies inside the volume it bounds.
  bool inside(const double* p) const;

 private:
  bool inside_slow(const double* p) const;
  const SurfaceMesh& surface_;
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};  // bounding box of the surface
  double reach_ = 0;    // the bounding box grown by this holds the accelerated queries
  double u_[3] = {0, 0, 0}, v_[3] = {0, 0, 0};    // projection basis, orthogonal to the ray
  double u0_ = 0, v0_ = 0, cell_u_ = 1, cell_v_ = 1;
  uint32_t cells_u_ = 1, cells_v_ = 1;
  std::vector<uint32_t> first_;  // per cell, plus one (compressed rows)
  std::vector<uint32_t> tris_;
};

}  // namespace partet
