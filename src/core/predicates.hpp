// Exact geometric predicates on double coordinates: a floating-point filter
// with an exact expansion-arithmetic fallback, so the sign is always right.
// Points are `const double*` to 3 coordinates (x, y, z), or 2 for orient2d.
//
// Exact for every finite double input, whatever the exponents (tiny,
// subnormal, huge, mixed). Three stages:
//  1. inline filter: the determinant in doubles with a rigorous forward error
//     bound (C * permanent, plus an absolute term that covers products lost
//     to underflow); overflow makes the bound inf/NaN, which falls through;
//  2. expansion arithmetic (expansion.hpp) on the inputs scaled by a power of
//     two into a window where no step can underflow or overflow;
//  3. big integers (big_integer.hpp) when the inputs span too many binary
//     orders of magnitude for that window (e.g. 1e-200 next to 1e+200), and
//     for insphere whenever the coordinate differences are not exact doubles.
// NaN or infinite inputs are outside the contract.
#pragma once

#include <cmath>

namespace partet {

namespace detail {
int orient2d_exact(const double* a, const double* b, const double* c);
int orient3d_exact(const double* a, const double* b, const double* c, const double* d);

// Error-bound constants of the filters, in units of u = 2^-53: the rounding
// counts per monomial are 3 (orient2d), 7 (orient3d) and 15 (insphere), with
// one u of margin for the bound's own rounding.
inline constexpr double kOrient2dBound = 0x1p-51;   // 4u
inline constexpr double kOrient3dBound = 0x1p-50;   // 8u
inline constexpr double kInsphereBound = 0x1p-49;   // 16u
// Underflow: a product that underflows is off by at most 2^-1075 in absolute
// terms, which the relative bound does not see; this term (times the factors
// that multiply such a product later, plus one) covers it with a wide
// margin. It is the smallest normal double rather than anything smaller so
// that the term is never subnormal (subnormal operands cost x86 ~100
// cycles); the price is that tiny inputs (overall scale below ~1e-150 for
// orient2d, ~1e-100 for orient3d, ~1e-60 for insphere) take the exact path.
inline constexpr double kUnderflowSlack = 0x1p-1022;
}  // namespace detail

// Sign (-1, 0, +1) of det[b-a; c-a] for 2-D points: +1 when a, b, c turn
// counterclockwise.
inline int orient2d(const double* a, const double* b, const double* c) {
  const double ux = b[0] - a[0];
  const double uy = b[1] - a[1];
  const double vx = c[0] - a[0];
  const double vy = c[1] - a[1];
  const double left = ux * vy;
  const double right = uy * vx;
  const double det = left - right;
  const double bound =
      detail::kOrient2dBound * (std::fabs(left) + std::fabs(right)) + detail::kUnderflowSlack;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return detail::orient2d_exact(a, b, c);
}

// orient2d of 3-D points projected onto the coordinate plane that drops
// axis `drop` (0, 1 or 2): the remaining axes in cyclic order (drop x: (y, z),
// drop y: (z, x), drop z: (x, y)), so that the sign agrees with the dropped
// component of the normal (b-a)x(c-a).
inline int orient2d_projected(const double* a, const double* b, const double* c, int drop) {
  const int i = drop == 2 ? 0 : drop + 1;
  const int j = drop == 0 ? 2 : (drop == 1 ? 0 : 1);
  const double pa[2] = {a[i], a[j]};
  const double pb[2] = {b[i], b[j]};
  const double pc[2] = {c[i], c[j]};
  return orient2d(pa, pb, pc);
}

// Sign of det[b-a; c-a; d-a]: +1 when d lies on the side of the plane abc
// that the normal (b-a)x(c-a) points to. A tet (a, b, c, d) is positively
// oriented when orient3d(a, b, c, d) > 0.
inline int orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double p1 = vy * wz, p2 = vz * wy;
  const double p3 = vz * wx, p4 = vx * wz;
  const double p5 = vx * wy, p6 = vy * wx;
  const double det = (ux * (p1 - p2) + uy * (p3 - p4)) + uz * (p5 - p6);
  const double aux = std::fabs(ux), auy = std::fabs(uy), auz = std::fabs(uz);
  const double permanent = (aux * (std::fabs(p1) + std::fabs(p2)) +
                            auy * (std::fabs(p3) + std::fabs(p4))) +
                           auz * (std::fabs(p5) + std::fabs(p6));
  const double bound = detail::kOrient3dBound * permanent +
                       (aux + auy + auz + 1) * detail::kUnderflowSlack;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return detail::orient3d_exact(a, b, c, d);
}

// orient3d(a, b, c, d) for many d against one plane (a, b, c): the minors
// of (b - a, c - a) are computed once. The filter is orient3d's own, bit for
// bit, on the even permutation (a, d, b, c), whose determinant is the same;
// uncertain signs take the exact path of orient3d(a, b, c, d). The points
// must outlive the object.
class PlaneSide {
 public:
  PlaneSide(const double* a, const double* b, const double* c) : a_(a), b_(b), c_(c) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double p1 = uy * vz, p2 = uz * vy;
    const double p3 = uz * vx, p4 = ux * vz;
    const double p5 = ux * vy, p6 = uy * vx;
    minor_[0] = p1 - p2;
    minor_[1] = p3 - p4;
    minor_[2] = p5 - p6;
    minor_abs_[0] = std::fabs(p1) + std::fabs(p2);
    minor_abs_[1] = std::fabs(p3) + std::fabs(p4);
    minor_abs_[2] = std::fabs(p5) + std::fabs(p6);
  }
  // The sign of orient3d(a, b, c, d).
  int operator()(const double* d) const {
    const int sign = filtered(d);
    return sign != 0 ? sign : exact(d);
  }
  // The filter alone: the sign when it is certain, else 0 (d may still be
  // off the plane: exact(d) decides).
  int filtered(const double* d) const {
    const double wx = d[0] - a_[0], wy = d[1] - a_[1], wz = d[2] - a_[2];
    const double det = (wx * minor_[0] + wy * minor_[1]) + wz * minor_[2];
    const double awx = std::fabs(wx), awy = std::fabs(wy), awz = std::fabs(wz);
    const double permanent = (awx * minor_abs_[0] + awy * minor_abs_[1]) + awz * minor_abs_[2];
    const double bound = detail::kOrient3dBound * permanent + (awx + awy + awz + 1) * detail::kUnderflowSlack;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    return 0;
  }
  int exact(const double* d) const { return detail::orient3d_exact(a_, b_, c_, d); }

 private:
  const double *a_, *b_, *c_;
  double minor_[3], minor_abs_[3];
};

// det[b-a; c-a; d-a] evaluated in plain doubles (six times the signed volume
// of tet abcd), for sizes and quality measures only: its sign may be wrong
// for nearly flat tets, so decisions use orient3d.
inline double orient3d_value(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  return ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz) + uz * (vx * wy - vy * wx);
}

// In-sphere test: +1 when e lies strictly inside the sphere through a, b, c,
// d, -1 strictly outside, 0 on it, for a positively oriented tet
// (orient3d(a, b, c, d) > 0); the sign flips for a negatively oriented one
// (for coplanar a, b, c, d it is still the determinant's sign, but no
// in/out answer). It is the sign of
// sum_i (-1)^i |p_i - e|^2 det[p_j - e; p_k - e; p_l - e] over p = (a, b, c, d),
// {j < k < l} = {0..3} \ {i}, i.e. -det of the 4x4 matrix with rows
// (p - e, |p - e|^2).
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

}  // namespace partet
