// The exact stages of the predicates (see predicates.hpp): power-of-two
// scaling into a safe window for expansion arithmetic, big integers outside
// it, and the in-sphere test with its own filter.
//
// Why scaling makes expansions exact: if every input coordinate is an
// integer multiple of 2^lo and smaller than 2^hi in magnitude, then every
// quantity a degree-d determinant computes from coordinate differences is a
// multiple of 2^(d*lo); when that grid is not finer than 2^-1074, every
// rounding error of a sum or product is itself a double, so two-sum and
// two-product lose nothing. Multiplying all inputs by the same 2^s is exact
// here and keeps every sign (the determinants are homogeneous). A window
// [low, high] per degree keeps the grid at or above the smallest normal
// 2^-1022 and all magnitudes far below 2^1023.
#include "core/predicates.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

#include "core/big_integer.hpp"
#include "core/expansion.hpp"

namespace partet {
namespace {

using exact::BigInt;
using exact::Expansion;

// Binary magnitude of a set of coordinates: every nonzero one is a multiple
// of 2^low and below 2^high in magnitude. high == INT_MIN when all are zero.
struct ExponentRange {
  int low = INT_MAX;
  int high = INT_MIN;
};

// From the bits (frexp and ldexp cost a library call each, and the exact
// stages run hundreds of thousands of times per mesh): for a nonzero finite
// x, |x| < 2^high and x is a multiple of 2^low.
void binary_exponents(double x, int& high, int& low) {
  const uint64_t bits = std::bit_cast<uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  uint64_t mantissa = bits & ((uint64_t{1} << 52) - 1);
  if (biased != 0) mantissa |= uint64_t{1} << 52;
  const int unit = biased != 0 ? biased - 1075 : -1074;  // exponent of the mantissa's unit bit
  high = unit + 64 - std::countl_zero(mantissa);
  low = unit + std::countr_zero(mantissa);
}

ExponentRange exponent_range(const double* const* points, int count, int dim) {
  ExponentRange r;
  for (int i = 0; i < count; ++i) {
    for (int k = 0; k < dim; ++k) {
      const double x = points[i][k];
      if (x == 0) continue;
      int high, low;
      binary_exponents(x, high, low);
      if (high > r.high) r.high = high;
      if (low < r.low) r.low = low;
    }
  }
  return r;
}

// x * 2^shift, exact when the result is a normal double or zero: one
// multiplication when 2^shift is itself a normal double.
double scale_by_power_of_two(double x, int shift) {
  if (shift >= -1022 && shift <= 1023)
    return x * std::bit_cast<double>(static_cast<uint64_t>(shift + 1023) << 52);
  return std::ldexp(x, shift);
}

// Inputs to a degree-d determinant may be multiples of 2^low and below
// 2^high: d * low >= -1022 (every component of every expansion is then a
// normal double, so exact on the 2^-1074 grid and free of the slow
// subnormal arithmetic), and the largest intermediate stays below 2^1000.
struct Window {
  int low;
  int high;
};
constexpr Window kOrient2dWindow{-511, 500};
constexpr Window kOrient3dWindow{-340, 330};
constexpr Window kInsphereWindow{-204, 195};

// The power of two that moves `r` into `w` (0 when it is already inside,
// else centring it); false when the range is too wide for the window.
bool window_shift(const ExponentRange& r, const Window& w, int& shift) {
  shift = 0;
  if (r.low >= w.low && r.high <= w.high) return true;
  if (r.high - r.low > w.high - w.low) return false;
  shift = std::clamp((w.low + w.high - r.low - r.high) / 2, w.low - r.low, w.high - r.high);
  return true;
}

// Coordinates of `count` points scaled by 2^shift (exact inside the window).
template <int Count, int Dim>
void scaled_copy(const double* const* points, int shift, double (&out)[Count][Dim]) {
  for (int i = 0; i < Count; ++i)
    for (int k = 0; k < Dim; ++k)
      out[i][k] = shift == 0 ? points[i][k] : scale_by_power_of_two(points[i][k], shift);
}

// The determinants, over any exact number type, from coordinate differences.
template <class T>
auto orient2d_formula(const T (&u)[2], const T (&v)[2]) {
  return u[0] * v[1] - u[1] * v[0];
}

template <class T>
auto orient3d_formula(const T (&u)[3], const T (&v)[3], const T (&w)[3]) {
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2])) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// sum_i (-1)^i |p_i|^2 det[p_j; p_k; p_l] for rows p = a, b, c, d taken
// relative to e: each 3x3 determinant expanded along z over the xy minors.
template <class T>
auto insphere_formula(const T (&a)[3], const T (&b)[3], const T (&c)[3], const T (&d)[3]) {
  const auto ab = a[0] * b[1] - b[0] * a[1];
  const auto ac = a[0] * c[1] - c[0] * a[1];
  const auto ad = a[0] * d[1] - d[0] * a[1];
  const auto bc = b[0] * c[1] - c[0] * b[1];
  const auto bd = b[0] * d[1] - d[0] * b[1];
  const auto cd = c[0] * d[1] - d[0] * c[1];
  const auto bcd = (b[2] * cd - c[2] * bd) + d[2] * bc;
  const auto acd = (a[2] * cd - c[2] * ad) + d[2] * ac;
  const auto abd = (a[2] * bd - b[2] * ad) + d[2] * ab;
  const auto abc = (a[2] * bc - b[2] * ac) + c[2] * ab;
  const auto la = (a[0] * a[0] + a[1] * a[1]) + a[2] * a[2];
  const auto lb = (b[0] * b[0] + b[1] * b[1]) + b[2] * b[2];
  const auto lc = (c[0] * c[0] + c[1] * c[1]) + c[2] * c[2];
  const auto ld = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
  return (la * bcd - lb * acd) + (lc * abd - ld * abc);
}

