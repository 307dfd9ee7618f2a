// Gap vertices (see gap_vertices.hpp): every candidate leaf centre starts
// kept; each surface triangle vetoes the candidates whose centre is nearer
// to it than gap * s_t, among the leaves over its box grown by that
// distance; boundary leaf centres left must pass the ray parity test.
#include "front/gap_vertices.hpp"

#include <algorithm>
#include <optional>

#include "core/distance.hpp"
#include "octree/inside_index.hpp"
#include "octree/range_query.hpp"
#include "octree/triangle_batches.hpp"
#include "octree/triangle_bins.hpp"

namespace partet {

namespace {

// Centre of leaf i: its lattice coordinates (doubled grid) and its point.
void leaf_centre(const LinearOctree& tree, const RootCube& root, size_t i, uint32_t* lattice, double* p) {
  uint32_t a[3];
  tree.anchor(i, a[0], a[1], a[2]);
  const uint32_t edge = octant_edge(tree.level[i]);  // grid units: half the edge in lattice units
  for (int k = 0; k < 3; ++k) lattice[k] = 2 * a[k] + edge;
  root.lattice_point(lattice[0], lattice[1], lattice[2], p);
}

}  // namespace

GapVertices gap_vertices(const LinearOctree& tree, const RootCube& root, const SurfaceMesh& surface,
                         const std::vector<double>& vertex_size, double gap) {
  GapVertices out;
  if (!(gap > 0)) return out;
  const size_t n = tree.size();
  std::vector<uint8_t> kept(n, 0);
  LeafSet candidates(n);  // the range queries list only these
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    kept[i] = tree.cls[i] == LeafClass::kTooClose || tree.cls[i] == LeafClass::kBoundary;
    if (kept[i]) candidates.insert(i);
    any = any || kept[i];
  }
  if (!any) return out;

  // Each triangle vetoes the centres within its reach, searched by batches
  // of triangles (triangle_batches.hpp).
  // A centre farther from a triangle's box than its reach is not vetoed by
  // it (TriangleBoxReach): a cheap test that spares most of the distances.
  struct Reach {
    uint32_t t;
    double reach;
    TriangleBoxReach box;
    uint32_t lo[3], hi[3];
  };
  const auto region_of = [&](uint32_t t) {
    const uint32_t* v = &surface.tris[3 * size_t{t}];
    const double *a = surface.point(v[0]), *b = surface.point(v[1]), *c = surface.point(v[2]);
    const double reach = gap * (vertex_size[v[0]] + vertex_size[v[1]] + vertex_size[v[2]]) / 3;
    Reach r{t, reach, TriangleBoxReach(a, b, c, reach), {}, {}};
    triangle_grid_range(root, a, b, c, reach, r.lo, r.hi);
    return r;
  };
  const LeafRangeQuery query(tree);
  for_each_triangle_batch(triangles_in_tree_order(surface, root), query, region_of,
                          [&](const std::vector<Reach>& batch, const std::vector<size_t>& leaves) {
    for (size_t leaf : leaves) {
      if (!kept[leaf]) continue;
      uint32_t a[3];
      tree.anchor(leaf, a[0], a[1], a[2]);
      const uint32_t edge = octant_edge(tree.level[leaf]);
      uint32_t lattice[3];
      double centre[3];
      leaf_centre(tree, root, leaf, lattice, centre);
      for (const Reach& r : batch) {
        if (!leaf_meets_region(a, edge, r.lo, r.hi) || r.box.excludes(centre)) continue;
        const uint32_t* v = &surface.tris[3 * size_t{r.t}];
        if (squared_point_triangle_distance(centre, surface.point(v[0]), surface.point(v[1]), surface.point(v[2])) <
            r.reach * r.reach) {
          kept[leaf] = 0;
          break;
        }
      }
    }
  }, &candidates);

  std::optional<RayParityIndex> parity;  // built only when a boundary leaf's centre is left
  for (size_t i = 0; i < n; ++i) {
    if (!kept[i]) continue;
    uint32_t lattice[3];
    double centre[3];
    leaf_centre(tree, root, i, lattice, centre);
    // Off the surface (no triangle is nearer than its reach), so the test
    // is defined; too-close leaves are inside by classification.
    if (tree.cls[i] == LeafClass::kBoundary) {
      if (!parity) parity.emplace(surface);
      if (!parity->inside(centre)) continue;
    }
    out.xyz.insert(out.xyz.end(), centre, centre + 3);
    out.global_ids.push_back(morton_key(lattice[0], lattice[1], lattice[2]));
    out.leaf.push_back(static_cast<uint32_t>(i));
  }
  return out;
}

}  // namespace partet
