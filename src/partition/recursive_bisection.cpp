// partition_points: recursive bisection level by level. All ranks work on
// all the rank sets of a level at once (no sub-communicators: the points do
// not move, so every rank may hold points of every rank set); each level
// costs one all-reduce of totals, one of inertia moments (RIB, MROB), the
// rounds of weighted_cut and one of the separator offsets, all segmented by
// rank set. Weights are quantised to integers (sum below 2^62) so that every
// sum is exact and the result does not depend on the reduction order.
#include "partition/recursive_bisection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "partition/inertia.hpp"
#include "partition/weighted_cut.hpp"

namespace partet {
namespace {

struct RankRange {
  int first, last;
};

// Every rank agrees that all points are valid, or all throw.
void check_points(const Comm& comm, const double* xyz, const double* weight, size_t n) {
  std::string problem;
  for (size_t i = 0; i < n && problem.empty(); ++i) {
    bool finite = std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2]);
    if (!finite || !std::isfinite(weight[i]) || !(weight[i] >= 0))
      problem = "partition_points: point " + std::to_string(i) + " of rank " + std::to_string(comm.rank()) +
                " has a non-finite coordinate or a negative or non-finite weight";
  }
  if (comm.max(int64_t{problem.empty() ? 0 : 1}) == 0) return;
  throw InternalError(problem.empty() ? "partition_points: another rank passed an invalid point" : problem);
}

// Weights scaled by one power of two (the same on all ranks) and rounded, so
// that the global sum stays at most 2^62: a weight below about
// max weight * N / 2^62 (N points in all) becomes 0. All zero weights count
// as one each.
std::vector<uint64_t> quantize_weights(const Comm& comm, const double* weight, size_t n) {
  const int64_t total_points = comm.sum(static_cast<int64_t>(n));
  double local_max = 0;
  for (size_t i = 0; i < n; ++i) local_max = std::max(local_max, weight[i]);
  const double max_weight = comm.max(local_max);
  std::vector<uint64_t> q(n, 1);
  if (max_weight == 0) return q;
  int max_exponent = 0;  // max_weight < 2^max_exponent
  std::frexp(max_weight, &max_exponent);
  int count_bits = 0;  // total_points <= 2^count_bits
  while ((int64_t{1} << count_bits) < total_points) ++count_bits;
  const int scale = 62 - count_bits - max_exponent;
  for (size_t i = 0; i < n; ++i) q[i] = static_cast<uint64_t>(std::llround(std::ldexp(weight[i], scale)));
  return q;
}

// The integer nearest to total * part / whole.
uint64_t fraction_of(uint64_t total, int part, int whole) {
  using u128 = unsigned __int128;
  u128 num = static_cast<u128>(total) * static_cast<u128>(part) + static_cast<u128>(whole / 2);
  return static_cast<uint64_t>(num / static_cast<u128>(whole));
}

// The cutting normal of every slot of one level, and its coordinate axis
// (-1 for a RIB normal that is not one).
std::vector<double> level_normals(const Comm& comm, const double* xyz, const uint64_t* weight,
                                  const int32_t* slot, size_t n, size_t slots, BisectionMethod method,
                                  int depth, std::vector<int>& axis) {
  std::vector<double> normal(slots * 3, 0.0);
  axis.assign(slots, depth % 3);  // ROB, and any slot whose points have no spread
  if (method != BisectionMethod::kRob) {
    InertiaAxes inertia = principal_axes(comm, xyz, weight, slot, n, slots);
    for (size_t s = 0; s < slots; ++s) {
      if (!inertia.valid[s]) continue;
      const double* a = &inertia.axis[s * 3];
      axis[s] = closest_coordinate_axis(a);
      if (method == BisectionMethod::kRib && std::fabs(a[axis[s]]) != 1.0) {
        axis[s] = -1;
        for (size_t k = 0; k < 3; ++k) normal[s * 3 + k] = a[k];
      }
    }
  }
  for (size_t s = 0; s < slots; ++s)
    if (axis[s] >= 0) normal[s * 3 + static_cast<size_t>(axis[s])] = 1.0;
  return normal;
}

// The plane offset between the last low projection `lo` and the first high
// one `hi` (lo <= hi; -inf / +inf for an empty side): halves are exact and
// the rounded sum stays in [lo, hi].
double offset_between(double lo, double hi) {
  if (std::isfinite(lo) && std::isfinite(hi)) return lo * 0.5 + hi * 0.5;
  if (std::isfinite(lo)) return lo;
  return std::isfinite(hi) ? hi : 0.0;
}

}  // namespace

