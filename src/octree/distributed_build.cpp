// Distributed tree building by rank-set halving, triangle refinement per
// rank and balance by one exchange of required octants (see
// distributed_build.hpp).
#include "octree/distributed_build.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "parallel/migrate.hpp"

namespace partet {
namespace {

// The terminal octants of one rank set, in key order (the same on every rank
// of the set).
struct Octants {
  std::vector<uint64_t> key;
  std::vector<uint8_t> level;
  size_t size() const { return key.size(); }
  // Replaces octant j by its 8 children.
  void split(size_t j) {
    const uint8_t child = static_cast<uint8_t>(level[j] + 1);
    const uint64_t span = octant_key_span(child);
    const uint64_t k = key[j];
    key.erase(key.begin() + static_cast<std::ptrdiff_t>(j));
    level.erase(level.begin() + static_cast<std::ptrdiff_t>(j));
    for (uint64_t c = 8; c-- > 0;) {
      key.insert(key.begin() + static_cast<std::ptrdiff_t>(j), k + c * span);
      level.insert(level.begin() + static_cast<std::ptrdiff_t>(j), child);
    }
  }
};

// Per octant, this rank's part of: its load (sum of the levels of the points
// in it) at 2 j, and the number of its points asking for a deeper level at
// 2 j + 1. `points` are sorted and all inside the octants.
std::vector<int64_t> octant_stats(const Octants& o, const std::vector<RefineRequest>& points) {
  std::vector<int64_t> stats(2 * o.size(), 0);
  size_t p = 0;
  for (size_t j = 0; j < o.size(); ++j) {
    PARTET_ASSERT(p == points.size() || points[p].key >= o.key[j], "point outside its rank set's octants");
    const uint64_t end = o.key[j] + octant_key_span(o.level[j]);
    for (; p < points.size() && points[p].key < end; ++p) {
      stats[2 * j] += points[p].level;
      stats[2 * j + 1] += points[p].level > o.level[j];
    }
  }
  PARTET_ASSERT(p == points.size(), "point outside its rank set's octants");
  return stats;
}

// Sums `values` (this rank's, for its set's octants) over the ranks of each
// rank set, all sets in one all-reduce, each in its own segment. `first`:
// the first rank of this rank's set, which announces the segment length.
std::vector<int64_t> set_sum(const Comm& comm, int first, std::vector<int64_t> values) {
  const std::vector<int64_t> sizes =
      comm.all_gather(static_cast<int64_t>(comm.rank() == first ? values.size() : 0));
  size_t offset = 0, total = 0;
  for (size_t r = 0; r < sizes.size(); ++r) {
    if (static_cast<int>(r) < first) offset += static_cast<size_t>(sizes[r]);
    total += static_cast<size_t>(sizes[r]);
  }
  PARTET_ASSERT(offset + values.size() <= total, "rank set segments disagree");
  std::vector<int64_t> all(total, 0);
  std::copy(values.begin(), values.end(), all.begin() + static_cast<std::ptrdiff_t>(offset));
  comm.sum(all.data(), total);
  std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(offset), values.size(), values.begin());
  return values;
}

// The cut of a rank set's octants: the low ranks take octants [0, k).
struct Cut {
  size_t k = 0;
  int64_t miss = 0;          // |prefix load - target|
  size_t straddler = SIZE_MAX;  // the octant whose load spans the target, if any
};

Cut choose_cut(const std::vector<int64_t>& stats, int low_ranks, int ranks) {
  const size_t n = stats.size() / 2;
  int64_t total = 0;
  for (size_t j = 0; j < n; ++j) total += stats[2 * j];
  // Nearest integer to total * low_ranks / ranks (loads are small: no overflow).
  const int64_t target = (total * low_ranks + ranks / 2) / ranks;
  Cut cut;
  cut.miss = target;
  int64_t prefix = 0;
  for (size_t k = 1; k <= n; ++k) {
    const int64_t before = prefix;
    prefix += stats[2 * (k - 1)];
    if (before < target && target < prefix) cut.straddler = k - 1;
    const int64_t miss = prefix > target ? prefix - target : target - prefix;
    if (miss < cut.miss) {
      cut.miss = miss;
      cut.k = k;
    }
  }
  return cut;
}

}  // namespace

