// find_self_intersections: a bounding-volume hierarchy over the triangles'
// boxes, traversed against itself so that each pair of triangles whose
// boxes overlap is tested exactly once.
//
// Why a hierarchy and not a uniform grid: it adapts to any mix of triangle
// sizes (a few huge faces next to millions of tiny ones cost a grid either
// many cells per triangle or many triangles per cell), with no size
// parameter to tune. Build: object-median splits along the longest axis of
// the box centres, leaves of at most kLeafSize triangles; the total order
// on (centre, index) makes the tree, the traversal and so the result
// deterministic. Boxes only prune (closed boxes of the exact coordinates);
// every decision comes from the exact surface_triangles_conflict.
#include "surface/self_intersections.hpp"

#include <algorithm>
#include <utility>

#include "core/intersections.hpp"

namespace partet {
namespace {

constexpr uint32_t kLeafSize = 4;
constexpr uint32_t kNoChild = 0;  // the root is never a child

// Closed boxes stored as (min x, min y, min z, max x, max y, max z).
bool boxes_overlap(const double* a, const double* b) {
  return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] && b[2] <= a[5];
}

void merge_box(double* into, const double* box) {
  for (int k = 0; k < 3; ++k) {
    into[k] = std::min(into[k], box[k]);
    into[k + 3] = std::max(into[k + 3], box[k + 3]);
  }
}

// A triangle while the tree is built: its box centre and its index.
struct Item {
  double centre[3];
  uint32_t tri;
};

class SelfIntersectionSearch {
 public:
  SelfIntersectionSearch(const SurfaceMesh& surface, size_t limit) : surface_(surface), limit_(limit) {}

  std::vector<TrianglePair> run() {
    if (surface_.num_triangles() < 2 || limit_ == 0) return {};
    build_tree();
    traverse();
    std::sort(found_.begin(), found_.end(), [](const TrianglePair& x, const TrianglePair& y) {
      return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    if (found_.size() > limit_) found_.resize(limit_);
    return std::move(found_);
  }

 private:
  // Box of triangle t as (min xyz, max xyz).
  void triangle_box(uint32_t t, double* box) const {
    const uint32_t* v = &surface_.tris[3 * size_t{t}];
    const double* p[3] = {surface_.point(v[0]), surface_.point(v[1]), surface_.point(v[2])};
    for (int k = 0; k < 3; ++k) {
      box[k] = std::min({p[0][k], p[1][k], p[2][k]});
      box[k + 3] = std::max({p[0][k], p[1][k], p[2][k]});
    }
  }

  // Object-median splits, iteratively; children of a node are consecutive.
  // The items move as whole records, so each split scans contiguous memory.
  void build_tree() {
    const uint32_t n = static_cast<uint32_t>(surface_.num_triangles());
    std::vector<Item> items(n);
    for (uint32_t t = 0; t < n; ++t) {
      double box[6];
      triangle_box(t, box);
      for (int k = 0; k < 3; ++k) items[t].centre[k] = 0.5 * box[k] + 0.5 * box[k + 3];
      items[t].tri = t;
    }
    node_first_.assign(1, 0);
    node_size_.assign(1, n);
    node_child_.assign(1, kNoChild);
    std::vector<uint32_t> stack = {0};
    while (!stack.empty()) {
      const uint32_t node = stack.back();
      stack.pop_back();
      const uint32_t first = node_first_[node];
      const uint32_t size = node_size_[node];
      if (size <= kLeafSize) continue;
      const int axis = widest_centre_axis(&items[first], size);
      const uint32_t half = size / 2;
      std::nth_element(items.begin() + first, items.begin() + first + half, items.begin() + first + size,
                       [axis](const Item& x, const Item& y) {
                         if (x.centre[axis] != y.centre[axis]) return x.centre[axis] < y.centre[axis];
                         return x.tri < y.tri;
                       });
      const uint32_t left = static_cast<uint32_t>(node_first_.size());
      node_child_[node] = left;
      node_first_.insert(node_first_.end(), {first, first + half});
      node_size_.insert(node_size_.end(), {half, size - half});
      node_child_.insert(node_child_.end(), {kNoChild, kNoChild});
      stack.push_back(left + 1);
      stack.push_back(left);
    }
    // Triangles in leaf order, then node boxes bottom-up (children were
    // created after their parents).
    order_.resize(n);
    sorted_box_.resize(6 * size_t{n});
    for (uint32_t i = 0; i < n; ++i) {
      order_[i] = items[i].tri;
      triangle_box(order_[i], &sorted_box_[6 * size_t{i}]);
    }
    const size_t nodes = node_first_.size();
    node_box_.resize(6 * nodes);
    for (size_t node = nodes; node-- > 0;) {
      double* box = &node_box_[6 * node];
      if (is_leaf(static_cast<uint32_t>(node))) {
        const double* leaf = &sorted_box_[6 * size_t{node_first_[node]}];
        std::copy_n(leaf, 6, box);
        for (uint32_t i = 1; i < node_size_[node]; ++i) merge_box(box, leaf + 6 * size_t{i});
      } else {
        const uint32_t left = node_child_[node];
        std::copy_n(&node_box_[6 * size_t{left}], 6, box);
        merge_box(box, &node_box_[6 * size_t{left + 1}]);
      }
    }
  }

  static int widest_centre_axis(const Item* items, uint32_t size) {
    double lo[3];
    double hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = items[0].centre[k];
    for (uint32_t i = 1; i < size; ++i) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], items[i].centre[k]);
        hi[k] = std::max(hi[k], items[i].centre[k]);
      }
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    return axis;
  }

