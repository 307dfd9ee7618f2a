// Fixed-capacity signed big integers, the last-resort exact arithmetic of the
// predicates: used when the input coordinates span too many binary orders of
// magnitude for expansion arithmetic (which must stay clear of underflow).
//
// Contract. BigInt<N> is sign and magnitude with up to N 64-bit limbs, kept
// normalized (no leading zero limb; zero has n == 0). The capacity of each
// result is part of its type (sum: max(A,B)+1 limbs, product: A+B limbs), so
// nothing can overflow and nothing is allocated: all arrays are on the stack.
// from_double(x, q) is x / 2^q, which must be an integer (q at most the
// exponent of the lowest set bit of x).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

namespace partet::exact {

template <int N>
struct BigInt {
  static_assert(N >= 1);
  int n = 0;              // limbs in use
  bool negative = false;  // never true for zero
  uint64_t limb[N];       // little-endian magnitude, limb[0..n)

  BigInt() = default;
  BigInt(const BigInt& o) : n(o.n), negative(o.negative) { std::copy(o.limb, o.limb + o.n, limb); }
  BigInt& operator=(const BigInt& o) {
    n = o.n;
    negative = o.negative;
    std::copy(o.limb, o.limb + o.n, limb);
    return *this;
  }
  int sign() const { return n == 0 ? 0 : (negative ? -1 : 1); }
  void trim() {
    while (n > 0 && limb[n - 1] == 0) --n;
    if (n == 0) negative = false;
  }
};

// Splits a finite double into x == mantissa * 2^exponent with an odd
// mantissa (or zero).
inline void decompose(double x, uint64_t& mantissa, int& exponent, bool& negative) {
  const uint64_t bits = std::bit_cast<uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  mantissa = bits & ((uint64_t{1} << 52) - 1);
  negative = (bits >> 63) != 0;
  if (biased != 0) mantissa |= uint64_t{1} << 52;
  exponent = biased != 0 ? biased - 1075 : -1074;
  if (mantissa == 0) return;
  const int tz = std::countr_zero(mantissa);
  mantissa >>= tz;
  exponent += tz;
}

// Exponent of the lowest set bit of a nonzero finite double.
inline int lowest_bit_exponent(double x) {
  uint64_t m;
  int e;
  bool neg;
  decompose(x, m, e, neg);
  return e;
}

// x / 2^q as a big integer; 33 limbs hold any double over any q >= -1074.
inline BigInt<33> from_double(double x, int q) {
  BigInt<33> r;
  uint64_t m;
  int e;
  decompose(x, m, e, r.negative);
  if (m == 0) {
    r.negative = false;
    return r;
  }
  const int shift = e - q;
  const int word = shift / 64;
  const int bit = shift % 64;
  std::memset(r.limb, 0, sizeof(uint64_t) * static_cast<size_t>(word + 1));
  r.limb[word] = m << bit;
  r.n = word + 1;
  if (bit > 11 && word + 1 < 33) {
    r.limb[word + 1] = m >> (64 - bit);
    r.n = word + 2;
  }
  r.trim();
  return r;
}

// Compares magnitudes: -1, 0, +1 for |a| <, ==, > |b|.
template <int A, int B>
int compare_magnitude(const BigInt<A>& a, const BigInt<B>& b) {
  if (a.n != b.n) return a.n < b.n ? -1 : 1;
  for (int i = a.n - 1; i >= 0; --i)
    if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
  return 0;
}

// r = |a| + |b|, sign left to the caller.
template <int R, int A, int B>
void add_magnitudes(BigInt<R>& r, const BigInt<A>& a, const BigInt<B>& b) {
  static_assert(R > A && R > B);
  const int n = a.n > b.n ? a.n : b.n;
  uint64_t carry = 0;
  for (int i = 0; i < n; ++i) {
    const uint64_t x = i < a.n ? a.limb[i] : 0;
    const uint64_t y = i < b.n ? b.limb[i] : 0;
    const uint64_t s = x + y;
    const uint64_t c1 = s < x ? 1 : 0;
    r.limb[i] = s + carry;
    carry = c1 + (r.limb[i] < s ? 1 : 0);
  }
  r.limb[n] = carry;
  r.n = n + 1;
}

// r = |a| - |b|, requires |a| >= |b|.
template <int R, int A, int B>
void subtract_magnitudes(BigInt<R>& r, const BigInt<A>& a, const BigInt<B>& b) {
  uint64_t borrow = 0;
  for (int i = 0; i < a.n; ++i) {
    const uint64_t x = a.limb[i];
    const uint64_t y = i < b.n ? b.limb[i] : 0;
    const uint64_t d = x - y;
    const uint64_t b1 = x < y ? 1 : 0;
    r.limb[i] = d - borrow;
    borrow = b1 + (d < borrow ? 1 : 0);
  }
  r.n = a.n;
}

// a + (-1)^flip_b * b.
template <int A, int B>
BigInt<(A > B ? A : B) + 1> signed_sum(const BigInt<A>& a, const BigInt<B>& b, bool flip_b) {
  BigInt<(A > B ? A : B) + 1> r;
  const bool b_negative = b.negative != flip_b;
  if (b.n == 0 || a.negative == b_negative || a.n == 0) {
    add_magnitudes(r, a, b);
    r.negative = a.n != 0 ? a.negative : b_negative;
  } else if (compare_magnitude(a, b) >= 0) {
    subtract_magnitudes(r, a, b);
    r.negative = a.negative;
  } else {
    subtract_magnitudes(r, b, a);
    r.negative = b_negative;
  }
  r.trim();
  return r;
}

template <int A, int B>
BigInt<(A > B ? A : B) + 1> operator+(const BigInt<A>& a, const BigInt<B>& b) {
  return signed_sum(a, b, false);
}

template <int A, int B>
BigInt<(A > B ? A : B) + 1> operator-(const BigInt<A>& a, const BigInt<B>& b) {
  return signed_sum(a, b, true);
}

// Schoolbook product with 128-bit partial products.
template <int A, int B>
BigInt<A + B> operator*(const BigInt<A>& a, const BigInt<B>& b) {
  using u128 = unsigned __int128;
  BigInt<A + B> r;
  if (a.n == 0 || b.n == 0) return r;
  r.n = a.n + b.n;
  std::memset(r.limb, 0, sizeof(uint64_t) * static_cast<size_t>(r.n));
  for (int i = 0; i < a.n; ++i) {
    uint64_t carry = 0;
    for (int j = 0; j < b.n; ++j) {
      const u128 t = static_cast<u128>(a.limb[i]) * b.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<uint64_t>(t);
      carry = static_cast<uint64_t>(t >> 64);
    }
    r.limb[i + b.n] = carry;
  }
  r.negative = a.negative != b.negative;
  r.trim();
  return r;
}

}  // namespace partet::exact
