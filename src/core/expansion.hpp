// Floating-point expansion arithmetic: a real number held exactly as an
// unevaluated sum of doubles (components), used by the exact predicates.
//
// Contract. An Expansion<N> holds at most N nonzero components in increasing
// order of magnitude, pairwise nonoverlapping (every set bit of a smaller
// one lies below the lowest set bit of a larger one), so the sign of the sum
// is the sign of the largest component. The algorithms (merge-and-carry sum,
// scaling by a double) follow Priest and Shewchuk's papers. Every operation is exact under IEEE-754 binary64
// round-to-nearest-even arithmetic *provided no step overflows or loses bits
// to underflow*. The caller guarantees that: all inputs are integer multiples
// of 2^q and bounded by 2^h with the degree-d results on the grid 2^(d*q) >=
// 2^-1074 and far below 2^1023 (predicates.cpp scales its inputs by a power
// of two into such a window). On such a grid every two-sum, two-diff and
// two-product error term is itself a double, so nothing is ever lost.
//
// The result capacity of each operator is part of its type (sum: A+B,
// product: 2AB), so the fixed-size arrays live on the stack and no operation
// allocates.
#pragma once

#include <algorithm>
#include <cmath>

namespace partet::exact {

// x + y == a + b exactly, x = fl(a + b).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// x + y == a + b exactly, x = fl(a + b); requires |a| >= |b| or a == 0.
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

// x + y == a - b exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

// x + y == a * b exactly, x = fl(a * b): one fused multiply-add when the
// target has it, else Dekker's split into 26-bit halves.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
#if defined(__FMA__)
  y = std::fma(a, b, -x);
#else
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double ca = kSplitter * a;
  const double ahi = ca - (ca - a);
  const double alo = a - ahi;
  const double cb = kSplitter * b;
  const double bhi = cb - (cb - b);
  const double blo = b - bhi;
  y = ((ahi * bhi - x) + ahi * blo + alo * bhi) + alo * blo;
#endif
}

// h = e + f (zero components dropped); returns the number of components.
// Merges e and f by magnitude, then carries the running sum upwards with
// two-sums, emitting each round-off that can no longer change.
inline int sum_expansions(const double* e, int ne, const double* f, int nf, double* h) {
  if (ne == 0 || nf == 0) {
    const double* src = ne == 0 ? f : e;
    const int n = ne == 0 ? nf : ne;
    for (int i = 0; i < n; ++i) h[i] = src[i];
    return n;
  }
  int i = 0;
  int j = 0;
  auto next = [&]() {
    if (j >= nf || (i < ne && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  double q = next();
  int nh = 0;
  while (i < ne || j < nf) {
    double s;
    double err;
    two_sum(q, next(), s, err);
    if (err != 0) h[nh++] = err;
    q = s;
  }
  if (q != 0) h[nh++] = q;
  return nh;
}

// h = e * b (zero components dropped); returns the number of components.
inline int scale_expansion(const double* e, int ne, double b, double* h) {
  if (ne == 0 || b == 0) return 0;
  int nh = 0;
  double q;
  double err;
  two_product(e[0], b, q, err);
  if (err != 0) h[nh++] = err;
  for (int i = 1; i < ne; ++i) {
    double p1;
    double p0;
    two_product(e[i], b, p1, p0);
    double s;
    two_sum(q, p0, s, err);
    if (err != 0) h[nh++] = err;
    fast_two_sum(p1, s, q, err);
    if (err != 0) h[nh++] = err;
  }
  if (q != 0) h[nh++] = q;
  return nh;
}

template <int N>
struct Expansion {
  static_assert(N >= 1);
  int n = 0;    // number of nonzero components
  double c[N];  // c[0..n): increasing magnitude, nonoverlapping

  Expansion() = default;
  Expansion(const Expansion& o) : n(o.n) { std::copy(o.c, o.c + o.n, c); }
  Expansion& operator=(const Expansion& o) {
    n = o.n;
    std::copy(o.c, o.c + o.n, c);
    return *this;
  }
  int sign() const { return n == 0 ? 0 : (c[n - 1] > 0 ? 1 : -1); }
  double estimate() const {
    double s = 0;
    for (int i = 0; i < n; ++i) s += c[i];
    return s;
  }
};

// The exact difference a - b of two doubles.
inline Expansion<2> exact_difference(double a, double b) {
  Expansion<2> r;
  double x;
  double y;
  two_diff(a, b, x, y);
  if (y != 0) r.c[r.n++] = y;
  if (x != 0) r.c[r.n++] = x;
  return r;
}

// A single double as an expansion.
inline Expansion<1> exact_value(double a) {
  Expansion<1> r;
  if (a != 0) r.c[r.n++] = a;
  return r;
}

template <int A, int B>
Expansion<A + B> operator+(const Expansion<A>& a, const Expansion<B>& b) {
  Expansion<A + B> r;
  r.n = sum_expansions(a.c, a.n, b.c, b.n, r.c);
  return r;
}

template <int N>
Expansion<N> operator-(const Expansion<N>& a) {
  Expansion<N> r;
  r.n = a.n;
  for (int i = 0; i < a.n; ++i) r.c[i] = -a.c[i];
  return r;
}

template <int A, int B>
Expansion<A + B> operator-(const Expansion<A>& a, const Expansion<B>& b) {
  return a + (-b);
}

// Product: b scaled by each component of a, the partial products summed.
template <int A, int B>
Expansion<2 * A * B> operator*(const Expansion<A>& a, const Expansion<B>& b) {
  Expansion<2 * A * B> r;
  if (a.n == 0 || b.n == 0) return r;
  r.n = scale_expansion(b.c, b.n, a.c[0], r.c);
  for (int i = 1; i < a.n; ++i) {
    double part[2 * B];
    double merged[2 * A * B];
    const int np = scale_expansion(b.c, b.n, a.c[i], part);
    const int nm = sum_expansions(r.c, r.n, part, np, merged);
    for (int k = 0; k < nm; ++k) r.c[k] = merged[k];
    r.n = nm;
  }
  return r;
}

}  // namespace partet::exact
