// A triangulated surface as flat arrays: what every reader produces and the
// diagnosis checks. Vertex indices are 0-based; triangles are oriented
// (counterclockwise seen from outside once diagnosis has oriented them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet {

struct SurfaceMesh {
  std::vector<double> xyz;     // 3 coordinates per vertex
  std::vector<uint32_t> tris;  // 3 vertex indices per triangle

  size_t num_vertices() const { return xyz.size() / 3; }
  size_t num_triangles() const { return tris.size() / 3; }
  const double* point(size_t v) const { return &xyz[3 * v]; }
};

}  // namespace partet
