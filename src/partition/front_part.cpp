// FrontPart assembly (sorting faces by leaf and vertex ids, keeping the used
// vertices) and leaf migration with the faces attached.
#include "partition/front_part.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "parallel/migrate.hpp"

namespace partet {
namespace {

struct LeafRecord {
  uint64_t key;
  uint8_t level;
  LeafClass cls;
  uint8_t pad[6];
};

}  // namespace

FrontPart assemble_front_part(LinearOctree leaves, const FaceBatch& batch, int rank) {
  PARTET_ASSERT(std::adjacent_find(leaves.key.begin(), leaves.key.end(), std::greater_equal<>()) ==
                    leaves.key.end(),
                "front part leaves must be sorted and unique");
  FrontPart part;
  part.leaves = std::move(leaves);
  part.leaves.owner.assign(part.leaves.size(), rank);
  const size_t n = batch.num_faces();

  // Each face's leaf and its vertices' global ids, then the order.
  struct Key {
    uint32_t leaf;
    std::array<uint64_t, 3> ids;
  };
  std::vector<Key> keys(n);
  for (size_t f = 0; f < n; ++f) {
    auto at = std::lower_bound(part.leaves.key.begin(), part.leaves.key.end(), batch.leaf_key[f]);
    PARTET_ASSERT(at != part.leaves.key.end() && *at == batch.leaf_key[f],
                  "rank " + std::to_string(rank) + " got a front face of leaf " + std::to_string(batch.leaf_key[f]) +
                      ", which it does not hold");
    keys[f].leaf = static_cast<uint32_t>(at - part.leaves.key.begin());
    for (int k = 0; k < 3; ++k) keys[f].ids[static_cast<size_t>(k)] = batch.global_ids[batch.faces[3 * f + k]];
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return keys[a].leaf != keys[b].leaf ? keys[a].leaf < keys[b].leaf : keys[a].ids < keys[b].ids;
  });

  // The vertices used, ascending by global id (batch vertices are unique).
  std::vector<uint32_t> used;
  used.reserve(batch.faces.size());
  used.assign(batch.faces.begin(), batch.faces.end());
  std::sort(used.begin(), used.end(),
            [&](uint32_t a, uint32_t b) { return batch.global_ids[a] < batch.global_ids[b]; });
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<uint32_t> index(batch.global_ids.size(), UINT32_MAX);
  for (uint32_t v : used) {
    index[v] = static_cast<uint32_t>(part.global_ids.size());
    part.global_ids.push_back(batch.global_ids[v]);
    part.xyz.insert(part.xyz.end(), &batch.xyz[3 * size_t{v}], &batch.xyz[3 * size_t{v}] + 3);
  }

  part.leaf_first_face.assign(part.leaves.size() + 1, 0);
  part.faces.reserve(3 * n);
  for (uint32_t f : order) {
    ++part.leaf_first_face[keys[f].leaf + 1];
    for (int k = 0; k < 3; ++k) part.faces.push_back(index[batch.faces[3 * f + k]]);
  }
  for (size_t i = 0; i < part.leaves.size(); ++i) part.leaf_first_face[i + 1] += part.leaf_first_face[i];
  return part;
}

FrontPart migrate_front_part(const Comm& comm, const FrontPart& part, const std::vector<int32_t>& destination,
                             MigrationBytes* bytes) {
  PARTET_ASSERT(destination.size() == part.leaves.size(), "one destination per leaf expected");
  std::vector<LeafRecord> leaves(part.leaves.size());
  FaceBatch out;
  out.global_ids = part.global_ids;
  out.xyz = part.xyz;
  out.faces = part.faces;
  out.leaf_key.reserve(part.num_faces());
  std::vector<int32_t> face_destination;
  face_destination.reserve(part.num_faces());
  for (size_t i = 0; i < part.leaves.size(); ++i) {
    leaves[i] = LeafRecord{part.leaves.key[i], part.leaves.level[i], part.leaves.cls[i], {}};
    out.leaf_key.insert(out.leaf_key.end(), part.leaf_work(i), part.leaves.key[i]);
    face_destination.insert(face_destination.end(), part.leaf_work(i), destination[i]);
  }
  std::vector<int32_t> sources;
  std::vector<LeafRecord> got = migrate(comm, destination, leaves, 1, &sources);
  if (bytes != nullptr) {
    bytes->sent += bytes_off_rank(destination, comm.rank(), sizeof(LeafRecord));
    bytes->received += bytes_off_rank(sources, comm.rank(), sizeof(LeafRecord));
  }
  const FaceBatch in = migrate_faces(comm, out, face_destination, bytes);

  std::sort(got.begin(), got.end(), [](const LeafRecord& a, const LeafRecord& b) { return a.key < b.key; });
  LinearOctree mine;
  for (const LeafRecord& r : got) {
    mine.key.push_back(r.key);
    mine.level.push_back(r.level);
    mine.cls.push_back(r.cls);
  }
  return assemble_front_part(std::move(mine), in, comm.rank());
}

}  // namespace partet
