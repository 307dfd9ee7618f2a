// Distributed weighted cut of several point sets at once ("slots"): the
// parallel weighted quantile search of recursive bisection.
//
// Contract: collective over `comm`. Point i belongs to slot slot[i] in
// [0, target.size()), or to none when slot[i] < 0. Each point has a key of
// kCutKeyWords 64-bit words (CutKeys, compared lexicographically) that is
// distinct from every other key of its slot over all ranks, and an integer
// weight (sums over all ranks below 2^62). In the key order, the low side of
// a slot is a prefix: the points before the first point e at which the running
// weight reaches target[s], plus e itself when that brings the low weight
// closer to target[s] (or as close). The result is 1 for the points on the
// low side, 0 for the others (and for points of no slot). It depends only on
// the global set of (key, weight) pairs, never on the rank holding a point.
//
// Method: radix refinement from the most significant byte: each round sums
// over all ranks, for every slot at once, the weight and count of the
// undecided points in each of 256 buckets of the next key byte; the points
// in the buckets before the one where the target is reached are decided low,
// those after it high. A slot is done when one undecided point is left: at
// most 8 * kCutKeyWords rounds, usually a few.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

// The words of a key (CutKeys::word 0 .. kCutKeyWords - 1).
constexpr size_t kCutKeyWords = 6;

// An unsigned key with the order of the doubles (-0.0 and 0.0 are one key).
inline uint64_t ordered_key(double v) {
  if (v == 0) v = 0.0;
  uint64_t bits = std::bit_cast<uint64_t>(v);
  return (bits >> 63) != 0 ? ~bits : bits | (uint64_t{1} << 63);
}

// The key of point i: its projection, its three coordinates, its weight
// (as the caller gave it), then its global index (first_index + i), each as
// ordered_key's word. Read word by word as the rounds need them: the first
// word decides most points in a round or two, and storing all six took 48
// bytes per point (113 MB on rank 0 for femur r2's 2.35 M tets).
struct CutKeys {
  const double* projection;  // one per point
  const double* xyz;         // three per point
  const double* weight;      // one per point
  uint64_t first_index;      // global index of point 0
  uint64_t word(size_t i, size_t w) const {
    switch (w) {
      case 0: return ordered_key(projection[i]);
      case 1: case 2: case 3: return ordered_key(xyz[3 * i + (w - 1)]);
      case 4: return ordered_key(weight[i]);
      default: return first_index + i;  // word kCutKeyWords - 1
    }
  }
};

std::vector<uint8_t> weighted_cut(const Comm& comm, const CutKeys& keys, const uint64_t* weight,
                                  const int32_t* slot, size_t n, const std::vector<uint64_t>& target);

}  // namespace partet
