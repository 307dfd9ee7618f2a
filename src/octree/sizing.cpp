// Target size per surface vertex, its octree level and grid cell.
#include "octree/sizing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace partet {

std::vector<double> mean_incident_edge_length(const SurfaceMesh& s) {
  const size_t nv = s.num_vertices();
  std::vector<double> sum(nv, 0.0);
  std::vector<uint32_t> count(nv, 0);
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    const uint32_t* v = &s.tris[3 * t];
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = v[k], b = v[(k + 1) % 3];
      const double* p = s.point(a);
      const double* q = s.point(b);
      const double len = std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
                                   (q[2] - p[2]) * (q[2] - p[2]));
      sum[a] += len;
      sum[b] += len;
      ++count[a];
      ++count[b];
    }
  }
  for (size_t v = 0; v < nv; ++v) sum[v] = count[v] ? sum[v] / count[v] : 0.0;
  return sum;
}

int size_to_level(double d, double D, int max_level) {
  max_level = std::clamp(max_level, 1, kMaxLevel);
  if (!(d > 0)) return max_level;
  const double exact = std::log2(D / d);
  if (!(exact < max_level)) return max_level;  // also catches inf
  // floor(x + 0.5): nearest, ties to the finer level.
  const int level = static_cast<int>(std::floor(exact + 0.5));
  return std::clamp(level, 1, max_level);
}

void grid_cell(const RootCube& root, const double* p, uint32_t* g) {
  for (int i = 0; i < 3; ++i) {
    const double c = std::floor((p[i] - root.origin[i]) / root.unit);
    g[i] = c <= 0 ? 0u : (c >= kGridSize - 1 ? kGridSize - 1 : static_cast<uint32_t>(c));
  }
}

VertexSizing size_vertices(const SurfaceMesh& s, const RootCube& root, const SizingOptions& options) {
  if (!(options.size_factor > 0) || !std::isfinite(options.size_factor))
    throw InputError("size factor must be a positive number, got " + std::to_string(options.size_factor));
  if (!(options.max_size > 0))
    throw InputError("maximum size must be positive, got " + std::to_string(options.max_size));
  VertexSizing out;
  out.size = mean_incident_edge_length(s);
  const size_t nv = s.num_vertices();
  out.level.resize(nv);
  out.grid.resize(3 * nv);
  const double D = root.edge();
  for (size_t v = 0; v < nv; ++v) {
    out.size[v] = std::min(out.size[v] * options.size_factor, options.max_size);
    out.level[v] = static_cast<uint8_t>(size_to_level(out.size[v], D, options.max_level));
    grid_cell(root, s.point(v), &out.grid[3 * v]);
  }
  return out;
}

}  // namespace partet
