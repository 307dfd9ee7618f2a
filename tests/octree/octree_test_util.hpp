// Helpers shared by the octree tests: random complete trees, leaf boxes in
// grid units, brute-force adjacency, and surfaces assembled from boxes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "octree/build.hpp"
#include "octree/octree.hpp"
#include "surface/diagnose.hpp"
#include "surface/surface_mesh.hpp"
#include "test_support.hpp"

namespace partet::test {

// The complete tree build_octree makes for `points` uniformly random grid
// points with random levels in [1, max_level].
inline LinearOctree random_tree(uint32_t seed, size_t points, int max_level) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> coord(0, kGridSize - 1);
  std::uniform_int_distribution<int> level(1, max_level);
  std::vector<uint32_t> grid;
  std::vector<uint8_t> levels;
  for (size_t p = 0; p < points; ++p) {
    for (int i = 0; i < 3; ++i) grid.push_back(coord(rng));
    levels.push_back(static_cast<uint8_t>(level(rng)));
  }
  return build_octree(grid, levels);
}

// Leaf i as grid box [lo, lo + edge) on each axis (64-bit to avoid overflow).
struct GridBox {
  int64_t lo[3];
  int64_t edge;
};

inline GridBox grid_box(const LinearOctree& t, size_t i) {
  uint32_t a[3];
  t.anchor(i, a[0], a[1], a[2]);
  return {{a[0], a[1], a[2]}, octant_edge(t.level[i])};
}

// Dimension of the intersection of the closed boxes of two leaves of a
// tiling (-1: disjoint, 0: corner, 1: edge segment, 2: face patch).
inline int contact_dimension(const GridBox& a, const GridBox& b) {
  int dim = 0;
  for (int i = 0; i < 3; ++i) {
    const int64_t lo = std::max(a.lo[i], b.lo[i]);
    const int64_t hi = std::min(a.lo[i] + a.edge, b.lo[i] + b.edge);
    if (lo > hi) return -1;
    if (lo < hi) ++dim;
  }
  return dim;
}

// Appends surface `b` to `a` as separate shells (vertices renumbered).
inline void append_surface(SurfaceMesh& a, const SurfaceMesh& b) {
  const uint32_t base = static_cast<uint32_t>(a.num_vertices());
  a.xyz.insert(a.xyz.end(), b.xyz.begin(), b.xyz.end());
  for (uint32_t v : b.tris) a.tris.push_back(v + base);
}

// The closed surface of the cube [x, x + size] x [y, y + size] x
// [z, z + size], each face an n x n grid of squares split into two
// triangles, outward.
inline SurfaceMesh placed_box(double x, double y, double z, double size, int n = 1) {
  SurfaceMesh s;
  auto vertex = [&](double px, double py, double pz) {
    s.xyz.insert(s.xyz.end(), {x + px * size, y + py * size, z + pz * size});
    return static_cast<uint32_t>(s.num_vertices() - 1);
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<uint32_t> id((n + 1) * (n + 1));
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          double p[3];
          p[axis] = side;
          p[u] = static_cast<double>(i) / n;
          p[v] = static_cast<double>(j) / n;
          id[j * (n + 1) + i] = vertex(p[0], p[1], p[2]);
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const uint32_t a = id[j * (n + 1) + i], b = id[j * (n + 1) + i + 1];
          const uint32_t c = id[(j + 1) * (n + 1) + i + 1], d = id[(j + 1) * (n + 1) + i];
          // (u, v, axis) is right-handed: counterclockwise in (u, v) faces +axis.
          if (side == 1)
            s.tris.insert(s.tris.end(), {a, b, c, a, c, d});
          else
            s.tris.insert(s.tris.end(), {a, c, b, a, d, c});
        }
    }
  }
  // Merge duplicate vertices along the cube's edges.
  std::vector<uint32_t> remap(s.num_vertices());
  SurfaceMesh merged;
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    size_t found = merged.num_vertices();
    for (size_t w = 0; w < merged.num_vertices(); ++w)
      if (merged.xyz[3 * w] == s.xyz[3 * v] && merged.xyz[3 * w + 1] == s.xyz[3 * v + 1] &&
          merged.xyz[3 * w + 2] == s.xyz[3 * v + 2]) {
        found = w;
        break;
      }
    if (found == merged.num_vertices()) merged.xyz.insert(merged.xyz.end(), s.xyz.begin() + 3 * v, s.xyz.begin() + 3 * v + 3);
    remap[v] = static_cast<uint32_t>(found);
  }
  for (uint32_t v : s.tris) merged.tris.push_back(remap[v]);
  return merged;
}

// A random box of grid cells [lo, hi] (inclusive) for range queries: from
// a few cells to most of the root; with `aligned`, its low corner on the
// lattice of level-4 octants (boxes starting at octant boundaries).
inline void random_grid_box(std::mt19937& rng, bool aligned, uint32_t* lo, uint32_t* hi) {
  const int scale = std::uniform_int_distribution<int>(0, 20)(rng);
  std::uniform_int_distribution<uint32_t> coord(0, kGridSize - 1);
  std::uniform_int_distribution<uint32_t> extent(0, (1u << scale) - 1);
  for (int i = 0; i < 3; ++i) {
    lo[i] = coord(rng);
    if (aligned) lo[i] &= ~(octant_edge(4) - 1);
    hi[i] = std::min<uint32_t>(kGridSize - 1, lo[i] + extent(rng));
  }
}

}  // namespace partet::test