// Differences points[i] - points[origin] as big integers over the grid 2^q,
// for i != origin, in order.
template <int Count, int Dim>
void integer_differences(const double* const* points, int origin, int q,
                         BigInt<34> (&out)[Count - 1][Dim]) {
  int row = 0;
  for (int i = 0; i < Count; ++i) {
    if (i == origin) continue;
    for (int k = 0; k < Dim; ++k)
      out[row][k] = exact::from_double(points[i][k], q) - exact::from_double(points[origin][k], q);
    ++row;
  }
}

// Coordinates that are integers below 2^kSmallIntegerBits in units of
// 2^low (lattice points such as the templated core's, whose coplanar
// quadruples are common) take 128-bit integer arithmetic: differences
// below 2^41, 2x2 minors below 2^83, the determinant below 2^126.
constexpr int kSmallIntegerBits = 40;

__extension__ typedef __int128 Int128;

int orient3d_small_integers(const double* const* p, int low) {
  int64_t m[4][3];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = static_cast<int64_t>(scale_by_power_of_two(p[i][k], -low));
  int64_t u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = m[1][k] - m[0][k];
    v[k] = m[2][k] - m[0][k];
    w[k] = m[3][k] - m[0][k];
  }
  const Int128 det = u[0] * (Int128{v[1]} * w[2] - Int128{v[2]} * w[1]) +
                     u[1] * (Int128{v[2]} * w[0] - Int128{v[0]} * w[2]) +
                     u[2] * (Int128{v[0]} * w[1] - Int128{v[1]} * w[0]);
  return (det > 0) - (det < 0);
}

// Insphere on coordinates that are integers below 2^kInsphereSmallBits in
// units of 2^low (the core's lattice points, cospherical in bulk at the
// octree's 2:1 transitions, where the Delaunay fill's ties take this path
// by the thousand): differences below 2^24, the lifts below 2^49.6, the
// 3x3 determinants below 2^74.6, the determinant below 2^126.2, all in
// 128-bit integers.
constexpr int kInsphereSmallBits = 23;

