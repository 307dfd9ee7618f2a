// Measures of many tets at once, their corners by coordinate (structure
// of arrays), in loops the compiler vectorizes. Each repeats, per tet, the
// expressions of its scalar counterpart in the same order (no fused
// products: the build has -ffp-contract=off), so the values are the same
// bit for bit (tests/optimize/test_star_points.cpp holds them to it).
// Branches become selects, so the loops have none.
#pragma once

#include <cstddef>

namespace partet {

// Coordinate i of corner j of tet k at c[3 j + i][k].
struct TetColumns {
  const double* c[12];
};
// The columns of an array holding them one after the other, `stride`
// apart.
inline TetColumns column_view(const double* data, size_t stride) {
  TetColumns p;
  for (size_t c = 0; c < 12; ++c) p.c[c] = data + c * stride;
  return p;
}

// tet_quality (tet_quality.hpp) of each tet, in out[0 .. n).
void tet_qualities(const TetColumns& p, size_t n, double* out);
// tet_radius_ratio (check/quality.hpp) of each tet.
void tet_radius_ratios(const TetColumns& p, size_t n, double* out);
// orient3d's filter (core/predicates.hpp) on (p0, p1, p2, p3): 1 or -1
// where it is certain of the sign, 0 where the exact path must decide.
void orient3d_filters(const TetColumns& p, size_t n, double* out);
// The optimal Delaunay point's terms (smoothing.cpp, odt_point): det = 6
// times the signed volume, and det times the circumcentre, per coordinate
// (meaningless where det is not positive).
void circumcentre_terms(const TetColumns& p, size_t n, double* det, double* x, double* y, double* z);

}  // namespace partet
