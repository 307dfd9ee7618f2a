// write_distributed_mesh: pieces plus index, or gather-join-write on rank 0.
#include "parallel/write_parts.hpp"

#include <cstring>

#include "core/error.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_formats.hpp"
#include "parallel/collective_step.hpp"

namespace partet {

namespace {

template <class T>
void put(std::string& out, const std::vector<T>& v) {
  uint64_t n = v.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  if (n > 0) out.append(reinterpret_cast<const char*>(v.data()), n * sizeof(T));
}

template <class T>
void get(const std::string& in, size_t& pos, std::vector<T>& v) {
  uint64_t n = 0;
  PARTET_ASSERT(pos + sizeof n <= in.size(), "truncated part image");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  PARTET_ASSERT(n <= (in.size() - pos) / sizeof(T), "truncated part image");
  v.resize(n);
  if (n > 0) std::memcpy(v.data(), in.data() + pos, n * sizeof(T));
  pos += n * sizeof(T);
}

}  // namespace

std::string serialize_part(const TetMesh& part) {
  std::string out;
  put(out, part.xyz);
  put(out, part.tets);
  put(out, part.tris);
  put(out, part.global_ids);
  return out;
}

TetMesh deserialize_part(const std::string& bytes) {
  TetMesh m;
  size_t pos = 0;
  get(bytes, pos, m.xyz);
  get(bytes, pos, m.tets);
  get(bytes, pos, m.tris);
  get(bytes, pos, m.global_ids);
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
  if (comm.size() == 1) {
    collective_step(comm, [&] { write_volume_file(part, path, options); });
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
