// Migration of front faces with the vertices they use: each face travels as
// (key of its leaf, 3 vertex global ids), each vertex once per destination
// as (global id, coordinates).
//
// Contract: collective over `comm`. Face f of `out` goes to rank
// destination[f]; every vertex it uses goes along unless the destination
// already gets it from this rank. The result holds the faces received, in
// source rank order then source order, and the vertices they use, once
// each (vertices from several sources must agree: same id, same
// coordinates), ascending by global id. Bytes are counted for records that
// leave their rank (a rank's records to itself are not migrated).
// Deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

// Faces with their vertices, on one rank.
struct FaceBatch {
  std::vector<uint64_t> leaf_key;    // per face: the Morton key of the leaf it belongs to
  std::vector<uint32_t> faces;       // 3 vertex indices per face
  std::vector<uint64_t> global_ids;  // per vertex
  std::vector<double> xyz;           // 3 per vertex

  size_t num_faces() const { return leaf_key.size(); }
};

struct MigrationBytes {
  int64_t sent = 0;      // bytes this rank sent to other ranks
  int64_t received = 0;  // bytes this rank received from other ranks
};

// Collective: see the file comment. `bytes`, when given, gets the counts
// added.
FaceBatch migrate_faces(const Comm& comm, const FaceBatch& out, const std::vector<int32_t>& destination,
                        MigrationBytes* bytes = nullptr);

// The bytes of `records` (record_bytes each) that go to or come from
// another rank than `rank`, given each record's destination or source.
int64_t bytes_off_rank(const std::vector<int32_t>& ranks, int rank, size_t record_bytes);

}  // namespace partet
