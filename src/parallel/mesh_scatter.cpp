// partition_tets, scatter_parts and distribute_mesh (see mesh_scatter.hpp).
#include "parallel/mesh_scatter.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "parallel/write_parts.hpp"
#include "partition/recursive_bisection.hpp"

namespace partet {

std::vector<int32_t> partition_tets(const Comm& comm, const TetMesh& mesh) {
  std::vector<double> centroids;
  centroids.reserve(3 * mesh.num_tets());
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    for (int k = 0; k < 3; ++k) {
      double sum = 0;
      for (int i = 0; i < 4; ++i) sum += mesh.point(mesh.tets[4 * t + static_cast<size_t>(i)])[k];
      centroids.push_back(0.25 * sum);
    }
  const std::vector<double> weight(mesh.num_tets(), 1.0);
  // One rank often holds every tet: the others sleep meanwhile.
  comm.idle_barrier();
  return partition_points(comm, centroids.data(), weight.data(), mesh.num_tets(), BisectionMethod::kRib)
      .destination;
}

MeshPart scatter_parts(const Comm& comm, const std::vector<MeshPart>& parts) {
  std::vector<char> send;
  std::vector<int64_t> send_bytes(static_cast<size_t>(comm.size()), 0);
  for (size_t r = 0; r < parts.size(); ++r) {
    const std::string bytes = serialize_part(parts[r].mesh);
    send.insert(send.end(), bytes.begin(), bytes.end());
    send.insert(send.end(), parts[r].on_cut.begin(), parts[r].on_cut.end());
    send_bytes[r] = static_cast<int64_t>(bytes.size() + parts[r].on_cut.size());
  }
  std::vector<int64_t> recv_bytes;
  comm.idle_barrier();  // the ranks with no part to send sleep while rank 0 writes them
  const std::vector<char> recv = comm.all_to_all(send, send_bytes, recv_bytes);
  MeshPart own;
  own.mesh = deserialize_part(std::string(recv.begin(), recv.end()));
  const size_t flags = own.mesh.num_vertices();
  PARTET_ASSERT(recv.size() >= flags, "truncated part");
  own.on_cut.assign(recv.end() - static_cast<ptrdiff_t>(flags), recv.end());
  return own;
}

TetMesh distribute_mesh(const Comm& comm, const TetMesh& whole) {
  PARTET_ASSERT(whole.global_ids.empty(), "distribute_mesh: a whole mesh has no global ids");
  const std::vector<int32_t> part_of_tet = partition_tets(comm, whole);
  std::vector<MeshPart> parts;
  if (comm.rank() == 0) {
    parts = split_mesh(whole, part_of_tet, comm.size());
    // Each boundary triangle goes with the tet it is a face of.
    struct TripleHash {
      size_t operator()(const std::array<uint32_t, 3>& t) const {
        return static_cast<size_t>(hash_triple(t[0], t[1], t[2]));
      }
    };
    std::unordered_map<std::array<uint32_t, 3>, uint32_t, TripleHash> triangle;
    for (uint32_t i = 0; i < whole.num_triangles(); ++i) {
      std::array<uint32_t, 3> t = {whole.tris[3 * i], whole.tris[3 * i + 1], whole.tris[3 * i + 2]};
      std::sort(t.begin(), t.end());
      triangle.emplace(t, i);
    }
    std::vector<std::vector<uint32_t>> local(parts.size());
    for (size_t p = 0; p < parts.size(); ++p) {
      local[p].assign(whole.num_vertices(), ~uint32_t{0});
      for (uint32_t i = 0; i < parts[p].whole.size(); ++i) local[p][parts[p].whole[i]] = i;
      parts[p].mesh.global_ids.assign(parts[p].whole.begin(), parts[p].whole.end());
    }
    // Only faces whose three vertices are on the surface are looked up.
    std::vector<uint8_t> on_surface(whole.num_vertices(), 0);
    for (uint32_t v : whole.tris) on_surface[v] = 1;
    for (size_t t = 0; t < whole.num_tets() && !triangle.empty(); ++t)
      for (int skip = 0; skip < 4; ++skip) {
        std::array<uint32_t, 3> f;
        for (int i = 0, k = 0; i < 4; ++i)
          if (i != skip) f[static_cast<size_t>(k++)] = whole.tets[4 * t + static_cast<size_t>(i)];
        if (!on_surface[f[0]] || !on_surface[f[1]] || !on_surface[f[2]]) continue;
        std::sort(f.begin(), f.end());
        const auto it = triangle.find(f);
        if (it == triangle.end()) continue;
        const size_t p = static_cast<size_t>(part_of_tet[t]);
        for (int k = 0; k < 3; ++k) parts[p].mesh.tris.push_back(local[p][whole.tris[3 * size_t{it->second} + k]]);
      }
  }
  return scatter_parts(comm, parts).mesh;
}

}  // namespace partet