int insphere_small_integers(const double* const* p, int low) {
  int64_t m[5][3];
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = static_cast<int64_t>(scale_by_power_of_two(p[i][k], -low));
  Int128 rows[4][3];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) rows[i][k] = m[i][k] - m[4][k];
  const Int128 det = insphere_formula(rows[0], rows[1], rows[2], rows[3]);
  return (det > 0) - (det < 0);
}

int insphere_exact(const double* const* p) {
  const ExponentRange range = exponent_range(p, 5, 3);
  if (range.high == INT_MIN) return 0;
  if (range.high - range.low <= kInsphereSmallBits) return insphere_small_integers(p, range.low);
  int shift;
  if (window_shift(range, kInsphereWindow, shift)) {
    double s[5][3];
    scaled_copy(p, shift, s);
    // Expansions only when every difference is a double: with two-component
    // differences the worst-case expansions would not fit on the stack.
    Expansion<1> rows[4][3];
    bool exact_differences = true;
    for (int i = 0; i < 4 && exact_differences; ++i) {
      for (int k = 0; k < 3; ++k) {
        const Expansion<2> diff = exact::exact_difference(s[i][k], s[4][k]);
        if (diff.n == 2) exact_differences = false;
        rows[i][k] = exact::exact_value(diff.n == 0 ? 0.0 : diff.c[diff.n - 1]);
      }
    }
    if (exact_differences) return insphere_formula(rows[0], rows[1], rows[2], rows[3]).sign();
  }
  BigInt<34> rows[4][3];
  integer_differences<5, 3>(p, 4, range.low, rows);
  return insphere_formula(rows[0], rows[1], rows[2], rows[3]).sign();
}

// The first N coordinates of p and q are equal.
template <int N>
bool same_point(const double* p, const double* q) {
  for (int k = 0; k < N; ++k)
    if (p[k] != q[k]) return false;
  return true;
}

}  // namespace

namespace detail {

int orient2d_exact(const double* a, const double* b, const double* c) {
  // Three points with a coordinate in common lie on that axis-parallel
  // line, and two equal points on every line: zero without arithmetic (the
  // filter cannot certify a zero).
  for (int k = 0; k < 2; ++k)
    if (a[k] == b[k] && a[k] == c[k]) return 0;
  if (same_point<2>(a, b) || same_point<2>(a, c) || same_point<2>(b, c)) return 0;
  const double* p[3] = {a, b, c};
  const ExponentRange range = exponent_range(p, 3, 2);
  if (range.high == INT_MIN) return 0;
  int shift;
  if (window_shift(range, kOrient2dWindow, shift)) {
    double s[3][2];
    scaled_copy(p, shift, s);
    const Expansion<2> u[2] = {exact::exact_difference(s[1][0], s[0][0]),
                               exact::exact_difference(s[1][1], s[0][1])};
    const Expansion<2> v[2] = {exact::exact_difference(s[2][0], s[0][0]),
                               exact::exact_difference(s[2][1], s[0][1])};
    return orient2d_formula(u, v).sign();
  }
  BigInt<34> rows[2][2];
  integer_differences<3, 2>(p, 0, range.low, rows);
  return orient2d_formula(rows[0], rows[1]).sign();
}

int orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
  // Four points with a coordinate in common lie in that coordinate plane
  // (common: the templated core's faces and vertices, leaf corners), and a
  // point repeated leaves three: zero without arithmetic (the filter cannot
  // certify a zero).
  for (int k = 0; k < 3; ++k)
    if (a[k] == b[k] && a[k] == c[k] && a[k] == d[k]) return 0;
  if (same_point<3>(a, b) || same_point<3>(a, c) || same_point<3>(a, d) || same_point<3>(b, c) ||
      same_point<3>(b, d) || same_point<3>(c, d))
    return 0;
  const double* p[4] = {a, b, c, d};
  const ExponentRange range = exponent_range(p, 4, 3);
  if (range.high == INT_MIN) return 0;
  if (range.high - range.low <= kSmallIntegerBits) return orient3d_small_integers(p, range.low);
  int shift;
  if (window_shift(range, kOrient3dWindow, shift)) {
    double s[4][3];
    scaled_copy(p, shift, s);
    Expansion<2> rows[3][3];
    bool single = true;  // every difference is one double (common: nearby points)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        rows[i][k] = exact::exact_difference(s[i + 1][k], s[0][k]);
        single = single && rows[i][k].n < 2;
      }
    if (single) {
      // Products of single doubles: far shorter expansions than with
      // two-component differences.
      Expansion<1> one[3][3];
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) one[i][k] = exact::exact_value(rows[i][k].n == 0 ? 0.0 : rows[i][k].c[0]);
      return orient3d_formula(one[0], one[1], one[2]).sign();
    }
    return orient3d_formula(rows[0], rows[1], rows[2]).sign();
  }
  BigInt<34> rows[3][3];
  integer_differences<4, 3>(p, 0, range.low, rows);
  return orient3d_formula(rows[0], rows[1], rows[2]).sign();
}

}  // namespace detail

