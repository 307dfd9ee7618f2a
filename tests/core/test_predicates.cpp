// Exact predicates: degenerate and near-degenerate inputs that fool plain
// doubles, extreme exponents, and agreement with an independent exact
// reference (determinants of the homogeneous matrices by Laplace expansion
// over big integers, written here without the library's arithmetic).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/predicates.hpp"

namespace partet {
namespace {

// ---- Independent exact reference -------------------------------------------
// Sign-magnitude integers in base 2^32.
struct Ref {
  int sign = 0;
  std::vector<uint32_t> mag;  // little endian, no leading zeros
};

void trim(Ref& r) {
  while (!r.mag.empty() && r.mag.back() == 0) r.mag.pop_back();
  if (r.mag.empty()) r.sign = 0;
}

int compare_mag(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

Ref add(const Ref& a, const Ref& b) {
  if (a.sign == 0) return b;
  if (b.sign == 0) return a;
  Ref r;
  if (a.sign == b.sign) {
    r.sign = a.sign;
    uint64_t carry = 0;
    for (size_t i = 0; i < std::max(a.mag.size(), b.mag.size()); ++i) {
      carry += (i < a.mag.size() ? a.mag[i] : 0ull) + (i < b.mag.size() ? b.mag[i] : 0ull);
      r.mag.push_back(static_cast<uint32_t>(carry));
      carry >>= 32;
    }
    r.mag.push_back(static_cast<uint32_t>(carry));
  } else {
    const int c = compare_mag(a.mag, b.mag);
    if (c == 0) return Ref{};
    const Ref& big = c > 0 ? a : b;
    const Ref& small = c > 0 ? b : a;
    r.sign = big.sign;
    int64_t borrow = 0;
    for (size_t i = 0; i < big.mag.size(); ++i) {
      int64_t d = int64_t{big.mag[i]} - (i < small.mag.size() ? int64_t{small.mag[i]} : 0) - borrow;
      borrow = d < 0 ? 1 : 0;
      if (d < 0) d += int64_t{1} << 32;
      r.mag.push_back(static_cast<uint32_t>(d));
    }
  }
  trim(r);
  return r;
}

Ref negate(Ref a) {
  a.sign = -a.sign;
  return a;
}

Ref mul(const Ref& a, const Ref& b) {
  Ref r;
  if (a.sign == 0 || b.sign == 0) return r;
  r.mag.assign(a.mag.size() + b.mag.size(), 0);
  for (size_t i = 0; i < a.mag.size(); ++i) {
    uint64_t carry = 0;
    for (size_t j = 0; j < b.mag.size(); ++j) {
      carry += uint64_t{a.mag[i]} * b.mag[j] + r.mag[i + j];
      r.mag[i + j] = static_cast<uint32_t>(carry);
      carry >>= 32;
    }
    r.mag[i + b.mag.size()] = static_cast<uint32_t>(carry);
  }
  r.sign = a.sign * b.sign;
  trim(r);
  return r;
}

// x = m * 2^e with an odd integer m (x != 0).
void split_double(double x, int64_t& m, int& e) {
  int ex;
  const double f = std::frexp(x, &ex);
  m = static_cast<int64_t>(std::ldexp(f, 53));
  e = ex - 53;
  while (m % 2 == 0) {
    m /= 2;
    ++e;
  }
}

// x / 2^q as an integer (q at most the exponent of x's lowest bit).
Ref to_ref(double x, int q) {
  Ref r;
  if (x == 0) return r;
  int64_t m;
  int e;
  split_double(x, m, e);
  r.sign = m < 0 ? -1 : 1;
  uint64_t mag = static_cast<uint64_t>(m < 0 ? -m : m);
  const int shift = e - q;
  r.mag.assign(static_cast<size_t>(shift / 32), 0);
  const int bits = shift % 32;
  // mag << bits in 32-bit words (mag < 2^53, bits < 32: fits in 3 words).
  const uint64_t lo = (mag << bits) & 0xffffffffull;
  const uint64_t mid = bits == 0 ? (mag >> 32) : ((mag >> (32 - bits)) & 0xffffffffull);
  const uint64_t hi = bits == 0 ? 0 : (mag >> (64 - bits));
  r.mag.push_back(static_cast<uint32_t>(lo));
  r.mag.push_back(static_cast<uint32_t>(mid));
  r.mag.push_back(static_cast<uint32_t>(hi));
  trim(r);
  return r;
}

int lowest_exponent(const std::vector<double>& xs) {
  int q = 0;
  for (double x : xs) {
    if (x == 0) continue;
    int64_t m;
    int e;
    split_double(x, m, e);
    q = std::min(q, e);
  }
  return q;
}

Ref determinant(std::vector<std::vector<Ref>> m) {
  const size_t n = m.size();
  if (n == 1) return m[0][0];
  Ref total;
  for (size_t j = 0; j < n; ++j) {
    if (m[0][j].sign == 0) continue;
    std::vector<std::vector<Ref>> minor;
    for (size_t i = 1; i < n; ++i) {
      std::vector<Ref> row;
      for (size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(m[i][k]);
      minor.push_back(row);
    }
    const Ref term = mul(m[0][j], determinant(minor));
    total = add(total, j % 2 == 0 ? term : negate(term));
  }
  return total;
}

// Sign of the (dim+1)x(dim+1) homogeneous determinant of the points, with a
// lifted column |p|^2 when `lift`.
int reference_sign(const std::vector<const double*>& pts, int dim, bool lift) {
  std::vector<double> all;
  for (const double* p : pts) all.insert(all.end(), p, p + dim);
  const int q = lowest_exponent(all);
  const Ref one = to_ref(std::ldexp(1.0, q), q);
  std::vector<std::vector<Ref>> m;
  for (const double* p : pts) {
    std::vector<Ref> row;
    Ref squares;
    for (int k = 0; k < dim; ++k) {
      row.push_back(to_ref(p[k], q));
      squares = add(squares, mul(row.back(), row.back()));
    }
    if (lift) row.push_back(squares);
    row.push_back(one);
    m.push_back(row);
  }
  return determinant(m).sign;
}

int ref_orient2d(const double* a, const double* b, const double* c) { return reference_sign({a, b, c}, 2, false); }
int ref_orient3d(const double* a, const double* b, const double* c, const double* d) {
  return -reference_sign({a, b, c, d}, 3, false);
}
int ref_insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
  return -reference_sign({a, b, c, d, e}, 3, true);
}

// ---- Helpers -----------------------------------------------------------------

double ulps(double x, int k) {
  const double dir = k > 0 ? INFINITY : -INFINITY;
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, dir);
  return x;
}

int naive_orient2d(const double* a, const double* b, const double* c) {
  const double d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

struct Tet {
  double p[4][3];
};

// Four points with d near the plane abc: d computed in doubles from an
// affine combination, then moved by a few ulps.
Tet near_coplanar(std::mt19937_64& rng, double offset, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-2, 2);
  Tet t;
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) t.p[i][c] = offset + scale * u(rng);
  const double s = u(rng);
  const double r = u(rng);
  for (int c = 0; c < 3; ++c) {
    const double v = t.p[0][c] + s * (t.p[1][c] - t.p[0][c]) + r * (t.p[2][c] - t.p[0][c]);
    t.p[3][c] = ulps(v, k(rng));
  }
  return t;
}

// ---- Tests -------------------------------------------------------------------

// The build's contract with expansion.hpp: every product is rounded before
// it is added (no fused multiply-add). With x = 1 + 2^-30, x * x is
// 1 + 2^-29 + 2^-60, which rounds to 1 + 2^-29; a contracted x * x - y
// would keep the 2^-60. Volatile inputs keep the compiler from folding it.
TEST(Predicates, BuildRoundsEveryProduct) {
  volatile double vx = 1 + 0x1p-30, vy = 1 + 0x1p-29;
  const double x = vx, y = vy;
  EXPECT_EQ(x * x - y, 0.0) << "products are fused into sums: build with -ffp-contract=off";
}

TEST(Predicates, BasicSigns) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1}, d[2] = {2, 0};
  EXPECT_EQ(orient2d(a, b, c), 1);
  EXPECT_EQ(orient2d(a, c, b), -1);
  EXPECT_EQ(orient2d(a, b, d), 0);
  const double p[3] = {0, 0, 0}, q[3] = {1, 0, 0}, r[3] = {0, 1, 0}, s[3] = {0, 0, 1}, t[3] = {5, -3, 0};
  EXPECT_EQ(orient3d(p, q, r, s), 1);
  EXPECT_EQ(orient3d(p, r, q, s), -1);
  EXPECT_EQ(orient3d(p, q, r, t), 0);
  EXPECT_DOUBLE_EQ(orient3d_value(p, q, r, s), 1.0);
  // Coincident points.
  EXPECT_EQ(orient2d(a, a, b), 0);
  EXPECT_EQ(orient3d(p, p, q, r), 0);
  EXPECT_EQ(orient3d(p, p, p, p), 0);
}

