// FailedSplits::key (see failed_splits.hpp): the ring in one canonical
// order (ends ascending, the ring walked the way that makes the tets
// positive, from its smallest vertex), each vertex with its point's bits.
#include "optimize/failed_splits.hpp"

#include <algorithm>
#include <bit>

#include "core/hash_mix.hpp"

namespace partet {
namespace {

// The running hash with one more word.
uint64_t mix(uint64_t hash, uint64_t word) { return hash_mix(hash ^ (word + 0x9e3779b97f4a7c15ULL)); }

uint64_t mix_vertex(const TetTopology& topo, uint64_t hash, uint32_t v) {
  hash = mix(hash, v);
  for (int i = 0; i < 3; ++i) hash = mix(hash, std::bit_cast<uint64_t>(topo.point(v)[i]));
  return hash;
}

}  // namespace

uint64_t FailedSplits::key(const TetTopology& topo, const TetTopology::Ring& ring) {
  // Swapping the ends reverses the ring's direction.
  const bool swap = ring.a > ring.b;
  const int n = ring.n;
  const int start = static_cast<int>(std::min_element(ring.vertices, ring.vertices + n) - ring.vertices);
  uint64_t hash = mix_vertex(topo, mix_vertex(topo, static_cast<uint64_t>(n), swap ? ring.b : ring.a),
                             swap ? ring.a : ring.b);
  for (int k = 0; k < n; ++k) hash = mix_vertex(topo, hash, ring.vertices[(start + (swap ? n - k : k)) % n]);
  return hash;
}

}  // namespace partet
