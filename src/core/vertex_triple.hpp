// A face's three vertex indices, sorted, as a flat-hash-map key (the
// front's faces, the Delaunay fill's walls). Compared field by field:
// std::array's == is a memcmp call, 4 % of a run in the hash probes.
#pragma once

#include <cstdint>
#include <utility>

#include "core/hash_mix.hpp"

namespace partet {

struct VertexTriple {
  uint32_t a, b, c;
  bool operator==(const VertexTriple& o) const { return a == o.a && b == o.b && c == o.c; }
};

struct VertexTripleTraits {
  static VertexTriple empty() { return {UINT32_MAX, UINT32_MAX, UINT32_MAX}; }
  static uint64_t hash(const VertexTriple& k) { return hash_triple(k.a, k.b, k.c); }
};

inline VertexTriple sorted_triple(uint32_t a, uint32_t b, uint32_t c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

}  // namespace partet