TEST(Predicates, Orient2dUlpGridNearDiagonal) {
  // The classic: points a few ulps from the line y = x, seen from far along
  // it. Plain doubles get a visible share of these wrong.
  const double b[2] = {12, 12};
  const double c[2] = {24, 24};
  int naive_wrong = 0;
  int nonzero = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const double a[2] = {ulps(0.5, i), ulps(0.5, j)};
      const int expected = ref_orient2d(a, b, c);
      ASSERT_EQ(orient2d(a, b, c), expected) << i << " " << j;
      EXPECT_EQ(orient2d(b, c, a), expected);
      EXPECT_EQ(orient2d(b, a, c), -expected);
      naive_wrong += naive_orient2d(a, b, c) != expected;
      nonzero += expected != 0;
      // Exactly on the line iff the coordinates are equal.
      EXPECT_EQ(expected == 0, i == j);
    }
  }
  EXPECT_GT(naive_wrong, 100);
  EXPECT_GT(nonzero, 4000);
}

TEST(Predicates, Orient2dRandomNearCollinear) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-3, 3);
  for (int n = 0; n < 20000; ++n) {
    const double offset = (n % 3 == 0) ? 0 : (n % 3 == 1 ? 1e15 : -3e7);
    const double a[2] = {offset + u(rng), offset + u(rng)};
    const double b[2] = {offset + u(rng), offset + u(rng)};
    const double t = u(rng);
    const double c[2] = {ulps(a[0] + t * (b[0] - a[0]), k(rng)), ulps(a[1] + t * (b[1] - a[1]), k(rng))};
    const int expected = ref_orient2d(a, b, c);
    ASSERT_EQ(orient2d(a, b, c), expected) << n;
    ASSERT_EQ(orient2d(c, a, b), expected) << n;
    ASSERT_EQ(orient2d(a, c, b), -expected) << n;
  }
}