  bool is_leaf(uint32_t node) const { return node_child_[node] == kNoChild; }

  // Node pairs (x, y) whose subtrees may hold overlapping triangles; (x, x)
  // stands for the pairs inside x.
  void traverse() {
    std::vector<std::pair<uint32_t, uint32_t>> stack = {{0, 0}};
    while (!stack.empty() && found_.size() < limit_) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      if (x == y) {
        if (is_leaf(x)) {
          test_within_leaf(x);
        } else {
          const uint32_t left = node_child_[x];
          stack.push_back({left, left + 1});
          stack.push_back({left + 1, left + 1});
          stack.push_back({left, left});
        }
        continue;
      }
      if (!boxes_overlap(&node_box_[6 * size_t{x}], &node_box_[6 * size_t{y}])) continue;
      if (is_leaf(x) && is_leaf(y)) {
        test_leaves(x, y);
      } else if (is_leaf(y) || (!is_leaf(x) && node_size_[x] >= node_size_[y])) {
        const uint32_t left = node_child_[x];
        stack.push_back({left + 1, y});
        stack.push_back({left, y});
      } else {
        const uint32_t left = node_child_[y];
        stack.push_back({x, left + 1});
        stack.push_back({x, left});
      }
    }
  }

  void test_within_leaf(uint32_t node) {
    const uint32_t first = node_first_[node];
    const uint32_t end = first + node_size_[node];
    for (uint32_t i = first; i < end; ++i)
      for (uint32_t j = i + 1; j < end; ++j) test_positions(i, j);
  }

  void test_leaves(uint32_t x, uint32_t y) {
    const uint32_t x_end = node_first_[x] + node_size_[x];
    const uint32_t y_end = node_first_[y] + node_size_[y];
    for (uint32_t i = node_first_[x]; i < x_end; ++i)
      for (uint32_t j = node_first_[y]; j < y_end; ++j) test_positions(i, j);
  }

  // Triangles at leaf-order positions i and j.
  void test_positions(uint32_t i, uint32_t j) {
    if (found_.size() >= limit_) return;
    if (!boxes_overlap(&sorted_box_[6 * size_t{i}], &sorted_box_[6 * size_t{j}])) return;
    const uint32_t s = order_[i];
    const uint32_t t = order_[j];
    const uint32_t* is = &surface_.tris[3 * size_t{s}];
    const uint32_t* it = &surface_.tris[3 * size_t{t}];
    const double* ps[3] = {surface_.point(is[0]), surface_.point(is[1]), surface_.point(is[2])};
    const double* pt[3] = {surface_.point(it[0]), surface_.point(it[1]), surface_.point(it[2])};
    if (surface_triangles_conflict(ps, is, pt, it)) found_.push_back({std::min(s, t), std::max(s, t)});
  }

  const SurfaceMesh& surface_;
  const size_t limit_;
  std::vector<uint32_t> order_;       // triangles in leaf order
  std::vector<double> sorted_box_;    // 6 per leaf-order position
  std::vector<uint32_t> node_first_;  // first leaf-order position of each node
  std::vector<uint32_t> node_size_;   // triangles under each node
  std::vector<uint32_t> node_child_;  // left child (right = left + 1), kNoChild for leaves
  std::vector<double> node_box_;      // 6 per node
  std::vector<TrianglePair> found_;
};

}  // namespace

std::vector<TrianglePair> find_self_intersections(const SurfaceMesh& surface, size_t limit) {
  return SelfIntersectionSearch(surface, limit).run();
}

}  // namespace partet