DistributedOctree build_distributed_octree(const Comm& comm, const std::vector<uint32_t>& grid,
                                           const std::vector<uint8_t>& level, TreeBuildCounts* counts) {
  PARTET_ASSERT(grid.size() == 3 * level.size(), "3 grid coordinates per point");
  std::vector<RefineRequest> points(level.size());
  for (size_t p = 0; p < level.size(); ++p) {
    PARTET_ASSERT(grid[3 * p] < kGridSize && grid[3 * p + 1] < kGridSize && grid[3 * p + 2] < kGridSize &&
                      level[p] <= kMaxLevel,
                  "point outside the grid or level too deep");
    points[p] = {morton_key(grid[3 * p], grid[3 * p + 1], grid[3 * p + 2]), level[p]};
  }
  const auto by_key = [](const RefineRequest& a, const RefineRequest& b) { return a.key < b.key; };
  std::sort(points.begin(), points.end(), by_key);

  const int rank = comm.rank();
  int first = 0, last = comm.size();  // this rank's set
  Octants octants;
  octants.key = {0};
  octants.level = {0};
  TreeBuildCounts n;
  while (comm.max(static_cast<int64_t>(last - first)) > 1) {
    ++n.depths;
    const bool active = last - first > 1;
    const int mid = first + (last - first) / 2;
    std::vector<int64_t> stats;
    for (int pass = 0;; ++pass) {
      ++n.coarse_passes;
      stats = set_sum(comm, first, active ? octant_stats(octants, points) : std::vector<int64_t>{});
      bool split = false;
      if (active && pass == 0) {
        // Every terminal octant holding a point that asks for more, once.
        for (size_t j = octants.size(); j-- > 0;)
          if (stats[2 * j + 1] > 0) {
            octants.split(j);
            split = true;
          }
      } else if (active) {
        const Cut cut = choose_cut(stats, mid - first, last - first);
        int64_t total = 0;
        for (size_t j = 0; j < octants.size(); ++j) total += stats[2 * j];
        if (cut.straddler != SIZE_MAX && cut.miss > total / (16 * (last - first)) &&
            stats[2 * cut.straddler + 1] > 0) {
          octants.split(cut.straddler);
          split = true;
        }
      }
      if (comm.max(static_cast<int64_t>(split)) == 0) break;
    }
    std::vector<int32_t> destination(points.size(), rank);
    if (active) {
      const Cut cut = choose_cut(stats, mid - first, last - first);
      const size_t k = cut.k;
      const uint64_t cut_key = k < octants.size() ? octants.key[k]
                                                  : octants.key.back() + octant_key_span(octants.level.back());
      const bool low = rank < mid;
      const int other_first = low ? mid : first;
      const int other_size = low ? last - mid : mid - first;
      const int position = rank - (low ? first : mid);
      const int32_t other = other_first + position % other_size;
      for (size_t p = 0; p < points.size(); ++p)
        if ((points[p].key < cut_key) != low) destination[p] = other;
      const auto split_at = static_cast<std::ptrdiff_t>(k);
      if (low) {
        octants.key.erase(octants.key.begin() + split_at, octants.key.end());
        octants.level.erase(octants.level.begin() + split_at, octants.level.end());
        last = mid;
      } else {
        octants.key.erase(octants.key.begin(), octants.key.begin() + split_at);
        octants.level.erase(octants.level.begin(), octants.level.begin() + split_at);
        first = mid;
      }
    }
    points = migrate(comm, destination, points);
    std::sort(points.begin(), points.end(), by_key);
  }
  if (counts) *counts = n;

  DistributedOctree out;
  LinearOctree& tree = out.leaves;
  tree.key = octants.key;
  tree.level = octants.level;
  tree.cls.assign(octants.size(), LeafClass::kUnclassified);
  tree.owner.assign(octants.size(), rank);
  const uint64_t begin = octants.size() ? octants.key.front() : 0;
  const uint64_t end = octants.size() ? octants.key.back() + octant_key_span(octants.level.back()) : 0;
  refine_octree(tree, std::move(points));
  out.ranges = gather_key_partition(comm, begin, end);
  return out;
}

void refine_distributed_for_triangles(DistributedOctree& tree, int rank, const SurfaceMesh& surface,
                                      const RootCube& root, const std::vector<uint8_t>& vertex_level) {
  LinearOctree view = partition_view(tree.leaves, tree.ranges, rank);
  refine_for_triangles(view, surface, root, vertex_level, rank);
  tree.leaves = leaves_of(view, rank);
}

void balance_distributed_octree(const Comm& comm, DistributedOctree& tree, int grading) {
  const std::vector<RefineRequest> required = balance_requests(tree.leaves, grading);
  std::vector<int32_t> destination(required.size());
  for (size_t i = 0; i < required.size(); ++i) destination[i] = tree.ranges.owner(required[i].key);
  refine_octree(tree.leaves, migrate(comm, destination, required));
}

}  // namespace partet
