// Leaves overlapping a box of grid cells (see range_query.hpp).
#include "octree/range_query.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/error.hpp"

namespace partet {

namespace {

bool overlaps(const uint32_t* a, uint32_t h, const uint32_t* lo, const uint32_t* hi) {
  for (int i = 0; i < 3; ++i)
    if (a[i] > hi[i] || a[i] + (h - 1) < lo[i]) return false;
  return true;
}

bool inside(const uint32_t* a, uint32_t h, const uint32_t* lo, const uint32_t* hi) {
  for (int i = 0; i < 3; ++i)
    if (a[i] < lo[i] || a[i] + (h - 1) > hi[i]) return false;
  return true;
}

// Runs of at most this many leaves are scanned rather than descended; over
// a LeafSet, runs of up to kMemberScanRun (lever r1's removals without the
// optimizer: 64 -> 256 cut the tree-supported ones 0.72 -> 0.62 s and the
// tree-less ones 1.10 -> 0.84 s; 1,024 no better).
constexpr size_t kScanRun = 64;
constexpr size_t kMemberScanRun = 256;

// Every leaf, with a LeafSet's interface.
struct EveryLeaf {
  static bool any(size_t b, size_t e) { return b < e; }
  static bool contains(size_t) { return true; }
  template <class Visit>
  static void for_each(size_t b, size_t e, Visit&& visit) {
    for (size_t i = b; i < e; ++i) visit(i);
  }
};

// Runs a descent scans rather than splits: over a LeafSet the scan tests
// only the members (a word of bits per 64 leaves), and the children's
// binary searches it saves were most of the restricted query's time.
size_t scan_run(const EveryLeaf&) { return kScanRun; }
size_t scan_run(const LeafSet&) { return kMemberScanRun; }

}  // namespace

void grid_range(const RootCube& root, const double* blo, const double* bhi, uint32_t* lo, uint32_t* hi) {
  for (int i = 0; i < 3; ++i) {
    const double a = std::floor((blo[i] - root.origin[i]) / root.unit) - 1;
    const double b = std::floor((bhi[i] - root.origin[i]) / root.unit) + 1;
    const double top = kGridSize - 1;
    lo[i] = a <= 0 ? 0u : (a >= top ? kGridSize - 1 : static_cast<uint32_t>(a));
    hi[i] = b <= 0 ? 0u : (b >= top ? kGridSize - 1 : static_cast<uint32_t>(b));
  }
}

LeafRangeQuery::LeafRangeQuery(const LinearOctree& tree) : tree_(&tree), anchor_(3 * tree.size()) {
  PARTET_ASSERT(tree.size() < UINT32_MAX, "too many leaves for the search table");
  for (size_t i = 0; i < tree.size(); ++i) tree.anchor(i, anchor_[3 * i], anchor_[3 * i + 1], anchor_[3 * i + 2]);
  // Table level: about one cell per leaf, at most 8^7 cells.
  int level = 0;
  while (level < 7 && (size_t{1} << (3 * (level + 1))) <= tree.size()) ++level;
  table_shift_ = 3 * (kMaxLevel - level);
  const size_t cells = size_t{1} << (3 * level);
  table_.resize(cells + 1);
  size_t leaf = 0;
  for (size_t c = 0; c <= cells; ++c) {
    const uint64_t first_key = uint64_t{c} << table_shift_;
    while (leaf < tree.size() && tree.key[leaf] < first_key) ++leaf;
    table_[c] = static_cast<uint32_t>(leaf);
  }
}

size_t LeafRangeQuery::upper_bound(uint64_t key) const {
  const uint64_t cell = key >> table_shift_;
  const auto first = tree_->key.begin();
  return static_cast<size_t>(std::upper_bound(first + table_[cell], first + table_[cell + 1], key) - first);
}

size_t LeafRangeQuery::locate(uint32_t x, uint32_t y, uint32_t z) const { return upper_bound(morton_key(x, y, z)) - 1; }

size_t LeafRangeQuery::locate_near(size_t hint, uint32_t x, uint32_t y, uint32_t z) const {
  const uint64_t key = morton_key(x, y, z);
  const std::vector<uint64_t>& keys = tree_->key;
  const size_t n = keys.size();
  // Bracket the answer, the last leaf whose key is not above `key`, in
  // [lo, hi) by doubling steps away from the hint.
  size_t lo, hi, step = 1;
  if (keys[hint] <= key) {
    lo = hint;
    while (lo + step < n && keys[lo + step] <= key) {
      lo += step;
      step *= 2;
    }
    hi = std::min(lo + step, n);
  } else {
    hi = hint;
    while (hi >= step && keys[hi - step] > key) {
      hi -= step;
      step *= 2;
    }
    lo = hi >= step ? hi - step : 0;
  }
  const auto first = keys.begin();
  return static_cast<size_t>(std::upper_bound(first + static_cast<std::ptrdiff_t>(lo),
                                              first + static_cast<std::ptrdiff_t>(hi), key) - first) - 1;
}

template <class Only>
void LeafRangeQuery::descend(uint64_t key, const uint32_t* a, int level, size_t b, size_t e, const uint32_t* lo,
                             const uint32_t* hi, std::vector<size_t>& out, const Only& only) const {
  // The octant (key, anchor a, level) overlaps the query, is a leaf or
  // split, and its leaves are [b, e).
  if (!only.any(b, e)) return;
  if (e - b == 1 || inside(a, octant_edge(level), lo, hi)) {
    only.for_each(b, e, [&](size_t i) { out.push_back(i); });
    return;
  }
  if (e - b <= scan_run(only)) {
    only.for_each(b, e, [&](size_t i) {
      if (overlaps(&anchor_[3 * i], octant_edge(tree_->level[i]), lo, hi)) out.push_back(i);
    });
    return;
  }
  const uint64_t span = octant_key_span(level + 1);
  const uint32_t h = octant_edge(level + 1);
  const auto first = tree_->key.begin();
  size_t cb = b;
  for (uint32_t c = 0; c < 8; ++c) {
    const uint32_t ca[3] = {a[0] + ((c & 1) ? h : 0), a[1] + ((c & 2) ? h : 0), a[2] + ((c & 4) ? h : 0)};
    if (!overlaps(ca, h, lo, hi)) continue;
    const uint64_t ck = key + c * span;
    cb = static_cast<size_t>(std::lower_bound(first + cb, first + e, ck) - first);
    const size_t ce = static_cast<size_t>(std::lower_bound(first + cb, first + e, ck + span) - first);
    descend(ck, ca, level + 1, cb, ce, lo, hi, out, only);
    cb = ce;
  }
}

void LeafRangeQuery::leaves_in_range(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out) const {
  collect(lo, hi, out, EveryLeaf{});
}

void LeafRangeQuery::leaves_in_range(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out,
                                     const LeafSet& only) const {
  collect(lo, hi, out, only);
}

template <class Only>
void LeafRangeQuery::collect(const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out,
                             const Only& only) const {
  out.clear();
  const uint32_t extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1;
  const int level = kMaxLevel - static_cast<int>(std::bit_width(extent - 1));
  const uint32_t edge = octant_edge(level);
  // The (up to 8) level-`level` octants over the box, in Morton order.
  uint64_t keys[8];
  int count = 0;
  for (uint32_t z = lo[2] & ~(edge - 1); z <= hi[2]; z += edge)
    for (uint32_t y = lo[1] & ~(edge - 1); y <= hi[1]; y += edge)
      for (uint32_t x = lo[0] & ~(edge - 1); x <= hi[0]; x += edge) keys[count++] = morton_key(x, y, z);
  for (int k = 1; k < count; ++k)  // insertion sort (at most 8 keys)
    for (int j = k; j > 0 && keys[j - 1] > keys[j]; --j) std::swap(keys[j - 1], keys[j]);
  const size_t n = tree_->size();
  size_t next = n;  // the leaf after the previous octant's run
  size_t last = n;  // the last leaf found inside one octant
  for (int k = 0; k < count; ++k) {
    // The leaf containing the octant's anchor: often the one right after
    // the previous octant's run (consecutive in Morton order).
    const size_t b = next < n && tree_->key[next] == keys[k] ? next : upper_bound(keys[k]) - 1;
    if (tree_->level[b] <= level) {  // the octant lies inside leaf b
      if (last != b && only.contains(b)) out.push_back(b);
      last = b;
      next = b + 1;
      continue;
    }
    // Otherwise the octant is split and its run starts at its anchor: scan
    // short runs, descend long ones.
    const uint64_t end_key = keys[k] + octant_key_span(level);
    size_t e = b;
    while (e < n && e - b <= kScanRun && tree_->key[e] < end_key) ++e;
    if (e < n && tree_->key[e] < end_key) {
      e = upper_bound(end_key - 1);
      uint32_t a[3];
      morton_decode(keys[k], a[0], a[1], a[2]);
      descend(keys[k], a, level, b, e, lo, hi, out, only);
    } else {
      only.for_each(b, e, [&](size_t i) {
        if (overlaps(&anchor_[3 * i], octant_edge(tree_->level[i]), lo, hi)) out.push_back(i);
      });
    }
    next = e;
  }
}

void triangle_grid_range(const RootCube& root, const double* a, const double* b, const double* c, double reach,
                         uint32_t* lo, uint32_t* hi) {
  double blo[3], bhi[3];
  for (int i = 0; i < 3; ++i) {
    blo[i] = std::min({a[i], b[i], c[i]}) - reach;
    bhi[i] = std::max({a[i], b[i], c[i]}) + reach;
  }
  grid_range(root, blo, bhi, lo, hi);
}

void leaves_over_triangle_box(const LeafRangeQuery& query, const RootCube& root, const double* a, const double* b,
                              const double* c, std::vector<size_t>& out) {
  uint32_t glo[3], ghi[3];
  triangle_grid_range(root, a, b, c, 0, glo, ghi);
  query.leaves_in_range(glo, ghi, out);
}

}  // namespace partet
