// Morton key ranges of the ranks of a distributed octree, and the octants
// that tile a key range.
//
// A distributed octree gives each rank one contiguous range of Morton keys
// (in rank order: rank r's keys all come before rank r + 1's), possibly
// empty; the ranges tile the root cube's keys [0, 8^kMaxLevel). A key range
// [b, e) is a union of aligned octants, at most 7 per level on each side
// (like the digits of b and e in base 8): range_octants lists the coarsest
// ones. The partition view of one rank is its own leaves plus the range
// octants of every other rank (labelled with that rank as owner): a complete
// linear octree, so every serial algorithm that needs completeness (range
// queries, neighbour searches, refinement) runs on it unchanged, and a
// placeholder octant tells which rank holds the leaves there.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"

namespace partet {

struct KeyPartition {
  // Per rank + 1: rank r holds the keys [first[r], first[r + 1]) (empty
  // when equal); first.back() == octant_key_span(0).
  std::vector<uint64_t> first;

  int ranks() const { return static_cast<int>(first.size()) - 1; }
  // The rank whose (non-empty) range holds `key`.
  int owner(uint64_t key) const;
};

// Collective: every rank passes its range [begin, end) (begin == end when it
// holds nothing); the ranges of the non-empty ranks must tile the key space
// in rank order (InternalError otherwise).
KeyPartition gather_key_partition(const Comm& comm, uint64_t begin, uint64_t end);

// Appends (anchor key, level) of the coarsest aligned octants tiling
// [begin, end), in key order.
void append_range_octants(uint64_t begin, uint64_t end, std::vector<uint64_t>& key, std::vector<uint8_t>& level);

// Rank `rank`'s leaves `own` (sorted, inside its range) with the range
// octants of every other rank around them, whose owner is that rank and
// class kUnclassified. Complete.
LinearOctree partition_view(const LinearOctree& own, const KeyPartition& ranges, int rank);

// The leaves of `view` whose owner is `owner`, in order.
LinearOctree leaves_of(const LinearOctree& view, int32_t owner);

}  // namespace partet
