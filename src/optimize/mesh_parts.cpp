// split_mesh, join_parts, cut_vertices, tet_rings and band_around (see
// mesh_parts.hpp).
#include "optimize/mesh_parts.hpp"

#include <algorithm>
#include <utility>

#include "core/error.hpp"

namespace partet {

namespace {

constexpr uint32_t kUnset = ~uint32_t{0};
constexpr int32_t kNoPart = -2;  // no tet seen yet (-1: a tet in no part)

}  // namespace

std::vector<MeshPart> split_mesh(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet, int parts) {
  PARTET_ASSERT(part_of_tet.size() == mesh.num_tets(), "split_mesh: one part per tet");
  std::vector<MeshPart> out(static_cast<size_t>(std::max(parts, 0)));
  const std::vector<uint8_t> cut = cut_vertices(mesh, part_of_tet);
  // The tets of each part, in tet order.
  std::vector<std::vector<uint32_t>> tets_of(out.size());
  for (uint32_t t = 0; t < mesh.num_tets(); ++t)
    if (part_of_tet[t] >= 0 && part_of_tet[t] < parts) tets_of[static_cast<size_t>(part_of_tet[t])].push_back(t);
  // Per vertex, its index in the part being built (a stamp per part).
  std::vector<uint32_t> local(mesh.num_vertices(), kUnset);
  std::vector<int32_t> stamp(mesh.num_vertices(), -1);
  for (size_t p = 0; p < out.size(); ++p) {
    MeshPart& part = out[p];
    for (uint32_t t : tets_of[p])
      for (int i = 0; i < 4; ++i) {
        const uint32_t v = mesh.tets[4 * size_t{t} + static_cast<size_t>(i)];
        if (stamp[v] != static_cast<int32_t>(p)) {
          stamp[v] = static_cast<int32_t>(p);
          part.whole.push_back(v);
        }
      }
    std::sort(part.whole.begin(), part.whole.end());
    part.mesh.xyz.reserve(3 * part.whole.size());
    for (uint32_t i = 0; i < part.whole.size(); ++i) {
      const uint32_t v = part.whole[i];
      local[v] = i;
      part.mesh.xyz.insert(part.mesh.xyz.end(), mesh.point(v), mesh.point(v) + 3);
      part.on_cut.push_back(cut[v]);
    }
    part.mesh.tets.reserve(4 * tets_of[p].size());
    for (uint32_t t : tets_of[p])
      for (int i = 0; i < 4; ++i) part.mesh.tets.push_back(local[mesh.tets[4 * size_t{t} + static_cast<size_t>(i)]]);
  }
  return out;
}

std::vector<int32_t> join_parts(TetMesh& mesh, const std::vector<int32_t>& part_of_tet,
                                const std::vector<MeshPart>& parts) {
  PARTET_ASSERT(part_of_tet.size() == mesh.num_tets(), "join_parts: one part per tet");
  PARTET_ASSERT(mesh.global_ids.empty(), "join_parts: a whole mesh has no global ids");
  std::vector<uint32_t> tets;
  std::vector<int32_t> part_now;
  std::vector<uint32_t> to_whole;
  for (const MeshPart& part : parts) {
    const size_t n = part.mesh.num_vertices();
    PARTET_ASSERT(n >= part.whole.size(), "join_parts: a part lost vertices");
    to_whole.assign(part.whole.begin(), part.whole.end());
    for (size_t i = 0; i < part.whole.size(); ++i)
      std::copy_n(part.mesh.point(i), 3, &mesh.xyz[3 * size_t{part.whole[i]}]);
    for (size_t i = part.whole.size(); i < n; ++i) {
      to_whole.push_back(static_cast<uint32_t>(mesh.num_vertices()));
      mesh.xyz.insert(mesh.xyz.end(), part.mesh.point(i), part.mesh.point(i) + 3);
    }
    for (uint32_t v : part.mesh.tets) tets.push_back(to_whole[v]);
    part_now.resize(tets.size() / 4, static_cast<int32_t>(&part - parts.data()));
  }
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    if (part_of_tet[t] < 0 || static_cast<size_t>(part_of_tet[t]) >= parts.size()) {
      tets.insert(tets.end(), &mesh.tets[4 * t], &mesh.tets[4 * t] + 4);
      part_now.push_back(-1);
    }
  mesh.tets.swap(tets);
  return part_now;
}

std::vector<uint8_t> cut_vertices(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet) {
  PARTET_ASSERT(part_of_tet.size() == mesh.num_tets(), "cut_vertices: one part per tet");
  std::vector<int32_t> first(mesh.num_vertices(), kNoPart);
  std::vector<uint8_t> cut(mesh.num_vertices(), 0);
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const int32_t p = std::max(part_of_tet[t], int32_t{-1});
    for (int i = 0; i < 4; ++i) {
      const uint32_t v = mesh.tets[4 * t + static_cast<size_t>(i)];
      if (first[v] == kNoPart)
        first[v] = p;
      else if (first[v] != p)
        cut[v] = 1;
    }
  }
  return cut;
}

std::vector<int> tet_rings(const TetMesh& mesh, std::vector<uint8_t> marked, int layers) {
  PARTET_ASSERT(marked.size() == mesh.num_vertices(), "tet_rings: one flag per vertex");
  std::vector<int> ring(mesh.num_tets(), -1);
  for (int layer = 0;; ++layer) {
    for (size_t t = 0; t < mesh.num_tets(); ++t)
      for (int i = 0; i < 4 && ring[t] < 0; ++i)
        if (marked[mesh.tets[4 * t + static_cast<size_t>(i)]]) ring[t] = layer;
    if (layer == layers) break;
    for (size_t t = 0; t < mesh.num_tets(); ++t)
      if (ring[t] >= 0)
        for (int i = 0; i < 4; ++i) marked[mesh.tets[4 * t + static_cast<size_t>(i)]] = 1;
  }
  return ring;
}

std::vector<uint8_t> band_around(const TetMesh& mesh, std::vector<uint8_t> marked, int layers) {
  const std::vector<int> ring = tet_rings(mesh, std::move(marked), layers);
  std::vector<uint8_t> band(ring.size());
  for (size_t t = 0; t < ring.size(); ++t) band[t] = ring[t] >= 0;
  return band;
}

}  // namespace partet