TEST(Predicates, Orient3dRandomNearCoplanar) {
  std::mt19937_64 rng(11);
  const double offsets[] = {0, 1e15, -7.5e9, 3.0};
  const double scales[] = {1, 1e-3, 1e6};
  int zeros = 0;
  for (int n = 0; n < 20000; ++n) {
    const Tet t = near_coplanar(rng, offsets[n % 4], scales[(n / 4) % 3]);
    const double* p[4] = {t.p[0], t.p[1], t.p[2], t.p[3]};
    const int expected = ref_orient3d(p[0], p[1], p[2], p[3]);
    zeros += expected == 0;
    ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), expected) << n;
    // Even permutations keep the sign, odd ones flip it.
    ASSERT_EQ(orient3d(p[1], p[2], p[0], p[3]), expected) << n;
    ASSERT_EQ(orient3d(p[3], p[2], p[1], p[0]), expected) << n;
    ASSERT_EQ(orient3d(p[1], p[0], p[2], p[3]), -expected) << n;
    ASSERT_EQ(orient3d(p[0], p[1], p[3], p[2]), -expected) << n;
  }
  EXPECT_GT(zeros, 0);
}

// The exact paths' shortcuts (points sharing one coordinate, repeated
// points) give zero only where the reference does: near-degenerate sets
// that share a coordinate in all but one point, or repeat a point in all
// but one coordinate, keep their signs.
TEST(Predicates, ExactShortcutsOnSharedCoordinatesAndRepeatedPoints) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, 3), axis(0, 2), nudge(-1, 1);
  int zeros = 0, signs = 0;
  for (int n = 0; n < 20000; ++n) {
    double p[4][3];
    for (auto& q : p)
      for (double& x : q) x = 1e3 * u(rng);
    const int k = axis(rng);
    if (n % 2 == 0) {
      // One coordinate shared, but by some points nudged an ulp off.
      for (auto& q : p) q[k] = p[0][k];
      for (int i = 1; i < 4; ++i) p[i][k] = ulps(p[i][k], nudge(rng) * (pick(rng) == 0));
    } else {
      // A point repeated, but for some coordinates nudged an ulp off.
      const int i = pick(rng), j = (i + 1 + pick(rng) % 3) % 4;
      for (int c = 0; c < 3; ++c) p[j][c] = ulps(p[i][c], c == k ? nudge(rng) : 0);
    }
    const int expected = ref_orient3d(p[0], p[1], p[2], p[3]);
    zeros += expected == 0;
    signs += expected != 0;
    ASSERT_EQ(detail::orient3d_exact(p[0], p[1], p[2], p[3]), expected) << n;
    const double a[2] = {p[0][0], p[0][1]}, b[2] = {p[1][0], p[1][1]}, c[2] = {p[2][0], p[2][1]};
    ASSERT_EQ(detail::orient2d_exact(a, b, c), ref_orient2d(a, b, c)) << n;
  }
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(signs, 1000);
}

