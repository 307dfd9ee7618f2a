// The quality measure the optimizer maximises: the smallest sine of the six
// dihedral angles of a tet, scaled so that the regular tet scores 1. It is
// small for every bad shape (slivers, needles, caps, wedges: an angle near 0
// or near 180 degrees), scale-free, and costs no trigonometry:
//   sin(dihedral at edge ij) = 6 V |p_i - p_j| / (|n_k| |n_l|)
// where n_k, n_l are the (twice-area) normals of the two faces at the edge.
// V is signed, so an inverted tet scores below 0; a flat one (or one with a
// zero-area face) scores 0. This is
// a heuristic in doubles: validity is always decided by exact orient3d.
#pragma once

#include <cmath>

namespace partet {

// 1 / sin(arccos(1/3)): the sine of the regular tet's dihedral angle is 2 sqrt(2) / 3.
inline constexpr double kRegularSineScale = 1.0606601717798212;

double tet_quality(const double* p0, const double* p1, const double* p2, const double* p3);

// tet_quality and its gradient with respect to vertex p[j] (j in 0..3), in
// `gradient`. Where two edges tie for the smallest sine the measure has a
// kink; the gradient is then that of the edge listed first (01, 02, 03,
// 12, 13, 23), one of the one-sided gradients. 0 and a zero gradient for a
// tet with a zero-area face.
double tet_quality_gradient(const double* const p[4], int j, double gradient[3]);

// The quality threshold of an angle: a tet scores at least
// quality_of_angle(a) exactly when its dihedral angles all lie in
// [a, 180 - a] degrees (0 < a <= 90).
inline double quality_of_angle(double degrees) {
  return std::sin(degrees * 3.14159265358979323846 / 180) * kRegularSineScale;
}

}  // namespace partet
