// migrate_faces: faces as (leaf key, global ids) records, vertices as
// (global id, coordinates) records deduplicated per destination, two
// record migrations; the receiver merges the vertices by global id.
#include "parallel/front_migration.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "parallel/migrate.hpp"

namespace partet {
namespace {

struct FaceRecord {
  uint64_t leaf_key;
  uint64_t ids[3];
};

struct VertexRecord {
  uint64_t id;
  double xyz[3];
};

}  // namespace

int64_t bytes_off_rank(const std::vector<int32_t>& ranks, int rank, size_t record_bytes) {
  int64_t n = 0;
  for (int32_t r : ranks) n += r != rank;
  return n * static_cast<int64_t>(record_bytes);
}

FaceBatch migrate_faces(const Comm& comm, const FaceBatch& out, const std::vector<int32_t>& destination,
                        MigrationBytes* bytes) {
  const size_t n = out.num_faces();
  PARTET_ASSERT(destination.size() == n && out.faces.size() == 3 * n, "one destination per face expected");
  PARTET_ASSERT(out.xyz.size() == 3 * out.global_ids.size(), "three coordinates per vertex expected");
  std::vector<FaceRecord> faces(n);
  std::vector<uint64_t> pairs;  // destination << 32 | vertex, one per vertex and destination
  pairs.reserve(3 * n);
  for (size_t f = 0; f < n; ++f) {
    faces[f].leaf_key = out.leaf_key[f];
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = out.faces[3 * f + k];
      PARTET_ASSERT(v < out.global_ids.size(), "face " + std::to_string(f) + " uses a vertex out of range");
      faces[f].ids[k] = out.global_ids[v];
      pairs.push_back(uint64_t{static_cast<uint32_t>(destination[f])} << 32 | v);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<VertexRecord> vertices(pairs.size());
  std::vector<int32_t> vertex_destination(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    const uint32_t v = static_cast<uint32_t>(pairs[i]);
    vertex_destination[i] = static_cast<int32_t>(pairs[i] >> 32);
    vertices[i].id = out.global_ids[v];
    std::copy(&out.xyz[3 * size_t{v}], &out.xyz[3 * size_t{v}] + 3, vertices[i].xyz);
  }

  std::vector<int32_t> face_sources, vertex_sources;
  const std::vector<FaceRecord> got_faces = migrate(comm, destination, faces, 1, &face_sources);
  std::vector<VertexRecord> got_vertices = migrate(comm, vertex_destination, vertices, 1, &vertex_sources);
  if (bytes != nullptr) {
    const int rank = comm.rank();
    bytes->sent += bytes_off_rank(destination, rank, sizeof(FaceRecord)) +
                   bytes_off_rank(vertex_destination, rank, sizeof(VertexRecord));
    bytes->received += bytes_off_rank(face_sources, rank, sizeof(FaceRecord)) +
                       bytes_off_rank(vertex_sources, rank, sizeof(VertexRecord));
  }

  std::stable_sort(got_vertices.begin(), got_vertices.end(),
                   [](const VertexRecord& a, const VertexRecord& b) { return a.id < b.id; });
  FaceBatch in;
  for (size_t i = 0; i < got_vertices.size(); ++i) {
    const VertexRecord& v = got_vertices[i];
    if (!in.global_ids.empty() && in.global_ids.back() == v.id) {
      PARTET_ASSERT(std::equal(v.xyz, v.xyz + 3, in.xyz.end() - 3),
                    "vertex " + std::to_string(v.id) + " arrived with two different positions");
      continue;
    }
    in.global_ids.push_back(v.id);
    in.xyz.insert(in.xyz.end(), v.xyz, v.xyz + 3);
  }
  in.leaf_key.reserve(got_faces.size());
  in.faces.reserve(3 * got_faces.size());
  for (const FaceRecord& f : got_faces) {
    in.leaf_key.push_back(f.leaf_key);
    for (uint64_t id : f.ids) {
      auto at = std::lower_bound(in.global_ids.begin(), in.global_ids.end(), id);
      PARTET_ASSERT(at != in.global_ids.end() && *at == id,
                    "a migrated face arrived without its vertex " + std::to_string(id));
      in.faces.push_back(static_cast<uint32_t>(at - in.global_ids.begin()));
    }
  }
  return in;
}

}  // namespace partet