TEST(Predicates, PlaneSideMatchesOrient3d) {
  // One plane against many points: near-coplanar ones (ulps off the plane,
  // large offsets, small and large scales), points exactly on it, and far
  // ones; the sign must be orient3d's and the reference's.
  std::mt19937_64 rng(17);
  const double offsets[] = {0, 1e15, -7.5e9, 3.0};
  const double scales[] = {1, 1e-3, 1e6};
  int zeros = 0;
  for (int n = 0; n < 4000; ++n) {
    const Tet t = near_coplanar(rng, offsets[n % 4], scales[(n / 4) % 3]);
    const PlaneSide side(t.p[0], t.p[1], t.p[2]);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> k(-2, 2);
    for (int m = 0; m < 5; ++m) {
      // Four points within ulps of the plane, then one off it.
      double q[3];
      const double s = u(rng), r = u(rng);
      for (int c = 0; c < 3; ++c)
        q[c] = ulps(t.p[0][c] + s * (t.p[1][c] - t.p[0][c]) + r * (t.p[2][c] - t.p[0][c]), k(rng)) +
               (m == 4 ? scales[(n / 4) % 3] * u(rng) : 0.0);
      const int expected = ref_orient3d(t.p[0], t.p[1], t.p[2], q);
      zeros += expected == 0;
      ASSERT_EQ(side(q), expected) << n << " " << m;
      ASSERT_EQ(side(q), orient3d(t.p[0], t.p[1], t.p[2], q)) << n << " " << m;
    }
  }
  EXPECT_GT(zeros, 0);
  // Lattice points on the plane x + 2y - 3z = 0 shifted by 2^52.
  const double o = 4503599627370496.0;
  const double a[3] = {o, o, o}, b[3] = {o + 3, o, o + 1}, c[3] = {o - 2, o + 1, o};
  const PlaneSide lattice(a, b, c);
  std::uniform_int_distribution<int> v(-1000, 1000);
  for (int n = 0; n < 1000; ++n) {
    const double y = v(rng), z = v(rng);
    double q[3] = {o + (3 * z - 2 * y), o + y, o + z};
    EXPECT_EQ(lattice(q), 0);
    q[0] += 1;
    EXPECT_EQ(lattice(q), ref_orient3d(a, b, c, q));
  }
  // The underflow case of UnderflowInTheFilter, plane (a, c, d) against b
  // (an even permutation: the same sign).
  const double tiny = std::ldexp(1.0, -537);
  const double pa[3] = {0, 0, 0}, pb[3] = {std::ldexp(1.0, 600), 1, 0};
  const double pc[3] = {0, 1.25 * tiny, 1.25 * tiny}, pd[3] = {0.4 * std::ldexp(1.0, 63), 1.24 * tiny, 1.16 * tiny};
  EXPECT_EQ(PlaneSide(pa, pb, pc)(pd), 1);
  EXPECT_EQ(PlaneSide(pa, pc, pd)(pb), 1);
  EXPECT_EQ(PlaneSide(pb, pc, pa)(pd), 1);
}

