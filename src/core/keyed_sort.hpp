// Sorting (key, index) pairs by a least-significant-digit radix sort: the
// counts of every key byte in one read, then a scatter per byte in which
// the keys differ. The scatter is stable, so when the indices ascend in the
// input (pairs made in index order) the result is the pairs in (key, index)
// order, what std::sort gives, in linear passes where std::sort took
// n log n comparisons (2.3 M tets by Morton key: 0.13 s by std::sort).
// Deterministic.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace partet {

using KeyedIndex = std::pair<uint64_t, uint32_t>;

// Sorts `keyed` by (key, index); the indices must ascend in the input.
inline void sort_keyed_in_index_order(std::vector<KeyedIndex>& keyed) {
  const size_t n = keyed.size();
  for (size_t i = 1; i < n; ++i)
    PARTET_ASSERT(keyed[i - 1].second < keyed[i].second, "sort_keyed_in_index_order: indices must ascend");
  if (n < 2) return;
  // Every byte's counts in one read; then one stable scatter per byte in
  // which the keys differ.
  std::vector<std::array<size_t, 256>> start(8);
  uint64_t differ = 0;  // the bits in which some key differs from the first
  for (const KeyedIndex& k : keyed) {
    differ |= k.first ^ keyed[0].first;
    for (int byte = 0; byte < 8; ++byte) ++start[static_cast<size_t>(byte)][(k.first >> (8 * byte)) & 0xff];
  }
  std::vector<KeyedIndex> buffer(n);
  for (int byte = 0; byte < 8; ++byte) {
    const int shift = 8 * byte;
    if (((differ >> shift) & 0xff) == 0) continue;
    std::array<size_t, 256>& at = start[static_cast<size_t>(byte)];
    size_t sum = 0;
    for (size_t& s : at) sum += std::exchange(s, sum);
    for (const KeyedIndex& k : keyed) buffer[at[(k.first >> shift) & 0xff]++] = k;
    keyed.swap(buffer);
  }
}

}  // namespace partet