// Filter: the formula in doubles, the same structure with absolute values
// for the permanent, and an underflow term for every product that a later
// factor multiplies (xy minors by z and by the lift, z * minor and the lift's
// squares by the lift or the 3x3 determinant).
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
  double r[4][3];
  const double* p[4] = {a, b, c, d};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) r[i][k] = p[i][k] - e[k];
  double minor[4][4];
  double minor_abs[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const double x = r[i][0] * r[j][1];
      const double y = r[j][0] * r[i][1];
      minor[i][j] = x - y;
      minor_abs[i][j] = std::fabs(x) + std::fabs(y);
    }
  }
  // det3[i]: the 3x3 determinant of the rows other than i.
  double det3[4];
  double det3_abs[4];
  for (int i = 0; i < 4; ++i) {
    int t[3];
    int n = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) t[n++] = j;
    det3[i] = (r[t[0]][2] * minor[t[1]][t[2]] - r[t[1]][2] * minor[t[0]][t[2]]) +
              r[t[2]][2] * minor[t[0]][t[1]];
    det3_abs[i] = (std::fabs(r[t[0]][2]) * minor_abs[t[1]][t[2]] +
                   std::fabs(r[t[1]][2]) * minor_abs[t[0]][t[2]]) +
                  std::fabs(r[t[2]][2]) * minor_abs[t[0]][t[1]];
  }
  double lift[4];
  for (int i = 0; i < 4; ++i) lift[i] = (r[i][0] * r[i][0] + r[i][1] * r[i][1]) + r[i][2] * r[i][2];
  const double det = (lift[0] * det3[0] - lift[1] * det3[1]) + (lift[2] * det3[2] - lift[3] * det3[3]);
  const double permanent = (lift[0] * det3_abs[0] + lift[1] * det3_abs[1]) +
                           (lift[2] * det3_abs[2] + lift[3] * det3_abs[3]);
  const double lifts = (lift[0] + lift[1]) + (lift[2] + lift[3]);
  const double zs = (std::fabs(r[0][2]) + std::fabs(r[1][2])) + (std::fabs(r[2][2]) + std::fabs(r[3][2]));
  const double dets = (std::fabs(det3[0]) + std::fabs(det3[1])) + (std::fabs(det3[2]) + std::fabs(det3[3]));
  const double bound = detail::kInsphereBound * permanent +
                       (lifts * (2 * zs + 3) + 3 * dets + 4) * detail::kUnderflowSlack;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  const double* all[5] = {a, b, c, d, e};
  return insphere_exact(all);
}

}  // namespace partet
