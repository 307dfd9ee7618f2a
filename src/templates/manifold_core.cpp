// The manifold pass over the interior leaves (see manifold_core.hpp): the
// octant occupancy of every tested point, one byte per child anchor of a
// leaf, then rounds of repairs at the non-manifold points, each demoting
// the fewest leaves that make its occupancy manifold.
#include "templates/manifold_core.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "templates/face_rule.hpp"
#include "templates/leaf_neighbourhood.hpp"

namespace partet {
namespace {

// True when the octants of `set` are connected across octant faces (octants
// differing in one bit); the empty set is.
constexpr bool octants_connected(unsigned set) {
  if (set == 0) return true;
  unsigned reached = set & (~set + 1);
  for (;;) {
    unsigned grown = reached;
    for (int o = 0; o < 8; ++o)
      if (reached >> o & 1)
        for (int k = 0; k < 3; ++k) grown |= 1u << (o ^ (1 << k));
    grown &= set;
    if (grown == reached) return reached == set;
    reached = grown;
  }
}

constexpr bool occupancy_is_manifold(unsigned m) {
  if (m == 0 || m == 0xFF) return true;
  // Around each half-axis (axis k, side s) the four octants in cyclic
  // order: (u, v) = (0,0), (1,0), (1,1), (0,1). Two opposite ones alone make
  // the edge along that half-axis non-manifold.
  for (int k = 0; k < 3; ++k) {
    const int u = 1 << ((k + 1) % 3), v = 1 << ((k + 2) % 3);
    for (int s = 0; s < 2; ++s) {
      const int base = s << k;
      const bool a = m >> base & 1, b = m >> (base | u) & 1;
      const bool c = m >> (base | u | v) & 1, d = m >> (base | v) & 1;
      if (a == c && b == d && a != b) return false;
    }
  }
  return octants_connected(m) && octants_connected(~m & 0xFFu);
}

constexpr std::array<bool, 256> kManifold = [] {
  std::array<bool, 256> table{};
  for (unsigned m = 0; m < 256; ++m) table[m] = occupancy_is_manifold(m);
  return table;
}();

// The octants a leaf covers at its lattice point t (face_rule.hpp): on
// axis k only the high side when t_k = 0, only the low side when t_k = 2,
// both when t_k = 1.
constexpr std::array<uint8_t, kLeafPoints> kFootprint = [] {
  std::array<uint8_t, kLeafPoints> footprint{};
  for (int p = 0; p < kLeafPoints; ++p) {
    const int t[3] = {p % 3, p / 3 % 3, p / 9};
    unsigned mask = 0;
    for (unsigned o = 0; o < 8; ++o) {
      bool covered = true;
      for (int k = 0; k < 3; ++k) {
        const unsigned high = o >> k & 1;
        covered = covered && (t[k] == 1 || (t[k] == 0) == (high == 1));
      }
      mask |= static_cast<unsigned>(covered) << o;
    }
    footprint[p] = static_cast<uint8_t>(mask);
  }
  return footprint;
}();

constexpr bool is_corner_point(int p) { return p % 3 != 1 && p / 3 % 3 != 1 && p / 9 != 1; }

// The occupancy of the leaves' child anchors and which of them are tested
// (corners of leaves that were interior when the pass started). A point is
// named by its index 8 * home leaf + child anchor. With a `part` (a rank),
// the tree is a local view (octree/ghost_layer.hpp): only leaves with an
// owner mark their points, and only points homed on the part's leaves are
// tested; without (part < 0), every leaf does both.
class Occupancy {
 public:
  Occupancy(LinearOctree& tree, int32_t part)
      : tree_(tree), around_(tree), octants_(8 * tree.size(), 0), tested_(tree.size(), 0), part_(part) {}

  bool marks(size_t i) const { return part_ < 0 || tree_.owner[i] >= 0; }
  bool tests(size_t i) const { return part_ < 0 || tree_.owner[i] == part_; }

  // Marks the octants of every interior leaf at its 26 boundary points.
  void gather() {
    for (size_t i = 0; i < tree_.size(); ++i) {
      if (tree_.cls[i] != LeafClass::kInterior || !marks(i)) continue;
      around_.reset(i);
      for (int p = 0; p < kLeafPoints; ++p) {
        if (p == kLeafCentre) continue;
        const PointHome h = around_.home(p);
        if (h.leaf == kAbsentLeaf) {
          PARTET_ASSERT(!is_corner_point(p), "corner without a home at leaf " + std::to_string(i));
          continue;
        }
        octants_[8 * size_t{h.leaf} + h.child] |= kFootprint[p];
        if (is_corner_point(p)) tested_[h.leaf] |= static_cast<uint8_t>(1u << h.child);
      }
    }
  }

