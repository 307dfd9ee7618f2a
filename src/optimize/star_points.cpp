// StarPoints (see star_points.hpp): the corners scattered into columns
// once per star, the measures by the tet kernels (tet_kernels.hpp).
#include "optimize/star_points.hpp"

#include <algorithm>

#include "core/predicates.hpp"
#include "optimize/tet_kernels.hpp"

namespace partet {

void StarPoints::load(const TetTopology& topo, uint32_t v, std::span<const uint32_t> quads) {
  placed_ = false;
  n_ = quads.size() / 4;
  coordinates_.resize(12 * n_);
  corner_of_v_.resize(n_);
  for (size_t k = 0; k < n_; ++k) {
    const uint32_t* t = &quads[4 * k];
    for (int j = 0; j < 4; ++j) {
      if (t[j] == v) {
        corner_of_v_[k] = static_cast<uint8_t>(j);
        continue;
      }
      const double* p = topo.point(t[j]);
      for (int i = 0; i < 3; ++i) coordinates_[(3 * static_cast<size_t>(j) + i) * n_ + k] = p[i];
    }
  }
}

void StarPoints::place(const double* x) {
  // A trial measures one point several ways (radius ratios, qualities,
  // orientations): v's corners are written once per point.
  if (placed_ && x[0] == at_[0] && x[1] == at_[1] && x[2] == at_[2]) return;
  placed_ = true;
  std::copy_n(x, 3, at_);
  for (size_t k = 0; k < n_; ++k)
    for (int i = 0; i < 3; ++i) coordinates_[(3 * static_cast<size_t>(corner_of_v_[k]) + i) * n_ + k] = x[i];
}

void StarPoints::qualities(double* out) const {
  const TetColumns p = columns();
  tet_qualities(p, n_, out);
}

void StarPoints::radius_ratios(double* out) const {
  const TetColumns p = columns();
  tet_radius_ratios(p, n_, out);
}

void StarPoints::circumcentre_terms(double* det, double* x, double* y, double* z) const {
  const TetColumns p = columns();
  partet::circumcentre_terms(p, n_, det, x, y, z);
}

bool StarPoints::all_positive() const {
  const TetColumns p = columns();
  signs_.resize(n_);
  orient3d_filters(p, n_, signs_.data());
  for (size_t k = 0; k < n_; ++k) {
    if (signs_[k] > 0) continue;
    if (signs_[k] < 0) return false;
    double q[4][3];
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 3; ++i) q[j][i] = p.c[3 * j + i][k];
    if (detail::orient3d_exact(q[0], q[1], q[2], q[3]) <= 0) return false;
  }
  return true;
}

}  // namespace partet