TEST(Predicates, Orient3dExactlyCoplanarWithLargeOffsets) {
  // Integer points on the plane x + 2y - 3z = 0 shifted by 2^52: exactly
  // representable, exactly coplanar; moving one by one unit breaks it.
  const double o = 4503599627370496.0;  // 2^52
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> v(-1000, 1000);
  for (int n = 0; n < 2000; ++n) {
    double p[4][3];
    for (auto& q : p) {
      const double y = v(rng), z = v(rng);
      q[0] = o + (3 * z - 2 * y);
      q[1] = o + y;
      q[2] = o + z;
    }
    EXPECT_EQ(orient3d(p[0], p[1], p[2], p[3]), 0);
    const int expected_normal = ref_orient3d(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(expected_normal, 0);
    p[3][0] += 1;
    EXPECT_EQ(orient3d(p[0], p[1], p[2], p[3]), ref_orient3d(p[0], p[1], p[2], p[3]));
  }
}

TEST(Predicates, Orient3dScaleInvarianceAcrossExponents) {
  // Near-degenerate integer configurations scaled by 2^k over the whole
  // exponent range (subnormal to near overflow): the sign must not change.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> v(-(1 << 20), 1 << 20);
  std::uniform_int_distribution<int> nudge(-1, 1);
  for (int n = 0; n < 300; ++n) {
    double p[4][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) p[i][c] = v(rng);
    // d = a + (b - a) + (c - a) exactly, then nudged.
    for (int c = 0; c < 3; ++c) p[3][c] = p[1][c] + p[2][c] - p[0][c] + nudge(rng);
    const int expected = ref_orient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), expected);
    for (int k = -1050; k <= 980; k += 17) {
      double s[4][3];
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) s[i][c] = std::ldexp(p[i][c], k);
      ASSERT_EQ(orient3d(s[0], s[1], s[2], s[3]), expected) << n << " k=" << k;
    }
  }
}

TEST(Predicates, Orient3dLargeLatticeIntegers) {
  // Integers up to 2^40 in units of 2^k (the 128-bit path's widest case),
  // exactly coplanar or off by one unit, against the reference.
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int64_t> v(-(int64_t{1} << 38), int64_t{1} << 38);
  std::uniform_int_distribution<int> nudge(-1, 1);
  int zeros = 0;
  for (int n = 0; n < 3000; ++n) {
    double p[4][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) p[i][c] = static_cast<double>(v(rng) | 1);
    for (int c = 0; c < 3; ++c) p[3][c] = p[1][c] + p[2][c] - p[0][c] + nudge(rng);
    const int expected = ref_orient3d(p[0], p[1], p[2], p[3]);
    zeros += expected == 0;
    for (int k : {-60, 0, 37}) {
      double s[4][3];
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) s[i][c] = std::ldexp(p[i][c], k);
      ASSERT_EQ(orient3d(s[0], s[1], s[2], s[3]), expected) << n << " k=" << k;
      ASSERT_EQ(orient3d(s[1], s[0], s[2], s[3]), -expected) << n << " k=" << k;
    }
  }
  EXPECT_GT(zeros, 0);
}

TEST(Predicates, MixedExponentsMatchReference) {
  // Coordinates spanning far more binary orders than expansions can hold
  // (big integer path), near-degenerate by construction.
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> expo(-1070, 1000);
  std::uniform_real_distribution<double> u(1, 2);
  std::uniform_int_distribution<int> pick(0, 3);
  auto value = [&]() {
    const int kind = pick(rng);
    if (kind == 0) return 0.0;
    return std::ldexp(kind == 1 ? -u(rng) : u(rng), expo(rng));
  };
  for (int n = 0; n < 3000; ++n) {
    double p[4][3];
    for (auto& q : p)
      for (double& x : q) x = value();
    if (n % 2 == 0)
      for (int c = 0; c < 3; ++c) p[3][c] = p[0][c];  // tiny perturbations of a repeated point
    p[3][n % 3] = value();
    ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), ref_orient3d(p[0], p[1], p[2], p[3])) << n;
    const double a[2] = {p[0][0], p[0][1]}, b[2] = {p[1][0], p[1][1]}, c[2] = {p[3][0], p[3][1]};
    ASSERT_EQ(orient2d(a, b, c), ref_orient2d(a, b, c)) << n;
  }
}

