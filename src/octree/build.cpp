// Octree construction from (point, level) requests and refinement along the
// surface triangles (see build.hpp).
#include "octree/build.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "octree/box_triangle.hpp"
#include "octree/range_query.hpp"
#include "octree/triangle_bins.hpp"

namespace partet {

namespace {

// Appends to `tree` the leaves of the coarsest subtree rooted at octant
// (key, level) meeting the requests [first, last) (sorted, all inside it),
// with class `cls` and owner `owner`.
void build_subtree(uint64_t key, int level, const RefineRequest* first, const RefineRequest* last, LeafClass cls,
                   int32_t owner, LinearOctree& tree) {
  int need = 0;
  for (const RefineRequest* r = first; r != last; ++r) need = std::max<int>(need, r->level);
  if (need <= level) {
    tree.key.push_back(key);
    tree.level.push_back(static_cast<uint8_t>(level));
    tree.cls.push_back(cls);
    tree.owner.push_back(owner);
    return;
  }
  const uint64_t span = octant_key_span(level + 1);
  const auto key_less = [](const RefineRequest& r, uint64_t k) { return r.key < k; };
  const RefineRequest* begin = first;
  for (uint64_t c = 0; c < 8; ++c) {
    const uint64_t ck = key + c * span;
    const RefineRequest* end = c == 7 ? last : std::lower_bound(begin, last, ck + span, key_less);
    build_subtree(ck, level + 1, begin, end, cls, owner, tree);
    begin = end;
  }
}

}  // namespace

void refine_octree(LinearOctree& tree, std::vector<RefineRequest> requests) {
  if (requests.empty()) return;
  const auto by_key = [](const RefineRequest& a, const RefineRequest& b) { return a.key < b.key; };
  if (!std::is_sorted(requests.begin(), requests.end(), by_key))
    std::sort(requests.begin(), requests.end(), by_key);
  for (const RefineRequest& r : requests)
    PARTET_ASSERT(r.level <= kMaxLevel && r.key < octant_key_span(0), "refinement request outside the grid");
  LinearOctree out;
  out.key.reserve(tree.size());
  out.level.reserve(tree.size());
  out.cls.reserve(tree.size());
  out.owner.reserve(tree.size());
  size_t j = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    const uint64_t end_key = tree.key[i] + octant_key_span(tree.level[i]);
    size_t k = j;
    uint8_t need = 0;
    while (k < requests.size() && requests[k].key < end_key) need = std::max(need, requests[k++].level);
    if (need > tree.level[i]) {
      build_subtree(tree.key[i], tree.level[i], requests.data() + j, requests.data() + k, tree.cls[i],
                    tree.owner[i], out);
    } else {
      out.key.push_back(tree.key[i]);
      out.level.push_back(tree.level[i]);
      out.cls.push_back(tree.cls[i]);
      out.owner.push_back(tree.owner[i]);
    }
    j = k;
  }
  tree = std::move(out);
}

LinearOctree build_octree(const std::vector<uint32_t>& grid, const std::vector<uint8_t>& level) {
  PARTET_ASSERT(grid.size() == 3 * level.size(), "3 grid coordinates per point");
  LinearOctree tree;
  tree.key = {0};
  tree.level = {0};
  tree.cls = {LeafClass::kUnclassified};
  tree.owner = {0};
  std::vector<RefineRequest> requests(level.size());
  for (size_t p = 0; p < level.size(); ++p) {
    PARTET_ASSERT(grid[3 * p] < kGridSize && grid[3 * p + 1] < kGridSize && grid[3 * p + 2] < kGridSize,
                  "point outside the grid");
    requests[p] = {morton_key(grid[3 * p], grid[3 * p + 1], grid[3 * p + 2]), level[p]};
  }
  refine_octree(tree, std::move(requests));
  return tree;
}

namespace {

// Both forms of refine_for_triangles; `owner` < 0 refines every leaf.
void refine_along_triangles(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                            const std::vector<uint8_t>& vertex_level, int32_t owner) {
  std::vector<RefineRequest> requests;
  std::vector<size_t> leaves;
  LeafRangeQuery query(tree);
  struct Pending {
    uint32_t x, y, z;
    int level;
  };
  std::vector<Pending> stack;
  for (uint32_t t : triangles_in_tree_order(s, root)) {
    const uint32_t* v = &s.tris[3 * size_t{t}];
    const double* a = s.point(v[0]);
    const double* b = s.point(v[1]);
    const double* c = s.point(v[2]);
    const int want = std::min({vertex_level[v[0]], vertex_level[v[1]], vertex_level[v[2]]});
    leaves_over_triangle_box(query, root, a, b, c, leaves);
    const TriangleBoxTest triangle(a, b, c);
    for (size_t leaf : leaves) {
      if (tree.level[leaf] >= want || (owner >= 0 && tree.owner[leaf] != owner)) continue;
      uint32_t x, y, z;
      tree.anchor(leaf, x, y, z);
      stack.push_back({x, y, z, tree.level[leaf]});
      while (!stack.empty()) {
        const Pending o = stack.back();
        stack.pop_back();
        double blo[3], bhi[3];
        octant_box(root, o.x, o.y, o.z, o.level, blo, bhi);
        if (!triangle.meets(blo, bhi)) continue;
        if (o.level == want) {
          requests.push_back({morton_key(o.x, o.y, o.z), static_cast<uint8_t>(want)});
          continue;
        }
        const uint32_t h = octant_edge(o.level + 1);
        for (uint32_t k = 0; k < 8; ++k)
          stack.push_back({o.x + ((k & 1) ? h : 0), o.y + ((k & 2) ? h : 0), o.z + ((k & 4) ? h : 0), o.level + 1});
      }
    }
  }
  refine_octree(tree, std::move(requests));
}

}  // namespace

void refine_for_triangles(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                          const std::vector<uint8_t>& vertex_level) {
  refine_along_triangles(tree, s, root, vertex_level, -1);
}

void refine_for_triangles(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                          const std::vector<uint8_t>& vertex_level, int32_t owner) {
  PARTET_ASSERT(owner >= 0, "owner must be a rank");
  refine_along_triangles(tree, s, root, vertex_level, owner);
}

}  // namespace partet
