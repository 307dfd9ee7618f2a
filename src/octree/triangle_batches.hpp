// Triangles near leaves, many triangles to one range query: the triangles
// are taken in tree order (triangles_in_tree_order) and grouped while the
// union of their regions (grid cells each triangle searches) stays within
// twice the first one's extent, kTriangleBatch at most. Each batch gets one
// range query over that union; the caller then tests each leaf only
// against the triangles whose own region it meets, so the result is the
// same as one query per triangle, for a fraction of the queries (most of
// the cost of a search per triangle is the query).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/range_query.hpp"

namespace partet {

constexpr size_t kTriangleBatch = 32;

// True when leaf `leaf` (anchor `a`, edge `edge` in grid units) contains a
// grid cell of the region [lo, hi] (inclusive).
inline bool leaf_meets_region(const uint32_t* a, uint32_t edge, const uint32_t* lo, const uint32_t* hi) {
  for (int i = 0; i < 3; ++i)
    if (a[i] > hi[i] || a[i] + (edge - 1) < lo[i]) return false;
  return true;
}

// `region_of(t)` gives triangle t's region: a value with members lo[3] and
// hi[3] (grid cells, inclusive) and whatever else the caller keeps per
// triangle. `visit(batch, leaves)` gets each batch (regions, in tree order)
// and the leaves over their union (ascending); with `only`, the members of
// `only` among them.
template <class RegionOf, class Visit>
void for_each_triangle_batch(const std::vector<uint32_t>& order, const LeafRangeQuery& query, RegionOf region_of,
                             Visit visit, const LeafSet* only = nullptr) {
  using Region = decltype(region_of(uint32_t{0}));
  std::vector<Region> batch;
  std::vector<size_t> leaves;
  size_t next = 0;
  while (next < order.size()) {
    batch.assign(1, region_of(order[next++]));
    uint32_t lo[3], hi[3], limit = 0;
    for (int i = 0; i < 3; ++i) {
      lo[i] = batch[0].lo[i];
      hi[i] = batch[0].hi[i];
      limit = std::max(limit, 2 * (hi[i] - lo[i] + 1));
    }
    while (next < order.size() && batch.size() < kTriangleBatch) {
      const Region r = region_of(order[next]);
      bool fits = true;
      for (int i = 0; i < 3; ++i) fits = fits && std::max(hi[i], r.hi[i]) - std::min(lo[i], r.lo[i]) < limit;
      if (!fits) break;
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], r.lo[i]);
        hi[i] = std::max(hi[i], r.hi[i]);
      }
      batch.push_back(r);
      ++next;
    }
    if (only) {
      query.leaves_in_range(lo, hi, leaves, *only);
    } else {
      query.leaves_in_range(lo, hi, leaves);
    }
    visit(batch, leaves);
  }
}

}  // namespace partet