  // Appends the tested points that are not manifold, ascending.
  void find_non_manifold(std::vector<uint64_t>& out) const {
    for (size_t i = 0; i < tree_.size(); ++i)
      for (unsigned bits = tests(i) ? tested_[i] : 0u; bits != 0; bits &= bits - 1) {
        const uint64_t point = 8 * uint64_t{i} + static_cast<unsigned>(__builtin_ctz(bits));
        if (!kManifold[octants_[point]]) out.push_back(point);
      }
  }

  bool manifold(uint64_t point) const { return kManifold[octants_[point]]; }

  // Keeps the best manifold set of the interior leaves around `point` (see
  // the header) and demotes the others, appending them to `demoted` and the
  // tested points whose occupancy changed to `changed`.
  void repair(uint64_t point, std::vector<uint64_t>& changed, std::vector<size_t>& demoted) {
    const size_t home = point / 8;
    const unsigned child = point % 8;
    const unsigned mask = octants_[point];
    uint32_t p[3];
    tree_.anchor(home, p[0], p[1], p[2]);
    const uint32_t edge = octant_edge(tree_.level[home]);
    PARTET_ASSERT(child == 0 || edge >= 2,
                  "tested point off the grid at leaf " + std::to_string(home));
    for (int k = 0; k < 3; ++k) p[k] += (child >> k & 1) * (edge / 2);

    // The interior leaves around the point, in octant order, with the octants
    // each covers there.
    uint32_t leaf[8];
    uint8_t covers[8];
    int count = 0;
    for (unsigned o = 0; o < 8; ++o) {
      if (!(mask >> o & 1)) continue;
      uint32_t c[3];
      for (int k = 0; k < 3; ++k) {
        const bool high = o >> k & 1;
        PARTET_ASSERT(high ? p[k] < kGridSize : p[k] > 0, "occupied octant outside the root cube");
        c[k] = high ? p[k] : p[k] - 1;
      }
      const uint64_t key = morton_key(c[0], c[1], c[2]);
      const uint32_t j = static_cast<uint32_t>(seek_leaf_near(tree_, home, key));
      PARTET_ASSERT(tree_.cls[j] == LeafClass::kInterior,
                    "occupied octant in leaf " + std::to_string(j) + ", which is not interior");
      int m = 0;
      while (m < count && leaf[m] != j) ++m;
      if (m == count) {
        leaf[count] = j;
        covers[count++] = 0;
      }
      covers[m] = static_cast<uint8_t>(covers[m] | 1u << o);
    }

    // The best manifold subset to keep: most octants, then most volume.
    unsigned best = 0, best_octants = 0;
    uint64_t best_volume = 0;
    for (unsigned keep = 1; keep < (1u << count); ++keep) {
      unsigned kept = 0;
      uint64_t volume = 0;
      for (int m = 0; m < count; ++m)
        if (keep >> m & 1) {
          kept |= covers[m];
          volume += octant_key_span(tree_.level[leaf[m]]);
        }
      if (!kManifold[kept]) continue;
      const unsigned octants = static_cast<unsigned>(__builtin_popcount(kept));
      if (octants > best_octants || (octants == best_octants && volume > best_volume)) {
        best = keep;
        best_octants = octants;
        best_volume = volume;
      }
    }
    for (int m = 0; m < count; ++m)
      if (!(best >> m & 1)) {
        demote(leaf[m], changed);
        demoted.push_back(leaf[m]);
      }
  }

  // Makes leaf i too close and clears its octants at its boundary points.
  void demote(size_t i, std::vector<uint64_t>& changed) {
    tree_.cls[i] = LeafClass::kTooClose;
    if (!marks(i)) return;
    around_.reset(i);
    for (int p = 0; p < kLeafPoints; ++p) {
      if (p == kLeafCentre) continue;
      const PointHome h = around_.home(p);
      if (h.leaf == kAbsentLeaf) continue;
      const uint64_t point = 8 * uint64_t{h.leaf} + h.child;
      octants_[point] &= static_cast<uint8_t>(~kFootprint[p]);
      if ((tested_[h.leaf] >> h.child & 1) && tests(h.leaf)) changed.push_back(point);
    }
  }

