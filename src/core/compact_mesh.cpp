// Renumbering a TetMesh without its unused vertices (see compact_mesh.hpp).
#include "core/compact_mesh.hpp"

#include <cstdint>
#include <vector>

#include "core/error.hpp"

namespace partet {

size_t drop_unused_vertices(TetMesh& mesh) {
  const size_t n = mesh.num_vertices();
  std::vector<uint32_t> index(n, UINT32_MAX);
  for (uint32_t v : mesh.tets) index[v] = 0;
  uint32_t kept = 0;
  for (size_t v = 0; v < n; ++v) {
    if (index[v] == UINT32_MAX) continue;
    index[v] = kept;
    for (int k = 0; k < 3; ++k) mesh.xyz[3 * size_t{kept} + k] = mesh.xyz[3 * v + k];
    if (!mesh.global_ids.empty()) mesh.global_ids[kept] = mesh.global_ids[v];
    ++kept;
  }
  if (kept == n) return 0;
  mesh.xyz.resize(3 * size_t{kept});
  if (!mesh.global_ids.empty()) mesh.global_ids.resize(kept);
  for (uint32_t& v : mesh.tets) v = index[v];
  for (uint32_t& v : mesh.tris) {
    PARTET_ASSERT(index[v] != UINT32_MAX, "a boundary triangle uses a vertex no tet uses");
    v = index[v];
  }
  return n - kept;
}

}  // namespace partet
