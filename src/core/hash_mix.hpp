// splitmix64's finalizer: every input bit moves every output bit. The hash
// of the flat hash maps' integer keys and the spreading of keys over ranks;
// hash_triple builds the face keys' hash from it.
#pragma once

#include <cstdint>

namespace partet {

inline uint64_t hash_mix(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A hash of three 32-bit values (a face's vertex indices).
inline uint64_t hash_triple(uint32_t a, uint32_t b, uint32_t c) {
  return hash_mix((uint64_t{a} << 32 | b) ^ hash_mix(c));
}

}  // namespace partet
