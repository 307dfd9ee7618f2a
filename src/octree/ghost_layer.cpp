// Two ghost layers by two rounds of range queries on the partition view (see
// ghost_layer.hpp).
#include "octree/ghost_layer.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

#include "octree/range_query.hpp"
#include "parallel/migrate.hpp"

namespace partet {
namespace {

struct LeafRecord {
  uint64_t key = 0;
  uint8_t level = 0;
  LeafClass cls = LeafClass::kUnclassified;
  uint8_t unused[6] = {};
};
static_assert(sizeof(LeafRecord) == 16, "records are sent as bytes");

LeafRecord record_of(const LinearOctree& tree, size_t i) {
  LeafRecord r;
  r.key = tree.key[i];
  r.level = tree.level[i];
  r.cls = tree.cls[i];
  return r;
}

// The leaves of `query`'s tree whose closed boxes meet the closed box of the
// octant (key, level): those holding a grid cell of the octant grown by one
// cell on every side.
void touching(const LeafRangeQuery& query, uint64_t key, int level, std::vector<size_t>& out) {
  uint32_t a[3], lo[3], hi[3];
  morton_decode(key, a[0], a[1], a[2]);
  const uint32_t edge = octant_edge(level);
  for (int i = 0; i < 3; ++i) {
    lo[i] = a[i] > 0 ? a[i] - 1 : 0;
    hi[i] = std::min(a[i] + edge, kGridSize - 1);
  }
  query.leaves_in_range(lo, hi, out);
}

// Appends to `send`/`destination` this rank's leaves touching each octant of
// `octants`, once per destination; `owner_of(k)` names the rank asking about
// octant k.
template <class OwnerOf>
void own_leaves_touching(const LinearOctree& view, const LeafRangeQuery& query, int rank,
                         const std::vector<LeafRecord>& octants, OwnerOf owner_of,
                         std::vector<LeafRecord>& send, std::vector<int32_t>& destination) {
  std::vector<std::pair<int32_t, size_t>> found;  // (asking rank, own leaf)
  std::vector<size_t> hits;
  for (size_t k = 0; k < octants.size(); ++k) {
    touching(query, octants[k].key, octants[k].level, hits);
    for (size_t h : hits)
      if (view.owner[h] == rank) found.emplace_back(owner_of(k), h);
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  for (const auto& [to, leaf] : found) {
    send.push_back(record_of(view, leaf));
    destination.push_back(to);
  }
}

}  // namespace

LinearOctree ghost_view(const Comm& comm, const DistributedOctree& tree, GhostCounts* counts) {
  const int rank = comm.rank();
  const LinearOctree view = partition_view(tree.leaves, tree.ranges, rank);
  const LeafRangeQuery query(view);

  // Layer 1: to every other rank, the own leaves touching its range octants.
  std::vector<LeafRecord> placeholders;
  std::vector<int32_t> placeholder_owner;
  for (size_t i = 0; i < view.size(); ++i)
    if (view.owner[i] != rank) {
      placeholders.push_back(record_of(view, i));
      placeholder_owner.push_back(view.owner[i]);
    }
  std::vector<LeafRecord> send;
  std::vector<int32_t> destination;
  own_leaves_touching(view, query, rank, placeholders, [&](size_t k) { return placeholder_owner[k]; }, send,
                      destination);
  std::vector<int32_t> layer1_owner;
  const std::vector<LeafRecord> layer1 = migrate(comm, destination, send, 1, &layer1_owner);

  // Layer 2: ask the ranks whose ranges touch a layer-1 leaf for their
  // leaves touching it.
  std::vector<LeafRecord> asks;
  std::vector<int32_t> ask_to;
  std::vector<size_t> hits;
  std::vector<int32_t> owners;
  for (const LeafRecord& g : layer1) {
    touching(query, g.key, g.level, hits);
    owners.clear();
    for (size_t h : hits)
      if (view.owner[h] != rank) owners.push_back(view.owner[h]);
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    for (int32_t o : owners) {
      asks.push_back(g);
      ask_to.push_back(o);
    }
  }
  std::vector<int32_t> asker;
  const std::vector<LeafRecord> asked = migrate(comm, ask_to, asks, 1, &asker);
  send.clear();
  destination.clear();
  own_leaves_touching(view, query, rank, asked, [&](size_t k) { return asker[k]; }, send, destination);
  std::vector<LeafRecord> layer2 = migrate(comm, destination, send);

  // The local view: own leaves, layer 1, layer 2 (less what is in layer 1),
  // placeholders in the gaps.
  using Entry = std::tuple<uint64_t, uint8_t, LeafClass, int32_t>;
  std::vector<Entry> entries;
  for (size_t i = 0; i < tree.leaves.size(); ++i)
    entries.emplace_back(tree.leaves.key[i], tree.leaves.level[i], tree.leaves.cls[i], rank);
  for (size_t i = 0; i < layer1.size(); ++i)
    entries.emplace_back(layer1[i].key, layer1[i].level, layer1[i].cls, layer1_owner[i]);
  for (const LeafRecord& r : layer2) entries.emplace_back(r.key, r.level, r.cls, kContextOwner);
  // Layer 2 may repeat layer-1 leaves: equal keys are ordered by owner,
  // largest first (a layer-1 owner before kContextOwner), and the first kept.
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) < std::get<0>(b) : std::get<3>(a) > std::get<3>(b);
  });
  entries.erase(std::unique(entries.begin(), entries.end(),
                            [](const Entry& a, const Entry& b) { return std::get<0>(a) == std::get<0>(b); }),
                entries.end());
  LinearOctree out;
  uint64_t next = 0;  // first key not yet covered
  const auto fill_to = [&](uint64_t key) {
    append_range_octants(next, key, out.key, out.level);
    out.cls.resize(out.size(), LeafClass::kOutside);
    out.owner.resize(out.size(), kContextOwner);
  };
  size_t context = 0;
  for (const auto& [key, level, cls, owner] : entries) {
    fill_to(key);
    out.key.push_back(key);
    out.level.push_back(level);
    out.cls.push_back(cls);
    out.owner.push_back(owner);
    next = key + octant_key_span(level);
    context += owner == kContextOwner;
  }
  fill_to(octant_key_span(0));
  if (counts) {
    counts->layer1 = layer1.size();
    counts->layer2 = context;
  }
  return out;
}

}  // namespace partet