PartitionResult partition_points(const Comm& comm, const double* xyz, const double* weight, size_t n,
                                 BisectionMethod method) {
  check_points(comm, xyz, weight, n);
  const std::vector<uint64_t> quantized = quantize_weights(comm, weight, n);
  std::vector<int64_t> counts = comm.all_gather(static_cast<int64_t>(n));
  uint64_t first_index = 0;  // global index of this rank's first point
  for (int r = 0; r < comm.rank(); ++r) first_index += static_cast<uint64_t>(counts[static_cast<size_t>(r)]);

  PartitionResult result;
  std::vector<RankRange> ranges{{0, comm.size()}};
  std::vector<int32_t> range_of(n, 0);
  std::vector<int32_t> slot(n);
  std::vector<uint64_t> effective(n);
  std::vector<double> proj(n);
  for (int depth = 0;; ++depth) {
    // The rank sets still to split are this level's slots.
    std::vector<int32_t> slot_of_range(ranges.size(), -1);
    std::vector<size_t> range_of_slot;
    for (size_t r = 0; r < ranges.size(); ++r) {
      if (ranges[r].last - ranges[r].first < 2) continue;
      slot_of_range[r] = static_cast<int32_t>(range_of_slot.size());
      range_of_slot.push_back(r);
    }
    const size_t slots = range_of_slot.size();
    if (slots == 0) break;
    for (size_t i = 0; i < n; ++i) slot[i] = slot_of_range[static_cast<size_t>(range_of[i])];

    // Totals: a slot whose weights are all zero counts its points instead.
    std::vector<int64_t> totals(slots * 2, 0);
    for (size_t i = 0; i < n; ++i) {
      if (slot[i] < 0) continue;
      totals[static_cast<size_t>(slot[i]) * 2] += static_cast<int64_t>(quantized[i]);
      totals[static_cast<size_t>(slot[i]) * 2 + 1] += 1;
    }
    comm.sum(totals.data(), totals.size());
    for (size_t i = 0; i < n; ++i)
      effective[i] = slot[i] >= 0 && totals[static_cast<size_t>(slot[i]) * 2] > 0 ? quantized[i] : 1;

    std::vector<int> axis;
    std::vector<double> normal = level_normals(comm, xyz, effective.data(), slot.data(), n, slots, method, depth, axis);

    // Keys (CutKeys): the projection, then the coordinates, the weight and
    // the global index break ties.
    for (size_t i = 0; i < n; ++i)
      if (slot[i] >= 0) proj[i] = project(&normal[static_cast<size_t>(slot[i]) * 3], &xyz[3 * i]);
    const CutKeys keys{proj.data(), xyz, weight, first_index};
    std::vector<uint64_t> target(slots);
    for (size_t s = 0; s < slots; ++s) {
      const RankRange& rr = ranges[range_of_slot[s]];
      int64_t total = totals[s * 2] > 0 ? totals[s * 2] : totals[s * 2 + 1];
      target[s] = fraction_of(static_cast<uint64_t>(total), (rr.last - rr.first) / 2, rr.last - rr.first);
    }
    std::vector<uint8_t> low = weighted_cut(comm, keys, effective.data(), slot.data(), n, target);

    // Offsets midway between the last low projection and the first high one.
    std::vector<double> extreme(slots * 2, -std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < n; ++i) {
      if (slot[i] < 0) continue;
      double& e = extreme[static_cast<size_t>(slot[i]) * 2 + (low[i] ? 0 : 1)];
      e = std::max(e, low[i] ? proj[i] : -proj[i]);
    }
    comm.max(extreme.data(), extreme.size());

    std::vector<RankRange> next;
    std::vector<int32_t> low_range(ranges.size()), high_range(ranges.size());
    for (size_t r = 0; r < ranges.size(); ++r) {
      const RankRange rr = ranges[r];
      const int32_t s = slot_of_range[r];
      if (s < 0) {
        low_range[r] = high_range[r] = static_cast<int32_t>(next.size());
        next.push_back(rr);
        continue;
      }
      const int mid = rr.first + (rr.last - rr.first) / 2;
      const size_t at = static_cast<size_t>(s);
      Separator sep{};
      for (size_t k = 0; k < 3; ++k) sep.normal[k] = normal[at * 3 + k];
      sep.offset = offset_between(extreme[at * 2], -extreme[at * 2 + 1]);
      sep.axis = axis[at];
      sep.first_rank = rr.first;
      sep.mid_rank = mid;
      sep.last_rank = rr.last;
      sep.depth = depth;
      result.separators.push_back(sep);
      low_range[r] = static_cast<int32_t>(next.size());
      next.push_back({rr.first, mid});
      high_range[r] = static_cast<int32_t>(next.size());
      next.push_back({mid, rr.last});
    }
    for (size_t i = 0; i < n; ++i) {
      size_t r = static_cast<size_t>(range_of[i]);
      range_of[i] = slot[i] >= 0 && !low[i] ? high_range[r] : low_range[r];
    }
    ranges = std::move(next);
  }

  result.destination.resize(n);
  for (size_t i = 0; i < n; ++i) result.destination[i] = ranges[static_cast<size_t>(range_of[i])].first;
  return result;
}

}  // namespace partet