 private:

  LinearOctree& tree_;
  LeafNeighbourhood around_;
  std::vector<uint8_t> octants_;  // 8 per leaf: occupancy of child anchor b at 8 i + b
  std::vector<uint8_t> tested_;   // per leaf: the child anchors that are tested points
  int32_t part_;
};

// The next round's points: the changed ones still not manifold.
void next_queue(const Occupancy& occupancy, std::vector<uint64_t>& changed, std::vector<uint64_t>& queue) {
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  queue.clear();
  for (uint64_t point : changed)
    if (!occupancy.manifold(point)) queue.push_back(point);
}

}  // namespace

bool manifold_occupancy(unsigned mask) { return kManifold[mask & 0xFFu]; }

ManifoldCoreCounts make_core_manifold(LinearOctree& tree) {
  PARTET_ASSERT(tree.size() < UINT32_MAX, "more than 2^32 - 1 leaves");
  ManifoldCoreCounts counts;
  Occupancy occupancy(tree, -1);
  occupancy.gather();
  std::vector<uint64_t> queue, changed;
  std::vector<size_t> demoted;
  occupancy.find_non_manifold(queue);
  while (!queue.empty()) {
    ++counts.rounds;
    changed.clear();
    for (uint64_t point : queue) {
      if (occupancy.manifold(point)) continue;
      ++counts.repaired;
      occupancy.repair(point, changed, demoted);
    }
    next_queue(occupancy, changed, queue);
  }
  counts.demoted = demoted.size();
  for (LeafClass c : tree.cls) counts.interior += c == LeafClass::kInterior;
  return counts;
}

ManifoldCoreCounts make_core_manifold(const Comm& comm, LinearOctree& view) {
  PARTET_ASSERT(view.size() < UINT32_MAX, "more than 2^32 - 1 leaves");
  const int rank = comm.rank();
  ManifoldCoreCounts counts;
  Occupancy occupancy(view, rank);
  occupancy.gather();
  std::vector<uint64_t> queue, changed;
  std::vector<size_t> demoted;
  occupancy.find_non_manifold(queue);
  for (;;) {
    const std::vector<int64_t> waiting = comm.all_gather(static_cast<int64_t>(queue.size()));
    if (std::all_of(waiting.begin(), waiting.end(), [](int64_t w) { return w == 0; })) break;
    ++counts.rounds;
    changed.clear();
    // The ranks repair their points in rank order (the serial order), each
    // telling every rank the leaves it demoted before the next one starts.
    for (int r = 0; r < comm.size(); ++r) {
      if (waiting[static_cast<size_t>(r)] == 0) continue;
      std::string keys;
      if (r == rank) {
        const size_t before = demoted.size();
        for (uint64_t point : queue) {
          if (occupancy.manifold(point)) continue;
          ++counts.repaired;
          occupancy.repair(point, changed, demoted);
        }
        keys.resize((demoted.size() - before) * sizeof(uint64_t));
        for (size_t k = before; k < demoted.size(); ++k)
          std::memcpy(&keys[(k - before) * sizeof(uint64_t)], &view.key[demoted[k]], sizeof(uint64_t));
      }
      comm.broadcast(keys, r);
      if (r == rank) continue;
      for (size_t at = 0; at < keys.size(); at += sizeof(uint64_t)) {
        uint64_t key;
        std::memcpy(&key, &keys[at], sizeof key);
        const auto it = std::lower_bound(view.key.begin(), view.key.end(), key);
        if (it == view.key.end() || *it != key) continue;  // not near this rank
        const size_t i = static_cast<size_t>(it - view.key.begin());
        if (view.cls[i] == LeafClass::kInterior) occupancy.demote(i, changed);
      }
    }
    next_queue(occupancy, changed, queue);
  }
  int64_t n[3] = {static_cast<int64_t>(demoted.size()), static_cast<int64_t>(counts.repaired), 0};
  for (size_t i = 0; i < view.size(); ++i) n[2] += view.owner[i] == rank && view.cls[i] == LeafClass::kInterior;
  comm.sum(n, 3);
  counts.demoted = static_cast<size_t>(n[0]);
  counts.repaired = static_cast<size_t>(n[1]);
  counts.interior = static_cast<size_t>(n[2]);
  return counts;
}

}  // namespace partet