TEST(Predicates, HugeAndTinyCoordinates) {
  const double big = 1.5e308;
  // Differences overflow in the filter.
  const double a[3] = {-big, -big, 0}, b[3] = {big, -big, 0}, c[3] = {-big, big, 0};
  const double above[3] = {0, 0, 1e-300}, on[3] = {big, big, 0}, below[3] = {0, 0, -4.9e-324};
  EXPECT_EQ(orient3d(a, b, c, above), 1);
  EXPECT_EQ(orient3d(a, b, c, on), 0);
  EXPECT_EQ(orient3d(a, b, c, below), -1);
  // Subnormal triangle.
  const double t = 4.9e-324;
  const double p[2] = {0, 0}, q[2] = {t, 0}, r[2] = {0, t}, s[2] = {2 * t, -t};
  EXPECT_EQ(orient2d(p, q, r), 1);
  EXPECT_EQ(orient2d(p, q, s), -1);
  EXPECT_EQ(orient2d(q, r, s), ref_orient2d(q, r, s));
  // The smallest subnormal against huge values.
  const double x[2] = {big, big}, y[2] = {-big, -big}, z[2] = {t, 0};
  EXPECT_EQ(orient2d(y, x, z), -1);
  EXPECT_EQ(orient2d(y, x, p), 0);
  const double w[3] = {0, 0, 0}, e[3] = {big, 0, 0}, f[3] = {0, t, 0}, g[3] = {0, 0, t};
  EXPECT_EQ(orient3d(w, e, f, g), 1);
}

TEST(Predicates, UnderflowInTheFilter) {
  // The x minor of orient3d underflows to the wrong subnormal multiple and
  // a huge factor amplifies that: a filter that ignores underflow returns
  // -1 here, the exact sign is +1.
  const double t = std::ldexp(1.0, -537);
  const double a[3] = {0, 0, 0};
  const double b[3] = {std::ldexp(1.0, 600), 1, 0};
  const double c[3] = {0, 1.25 * t, 1.25 * t};
  const double d[3] = {0.4 * std::ldexp(1.0, 63), 1.24 * t, 1.16 * t};
  ASSERT_LT(orient3d_value(a, b, c, d), 0);
  EXPECT_EQ(ref_orient3d(a, b, c, d), 1);
  EXPECT_EQ(orient3d(a, b, c, d), 1);
}

TEST(Predicates, Orient2dProjectedMatchesNormal) {
  // orient2d_projected(a, b, c, k) is the sign of the k-th component of
  // (b-a)x(c-a), i.e. orient3d(a, b, c, a + e_k) (exact for these dyadics).
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int> v(-(1 << 24), 1 << 24);
  std::uniform_int_distribution<int> small(-2, 2);
  for (int n = 0; n < 5000; ++n) {
    double p[3][3];
    for (auto& q : p)
      for (double& x : q) x = std::ldexp(v(rng), -20);
    if (n % 2) {  // nearly collinear in some projection
      for (int c = 0; c < 3; ++c) p[2][c] = 2 * p[1][c] - p[0][c] + std::ldexp(small(rng), -20);
    }
    for (int k = 0; k < 3; ++k) {
      double d[3] = {p[0][0], p[0][1], p[0][2]};
      d[k] += 1;
      ASSERT_EQ(orient2d_projected(p[0], p[1], p[2], k), orient3d(p[0], p[1], p[2], d)) << n << " " << k;
    }
  }
}

TEST(Predicates, InsphereBasics) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  ASSERT_EQ(orient3d(a, b, c, d), 1);
  const double centre[3] = {0.5, 0.5, 0.5}, far[3] = {10, 10, 10}, on[3] = {1, 1, 1};
  EXPECT_EQ(insphere(a, b, c, d, centre), 1);
  EXPECT_EQ(insphere(a, b, c, d, far), -1);
  EXPECT_EQ(insphere(a, b, c, d, on), 0);
  EXPECT_EQ(insphere(b, a, c, d, centre), -1);  // negative tet: sign flips
  // Cospherical octahedron vertices.
  const double px[3] = {1, 0, 0}, nx[3] = {-1, 0, 0}, py[3] = {0, 1, 0}, pz[3] = {0, 0, 1}, nz[3] = {0, 0, -1};
  EXPECT_EQ(insphere(px, py, pz, nx, nz), 0);
  const double just_inside[3] = {0, 0, std::nextafter(-1.0, 0.0)};
  const double just_outside[3] = {0, 0, std::nextafter(-1.0, -2.0)};
  const int orientation = orient3d(px, py, pz, nx);
  EXPECT_EQ(insphere(px, py, pz, nx, just_inside), orientation);
  EXPECT_EQ(insphere(px, py, pz, nx, just_outside), -orientation);
}

