// partition_tets and scatter_parts (see mesh_scatter.hpp).
#include "parallel/mesh_scatter.hpp"

#include <string>
#include <utility>

#include "core/error.hpp"
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

MeshPart scatter_parts(const Comm& comm, std::vector<MeshPart>& parts) {
  std::vector<char> send;
  std::vector<int64_t> send_bytes(static_cast<size_t>(comm.size()), 0);
  for (size_t r = 1; r < parts.size(); ++r) {
    const std::string bytes = serialize_part(parts[r].mesh);
    send.insert(send.end(), bytes.begin(), bytes.end());
    send.insert(send.end(), parts[r].on_cut.begin(), parts[r].on_cut.end());
    send_bytes[r] = static_cast<int64_t>(bytes.size() + parts[r].on_cut.size());
  }
  std::vector<int64_t> recv_bytes;
  comm.idle_barrier();  // the ranks with no part to send sleep while rank 0 writes them
  const std::vector<char> recv = comm.all_to_all(send, send_bytes, recv_bytes);
  MeshPart own;
  if (comm.rank() == 0) {
    if (!parts.empty()) {
      own.mesh = std::move(parts[0].mesh);
      parts[0].mesh = TetMesh{};
      own.on_cut = parts[0].on_cut;
    }
    return own;
  }
  own.mesh = deserialize_part(std::string(recv.begin(), recv.end()));
  const size_t flags = own.mesh.num_vertices();
  PARTET_ASSERT(recv.size() >= flags, "truncated part");
  own.on_cut.assign(recv.end() - static_cast<ptrdiff_t>(flags), recv.end());
  return own;
}

void gather_parts(const Comm& comm, MeshPart& own, std::vector<MeshPart>& parts) {
  const bool root = comm.rank() == 0;
  const std::vector<std::string> images = comm.gather(root ? std::string() : serialize_part(own.mesh), 0);
  if (!root) return;
  PARTET_ASSERT(images.size() == parts.size(), "one part per rank");
  parts[0].mesh = std::move(own.mesh);
  own.mesh = TetMesh{};
  for (size_t r = 1; r < parts.size(); ++r) parts[r].mesh = deserialize_part(images[r]);
}

}  // namespace partet
