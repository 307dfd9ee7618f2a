// split_mesh, join_parts and cut_band (see mesh_parts.hpp).
#include "optimize/mesh_parts.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace partet {

namespace {

constexpr uint32_t kUnset = ~uint32_t{0};
constexpr int32_t kNoPart = -2;  // no tet seen yet (-1: a tet in no part)

}  // namespace

std::vector<MeshPart> split_mesh(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet, int parts) {
  PARTET_ASSERT(part_of_tet.size() == mesh.num_tets(), "split_mesh: one part per tet");
  std::vector<MeshPart> out(static_cast<size_t>(std::max(parts, 0)));
  // A vertex is on a cut when tets of two parts use it, or a tet of a part
  // and one in none.
  std::vector<uint8_t> cut(mesh.num_vertices(), 0);
  {
    std::vector<int32_t> first(mesh.num_vertices(), kNoPart);
    for (size_t t = 0; t < mesh.num_tets(); ++t) {
      const int32_t p = part_of_tet[t] < 0 ? -1 : part_of_tet[t];
      for (int i = 0; i < 4; ++i) {
        const uint32_t v = mesh.tets[4 * t + static_cast<size_t>(i)];
        if (first[v] == kNoPart)
          first[v] = p;
        else if (first[v] != p)
          cut[v] = 1;
      }
    }
  }
  // Per vertex, its index in the part being built (a stamp per part).
  std::vector<uint32_t> local(mesh.num_vertices(), kUnset);
  std::vector<int32_t> stamp(mesh.num_vertices(), -1);
  for (int p = 0; p < parts; ++p) {
    MeshPart& part = out[static_cast<size_t>(p)];
    for (size_t t = 0; t < mesh.num_tets(); ++t) {
      if (part_of_tet[t] != p) continue;
      for (int i = 0; i < 4; ++i) {
        const uint32_t v = mesh.tets[4 * t + static_cast<size_t>(i)];
        if (stamp[v] != p) {
          stamp[v] = p;
          part.whole.push_back(v);
        }
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
    for (size_t t = 0; t < mesh.num_tets(); ++t)
      if (part_of_tet[t] == p)
        for (int i = 0; i < 4; ++i) part.mesh.tets.push_back(local[mesh.tets[4 * t + static_cast<size_t>(i)]]);
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
  std::vector<int32_t> first_part(mesh.num_vertices(), -1);
  std::vector<uint8_t> cut(mesh.num_vertices(), 0);
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const int32_t p = part_of_tet[t];
    if (p < 0) continue;
    for (int i = 0; i < 4; ++i) {
      const uint32_t v = mesh.tets[4 * t + static_cast<size_t>(i)];
      if (first_part[v] < 0)
        first_part[v] = p;
      else if (first_part[v] != p)
        cut[v] = 1;
    }
  }
  return cut;
}

std::vector<uint8_t> band_around(const TetMesh& mesh, std::vector<uint8_t> marked, int layers) {
  PARTET_ASSERT(marked.size() == mesh.num_vertices(), "band_around: one flag per vertex");
  std::vector<uint8_t> band(mesh.num_tets(), 0);
  for (int layer = 0;; ++layer) {
    for (size_t t = 0; t < mesh.num_tets(); ++t)
      for (int i = 0; i < 4 && !band[t]; ++i) band[t] = marked[mesh.tets[4 * t + static_cast<size_t>(i)]];
    if (layer == layers) break;
    for (size_t t = 0; t < mesh.num_tets(); ++t)
      if (band[t])
        for (int i = 0; i < 4; ++i) marked[mesh.tets[4 * t + static_cast<size_t>(i)]] = 1;
  }
  return band;
}

}  // namespace partet
