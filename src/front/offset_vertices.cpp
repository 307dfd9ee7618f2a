// add_offset_vertices (see offset_vertices.hpp): candidates at the offset
// points that fall in gap leaves; then, vertex by vertex, one range query
// over the tree gives the leaves near a candidate, a template vertex or a
// leaf centre (listed by leaf), a surface triangle (binned by leaf) or an
// offset point kept before too near drops it, and the ray parity test
// keeps those inside.
#include "front/offset_vertices.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/distance.hpp"
#include "octree/inside_index.hpp"
#include "octree/range_query.hpp"
#include "octree/triangle_bins.hpp"

namespace partet {
namespace {

// Items (points) by the leaf holding each, in item order within a leaf.
struct LeafLists {
  std::vector<uint32_t> first, items;

  LeafLists(size_t leaves, const std::vector<uint32_t>& leaf_of) : first(leaves + 1, 0), items(leaf_of.size()) {
    for (uint32_t leaf : leaf_of) ++first[leaf + 1];
    for (size_t i = 0; i < leaves; ++i) first[i + 1] += first[i];
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (uint32_t i = 0; i < leaf_of.size(); ++i) items[next[leaf_of[i]]++] = i;
  }
  template <class Visit>
  void for_each(size_t leaf, Visit visit) const {
    for (uint32_t k = first[leaf]; k < first[leaf + 1]; ++k) visit(items[k]);
  }
};

double squared_distance(const double* a, const double* b) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum;
}

// The area normals summed per vertex (outward: the surface is diagnosed).
std::vector<double> vertex_normals(const SurfaceMesh& surface) {
  std::vector<double> normal(3 * surface.num_vertices(), 0.0);
  for (size_t t = 0; t < surface.num_triangles(); ++t) {
    const uint32_t* v = &surface.tris[3 * t];
    const double *a = surface.point(v[0]), *b = surface.point(v[1]), *c = surface.point(v[2]);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) normal[3 * size_t{v[k]} + i] += n[i];
  }
  return normal;
}

}  // namespace

size_t add_offset_vertices(const LinearOctree& tree, const RootCube& root, const SurfaceMesh& surface,
                           const std::vector<double>& vertex_size, double gap, const InitialFront& front,
                           GapVertices& gap_vertices, const LeafTriangles* bins) {
  if (!(gap > 0)) return 0;
  const std::vector<double> normal = vertex_normals(surface);
  std::vector<double> xyz;  // 3 per candidate
  std::vector<uint32_t> vertex, leaf;
  for (uint32_t v = 0; v < surface.num_vertices(); ++v) {
    const double* n = &normal[3 * size_t{v}];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0)) continue;
    const double step = kOffsetHeight * vertex_size[v] / length;
    double p[3];
    for (int i = 0; i < 3; ++i) p[i] = surface.point(v)[i] - step * n[i];
    const uint32_t in = leaf_of_point(tree, root, p);
    if (tree.cls[in] != LeafClass::kBoundary && tree.cls[in] != LeafClass::kTooClose) continue;
    xyz.insert(xyz.end(), p, p + 3);
    vertex.push_back(v);
    leaf.push_back(in);
  }
  if (vertex.empty()) return 0;
  const auto point = [&](uint32_t c) { return &xyz[3 * size_t{c}]; };

  std::vector<uint8_t> kept(vertex.size(), 0);
  const LeafLists candidates(tree.size(), leaf);
  const LeafRangeQuery query(tree);
  LeafTriangles own_bins;
  if (!bins) {
    own_bins = bin_triangles(tree, surface, root);
    bins = &own_bins;
  }

  // The template vertices and the leaf centres, by leaf.
  const size_t core = front.core_vertices;
  std::vector<uint32_t> lattice_leaf(front.vertex_leaf.begin(), front.vertex_leaf.begin() + core);
  lattice_leaf.insert(lattice_leaf.end(), gap_vertices.leaf.begin(), gap_vertices.leaf.end());
  const LeafLists lattice(tree.size(), lattice_leaf);
  const auto lattice_point = [&](uint32_t i) {
    return i < core ? &front.xyz[3 * size_t{i}] : &gap_vertices.xyz[3 * (size_t{i} - core)];
  };
  // Per candidate, the leaves over the box of its widest ball: then the
  // lattice points (most candidates on smooth bodies stop there), the
  // surface triangles (the boundary leaves list them) and the offset
  // points kept before, each within its own radius.
  const double widest = std::max({kOffsetBlock, gap, kOffsetSpacing});
  std::vector<size_t> near;
  std::optional<RayParityIndex> parity;
  const size_t before = gap_vertices.size();
  for (uint32_t c = 0; c < vertex.size(); ++c) {
    const double* p = point(c);
    const double s = vertex_size[vertex[c]];
    const double lo[3] = {p[0] - widest * s, p[1] - widest * s, p[2] - widest * s};
    const double hi[3] = {p[0] + widest * s, p[1] + widest * s, p[2] + widest * s};
    uint32_t glo[3], ghi[3];
    grid_range(root, lo, hi, glo, ghi);
    query.leaves_in_range(glo, ghi, near);
    const double block = kOffsetBlock * s, clear = gap * s, spacing = kOffsetSpacing * s;
    bool free = true;
    for (size_t l = 0; l < near.size() && free; ++l)
      lattice.for_each(near[l], [&](uint32_t i) { free = free && squared_distance(lattice_point(i), p) >= block * block; });
    for (size_t l = 0; l < near.size() && free; ++l)
      for (uint32_t k = bins->first[near[l]]; k < bins->first[near[l] + 1] && free; ++k) {
        const uint32_t* v = &surface.tris[3 * size_t{bins->tris[k]}];
        const double *a = surface.point(v[0]), *b = surface.point(v[1]), *c = surface.point(v[2]);
        free = TriangleBoxReach(a, b, c, clear).excludes(p) ||
               squared_point_triangle_distance(p, a, b, c) >= clear * clear;
      }
    for (size_t l = 0; l < near.size() && free; ++l)
      candidates.for_each(near[l], [&](uint32_t o) {
        free = free && !(o < c && kept[o] && squared_distance(point(o), p) < spacing * spacing);
      });
    if (!free) continue;
    if (!parity) parity.emplace(surface);
    if (!parity->inside(p)) continue;
    kept[c] = 1;
    gap_vertices.xyz.insert(gap_vertices.xyz.end(), p, p + 3);
    gap_vertices.global_ids.push_back(kOffsetVertexId | vertex[c]);
    gap_vertices.leaf.push_back(leaf[c]);
  }
  return gap_vertices.size() - before;
}

}  // namespace partet