TEST(Predicates, InsphereRandomNearCospherical) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> g(0, 1);
  std::uniform_int_distribution<int> k(-2, 2);
  const double offsets[] = {0, 1e6, -3.25};
  for (int n = 0; n < 3000; ++n) {
    double p[5][3];
    const double o = offsets[n % 3];
    for (auto& q : p) {
      double v[3] = {g(rng), g(rng), g(rng)};
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (int c = 0; c < 3; ++c) q[c] = ulps(o + v[c] / len, k(rng));
    }
    if (n % 4 == 0)  // a degenerate tet: e equal to a vertex
      for (int c = 0; c < 3; ++c) p[4][c] = p[1][c];
    const int expected = ref_insphere(p[0], p[1], p[2], p[3], p[4]);
    ASSERT_EQ(insphere(p[0], p[1], p[2], p[3], p[4]), expected) << n;
    ASSERT_EQ(insphere(p[1], p[0], p[2], p[3], p[4]), -expected) << n;
    ASSERT_EQ(insphere(p[1], p[2], p[3], p[0], p[4]), -expected) << n;
  }
}

TEST(Predicates, InsphereLatticeIntegers) {
  // Integers below 2^23 in units of 2^k (the 128-bit path's widest case)
  // and 2^24 (past it), cospherical or off by one unit: the sphere through
  // (+-x, +-y, +-z) about a centre holds every sign pattern of them.
  std::mt19937_64 rng(23);
  for (const int bits : {23, 24}) {
    const int64_t top = int64_t{1} << (bits - 2);
    std::uniform_int_distribution<int64_t> v(-top, top);
    std::uniform_int_distribution<int> nudge(-1, 1), pattern(0, 7);
    int zeros = 0;
    for (int n = 0; n < 3000; ++n) {
      const int64_t centre[3] = {v(rng), v(rng), v(rng)}, r[3] = {v(rng) / 2, v(rng) / 2, v(rng) / 2};
      double p[5][3];
      for (int i = 0; i < 5; ++i) {
        const int signs = pattern(rng);
        for (int c = 0; c < 3; ++c)
          p[i][c] = static_cast<double>(centre[c] + ((signs >> c & 1) ? r[c] : -r[c]) + (i == 4 ? nudge(rng) : 0));
      }
      const int expected = ref_insphere(p[0], p[1], p[2], p[3], p[4]);
      zeros += expected == 0;
      for (int k : {-40, 0, 30}) {
        double s[5][3];
        for (int i = 0; i < 5; ++i)
          for (int c = 0; c < 3; ++c) s[i][c] = std::ldexp(p[i][c], k);
        ASSERT_EQ(insphere(s[0], s[1], s[2], s[3], s[4]), expected) << n << " k=" << k;
        ASSERT_EQ(insphere(s[1], s[0], s[2], s[3], s[4]), -expected) << n << " k=" << k;
      }
    }
    EXPECT_GT(zeros, 100) << bits;
  }
}

TEST(Predicates, InsphereExtremeExponents) {
  std::mt19937_64 rng(19);
  std::uniform_int_distribution<int> v(-100, 100);
  std::uniform_int_distribution<int> expo(-1000, 900);
  for (int n = 0; n < 500; ++n) {
    double p[5][3];
    const int base = expo(rng);
    for (int i = 0; i < 5; ++i)
      for (int c = 0; c < 3; ++c)
        p[i][c] = std::ldexp(v(rng), (n % 2 == 0) ? base : expo(rng));
    ASSERT_EQ(insphere(p[0], p[1], p[2], p[3], p[4]), ref_insphere(p[0], p[1], p[2], p[3], p[4])) << n;
  }
}

TEST(Predicates, RandomGeneralPositionMatchesReference) {
  // Mostly the filter's path: it must never certify a wrong sign.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 0; n < 5000; ++n) {
    double p[5][3];
    for (auto& q : p)
      for (double& x : q) x = u(rng) * ((n % 5 == 0) ? 1e-200 : 1.0);
    ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), ref_orient3d(p[0], p[1], p[2], p[3])) << n;
    ASSERT_EQ(orient2d(p[0], p[1], p[2]), ref_orient2d(p[0], p[1], p[2])) << n;
    if (n % 5 == 0) {
      ASSERT_EQ(insphere(p[0], p[1], p[2], p[3], p[4]), ref_insphere(p[0], p[1], p[2], p[3], p[4])) << n;
    }
  }
}

}  // namespace
}  // namespace partet
