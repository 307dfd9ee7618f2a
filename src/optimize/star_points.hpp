// The corner points of a vertex's star laid out by coordinate (structure of
// arrays), so that the smoothing and relaxation trials measure every tet of
// the star at a trial point in one loop the compiler vectorizes
// (tet_kernels.hpp): tet_quality and tet_radius_ratio bit for bit, so the
// meshes do not change. The orientations are orient3d's: its filter on
// every tet, its exact path where that is not certain.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "optimize/tet_kernels.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

class StarPoints {
 public:
  // The tets `quads` (vertex quadruples, each having v, in their vertex
  // order) with the points of `topo`; v's point is set by place().
  void load(const TetTopology& topo, uint32_t v, std::span<const uint32_t> quads);
  // Puts v at x in every tet (nothing to do when it is there already).
  void place(const double* x);
  size_t size() const { return n_; }
  // tet_quality of each tet, in out[0 .. size()).
  void qualities(double* out) const;
  // tet_radius_ratio of each tet, in out[0 .. size()).
  void radius_ratios(double* out) const;
  // circumcentre_terms (tet_kernels.hpp) of each tet: det, x, y, z.
  void circumcentre_terms(double* det, double* x, double* y, double* z) const;
  // True when orient3d is positive for every tet (its filter on all at
  // once, the exact path for the uncertain ones).
  bool all_positive() const;

 private:
  // Coordinate i of corner j of tet k: coordinates_[(3 * j + i) * n_ + k].
  TetColumns columns() const { return column_view(coordinates_.data(), n_); }

  size_t n_ = 0;
  std::vector<double> coordinates_;
  std::vector<uint8_t> corner_of_v_;  // per tet
  bool placed_ = false;  // v's corners hold at_
  double at_[3] = {0, 0, 0};
  mutable std::vector<double> signs_;  // all_positive's filter, per tet
};

}  // namespace partet
