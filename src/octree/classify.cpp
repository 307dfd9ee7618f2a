// Boundary, interior/outside and too-close classification of the leaves
// (see classify.hpp).
#include "octree/classify.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "octree/box_triangle.hpp"
#include "octree/inside_index.hpp"
#include "octree/neighbours.hpp"
#include "octree/range_query.hpp"
#include "octree/triangle_batches.hpp"

namespace partet {

namespace {

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// Interior or outside for every unclassified leaf: groups connected across
// faces (union-find), one exact inside test per group at the centre of its
// first leaf. Each face-adjacent pair is joined from its finer (or either,
// if equal) leaf, which finds the other as the one leaf containing the cell
// just across its face at its anchor. Returns the group count.
size_t fill_groups(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root) {
  const size_t n = tree.size();
  std::vector<uint32_t> parent(n);
  for (size_t i = 0; i < n; ++i) parent[i] = static_cast<uint32_t>(i);
  const LeafRangeQuery query(tree);
  for (size_t i = 0; i < n; ++i) {
    if (tree.cls[i] != LeafClass::kUnclassified) continue;
    uint32_t a[3];
    tree.anchor(i, a[0], a[1], a[2]);
    const uint32_t h = octant_edge(tree.level[i]);
    for (int f = 0; f < kFaceCount; ++f) {
      const int axis = f / 2;
      uint32_t p[3] = {a[0], a[1], a[2]};
      if (f & 1) {
        if (a[axis] + h >= kGridSize) continue;
        p[axis] += h;
      } else {
        if (a[axis] == 0) continue;
        p[axis] -= 1;
      }
      const size_t j = query.locate_near(i, p[0], p[1], p[2]);
      if (tree.cls[j] != LeafClass::kUnclassified || tree.level[j] > tree.level[i]) continue;
      const uint32_t ri = find_root(parent, static_cast<uint32_t>(i));
      const uint32_t rj = find_root(parent, static_cast<uint32_t>(j));
      if (ri < rj) parent[rj] = ri;
      if (rj < ri) parent[ri] = rj;
    }
  }
  const RayParityIndex index(s);
  size_t groups = 0;
  for (size_t i = 0; i < n; ++i) {
    if (tree.cls[i] != LeafClass::kUnclassified) continue;
    const uint32_t r = find_root(parent, static_cast<uint32_t>(i));
    if (r != i) {  // roots are the smallest index of their group: decided
      tree.cls[i] = tree.cls[r];
      continue;
    }
    ++groups;
    uint32_t a[3];
    tree.anchor(i, a[0], a[1], a[2]);
    const uint32_t h = octant_edge(tree.level[i]);
    double centre[3];
    root.lattice_point(2 * a[0] + h, 2 * a[1] + h, 2 * a[2] + h, centre);
    tree.cls[i] = index.inside(centre) ? LeafClass::kInterior : LeafClass::kOutside;
  }
  return groups;
}

// A triangle with its target size, its cap b_t and the grid cells within
// its search reach.
struct NearRegion {
  uint32_t t;
  double size, cap;
  uint32_t lo[3], hi[3];
};

// Marks interior leaves too close to a triangle (see classify.hpp), the
// triangles searched in batches (triangle_batches.hpp).
void mark_too_close(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                    const std::vector<double>& vertex_size, const LeafTriangles& bins, double factor) {
  const auto region_of = [&](uint32_t t) {
    const uint32_t* v = &s.tris[3 * size_t{t}];
    NearRegion r;
    r.t = t;
    r.size = (vertex_size[v[0]] + vertex_size[v[1]] + vertex_size[v[2]]) / 3;
    r.cap = octant_edge(bins.coarsest[t]) * root.unit;
    const double reach = factor * std::max(r.size, r.cap);
    triangle_grid_range(root, s.point(v[0]), s.point(v[1]), s.point(v[2]), reach, r.lo, r.hi);
    return r;
  };
  const LeafRangeQuery query(tree);
  for_each_triangle_batch(triangles_in_tree_order(s, root), query, region_of,
                          [&](const std::vector<NearRegion>& batch, const std::vector<size_t>& leaves) {
    for (size_t leaf : leaves) {
      if (tree.cls[leaf] != LeafClass::kInterior) continue;
      uint32_t a[3];
      tree.anchor(leaf, a[0], a[1], a[2]);
      const uint32_t edge = octant_edge(tree.level[leaf]);
      const double h = edge * root.unit;
      double blo[3], bhi[3];
      query.leaf_box(root, leaf, blo, bhi);
      for (const NearRegion& r : batch) {
        if (!leaf_meets_region(a, edge, r.lo, r.hi)) continue;
        const uint32_t* v = &s.tris[3 * size_t{r.t}];
        const double gap = factor * std::max(r.size, std::min(0.5 * h, r.cap));
        if (box_triangle_closer_than(blo, bhi, s.point(v[0]), s.point(v[1]), s.point(v[2]), gap)) {
          tree.cls[leaf] = LeafClass::kTooClose;
          break;
        }
      }
    }
  });
}

}  // namespace

ClassCounts classify_leaves(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                            const std::vector<double>& vertex_size, const LeafTriangles& bins,
                            const ClassifyOptions& options) {
  PARTET_ASSERT(bins.first.size() == tree.size() + 1, "triangle bins from another tree");
  PARTET_ASSERT(vertex_size.size() == s.num_vertices(), "one target size per surface vertex");
  PARTET_ASSERT(options.too_close >= 0, "too-close factor must not be negative");
  for (size_t i = 0; i < tree.size(); ++i)
    tree.cls[i] = bins.count(i) ? LeafClass::kBoundary : LeafClass::kUnclassified;
  ClassCounts counts;
  counts.groups = fill_groups(tree, s, root);
  if (options.too_close > 0) mark_too_close(tree, s, root, vertex_size, bins, options.too_close);
  for (LeafClass c : tree.cls) {
    counts.boundary += c == LeafClass::kBoundary;
    counts.too_close += c == LeafClass::kTooClose;
    counts.interior += c == LeafClass::kInterior;
    counts.outside += c == LeafClass::kOutside;
  }
  return counts;
}

ClassCounts classify_leaves(LinearOctree& tree, const SurfaceMesh& s, const RootCube& root,
                            const std::vector<double>& vertex_size, const ClassifyOptions& options) {
  return classify_leaves(tree, s, root, vertex_size, bin_triangles(tree, s, root), options);
}

}  // namespace partet
