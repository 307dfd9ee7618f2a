// Triangles per leaf by range query and exact box-triangle test (see
// triangle_bins.hpp).
#include "octree/triangle_bins.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"
#include "octree/box_triangle.hpp"
#include "octree/range_query.hpp"
#include "octree/sizing.hpp"

namespace partet {

std::vector<uint32_t> triangles_in_tree_order(const SurfaceMesh& s, const RootCube& root) {
  const size_t nt = s.num_triangles();
  std::vector<uint64_t> order_key(nt);
  for (size_t t = 0; t < nt; ++t) {
    double lo[3];
    for (int i = 0; i < 3; ++i)
      lo[i] = std::min({s.point(s.tris[3 * t])[i], s.point(s.tris[3 * t + 1])[i], s.point(s.tris[3 * t + 2])[i]});
    uint32_t g[3];
    grid_cell(root, lo, g);
    order_key[t] = morton_key(g[0], g[1], g[2]);
  }
  std::vector<uint32_t> order(nt);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return order_key[a] != order_key[b] ? order_key[a] < order_key[b] : a < b;
  });
  return order;
}

LeafTriangles bin_triangles(const LinearOctree& tree, const SurfaceMesh& s, const RootCube& root) {
  LeafTriangles bins;
  bins.coarsest.assign(s.num_triangles(), kMaxLevel);
  // (leaf, triangle) pairs, then a counting sort by leaf.
  std::vector<uint32_t> pair_leaf, pair_tri;
  std::vector<size_t> leaves;
  LeafRangeQuery query(tree);
  for (uint32_t t : triangles_in_tree_order(s, root)) {
    const uint32_t* v = &s.tris[3 * size_t{t}];
    const double* a = s.point(v[0]);
    const double* b = s.point(v[1]);
    const double* c = s.point(v[2]);
    leaves_over_triangle_box(query, root, a, b, c, leaves);
    const TriangleBoxTest triangle(a, b, c);
    for (size_t leaf : leaves) {
      double blo[3], bhi[3];
      query.leaf_box(root, leaf, blo, bhi);
      if (!triangle.meets(blo, bhi)) continue;
      pair_leaf.push_back(static_cast<uint32_t>(leaf));
      pair_tri.push_back(t);
      bins.coarsest[t] = std::min(bins.coarsest[t], tree.level[leaf]);
    }
  }
  PARTET_ASSERT(tree.size() < UINT32_MAX && pair_tri.size() < UINT32_MAX, "too many leaves or leaf-triangle pairs");
  bins.first.assign(tree.size() + 1, 0);
  for (uint32_t leaf : pair_leaf) ++bins.first[leaf + 1];
  for (size_t i = 0; i < tree.size(); ++i) bins.first[i + 1] += bins.first[i];
  bins.tris.resize(pair_tri.size());
  std::vector<uint32_t> fill(bins.first.begin(), bins.first.end() - 1);
  for (size_t k = 0; k < pair_tri.size(); ++k) bins.tris[fill[pair_leaf[k]]++] = pair_tri[k];
  for (size_t i = 0; i < tree.size(); ++i)
    std::sort(bins.tris.begin() + bins.first[i], bins.tris.begin() + bins.first[i + 1]);
  return bins;
}

}  // namespace partet
