// Key ranges of ranks, range octants and the partition view (see
// key_ranges.hpp).
#include "octree/key_ranges.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace partet {

int KeyPartition::owner(uint64_t key) const {
  PARTET_ASSERT(key < first.back(), "key outside the root cube");
  // Empty ranks share their first key with the next rank: the last rank
  // starting at or before `key` is the non-empty one.
  return static_cast<int>(std::upper_bound(first.begin(), first.end() - 1, key) - first.begin()) - 1;
}

KeyPartition gather_key_partition(const Comm& comm, uint64_t begin, uint64_t end) {
  PARTET_ASSERT(begin <= end && end <= octant_key_span(0), "bad key range");
  const std::vector<int64_t> begins = comm.all_gather(static_cast<int64_t>(begin));
  const std::vector<int64_t> ends = comm.all_gather(static_cast<int64_t>(end));
  const size_t p = begins.size();
  KeyPartition out;
  out.first.assign(p + 1, octant_key_span(0));
  uint64_t expected = 0;  // where the next non-empty range must start
  for (size_t r = 0; r < p; ++r) {
    if (begins[r] == ends[r]) continue;
    PARTET_ASSERT(static_cast<uint64_t>(begins[r]) == expected,
                  "key range of rank " + std::to_string(r) + " does not follow the previous one");
    expected = static_cast<uint64_t>(ends[r]);
  }
  PARTET_ASSERT(expected == octant_key_span(0), "the ranks' key ranges do not cover the root cube");
  for (size_t r = p; r-- > 0;)
    out.first[r] = begins[r] == ends[r] ? out.first[r + 1] : static_cast<uint64_t>(begins[r]);
  return out;
}

void append_range_octants(uint64_t begin, uint64_t end, std::vector<uint64_t>& key, std::vector<uint8_t>& level) {
  while (begin < end) {
    int l = 0;
    while (begin % octant_key_span(l) != 0 || begin + octant_key_span(l) > end) ++l;
    key.push_back(begin);
    level.push_back(static_cast<uint8_t>(l));
    begin += octant_key_span(l);
  }
}

LinearOctree partition_view(const LinearOctree& own, const KeyPartition& ranges, int rank) {
  LinearOctree view;
  const auto add_range = [&](int r) {
    append_range_octants(ranges.first[r], ranges.first[r + 1], view.key, view.level);
    view.cls.resize(view.size(), LeafClass::kUnclassified);
    view.owner.resize(view.size(), r);
  };
  for (int r = 0; r < rank; ++r) add_range(r);
  view.key.insert(view.key.end(), own.key.begin(), own.key.end());
  view.level.insert(view.level.end(), own.level.begin(), own.level.end());
  view.cls.insert(view.cls.end(), own.cls.begin(), own.cls.end());
  view.owner.resize(view.size(), rank);
  for (int r = rank + 1; r < ranges.ranks(); ++r) add_range(r);
  return view;
}

LinearOctree leaves_of(const LinearOctree& view, int32_t owner) {
  LinearOctree out;
  for (size_t i = 0; i < view.size(); ++i) {
    if (view.owner[i] != owner) continue;
    out.key.push_back(view.key[i]);
    out.level.push_back(view.level[i]);
    out.cls.push_back(view.cls[i]);
    out.owner.push_back(owner);
  }
  return out;
}

}  // namespace partet
