// The edges of a triangle surface as groups of half-edges. Half-edge
// h = 3*t + k of triangle t runs from tris[3t+k] to tris[3t+(k+1)%3].
// Half-edges are sorted by their undirected edge (then by h), so the table
// is deterministic; a closed manifold surface has exactly two per edge.
#pragma once

#include <cstdint>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace partet {

struct EdgeTable {
  std::vector<uint32_t> half_edges;  // half-edge ids grouped by undirected edge
  std::vector<uint32_t> edge_start;  // edge e owns half_edges[edge_start[e], edge_start[e+1])
  std::vector<uint32_t> twin;        // per half-edge: the other half-edge of a 2-edge, else kNone

  static constexpr uint32_t kNone = UINT32_MAX;

  size_t num_edges() const { return edge_start.empty() ? 0 : edge_start.size() - 1; }
  uint32_t edge_size(size_t e) const { return edge_start[e + 1] - edge_start[e]; }
  uint32_t first_half_edge(size_t e) const { return half_edges[edge_start[e]]; }
};

EdgeTable build_edge_table(const SurfaceMesh& surface);

// Endpoints of half-edge h.
inline uint32_t half_edge_from(const SurfaceMesh& s, uint32_t h) { return s.tris[h]; }
inline uint32_t half_edge_to(const SurfaceMesh& s, uint32_t h) {
  return s.tris[h - h % 3 + (h % 3 + 1) % 3];
}

}  // namespace partet
