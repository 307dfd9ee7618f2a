// Links between the copies of a vertex held by several ranks (paper §4.1:
// vertices on rank boundaries are linked by (rank, local index) and carry
// one global id). Found by a rendezvous on the global id: every rank sends
// (global id, local index) to the id's home rank (a hash of the id), the
// home rank groups the copies of each id and tells every holder where the
// others are. Two exchanges, no assumption on which vertices are shared.
//
// Contract: collective over `comm`; `global_ids` are this rank's vertices'
// ids, each at most once on a rank. The result lists, for every local
// vertex, its copies on the other ranks ordered by rank (one per rank).
// Deterministic: it depends only on the ids each rank holds.
#pragma once

#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

struct VertexLinks {
  // Copies of local vertex v elsewhere: entries [first[v], first[v + 1]).
  std::vector<uint32_t> first;
  std::vector<int32_t> rank;
  std::vector<uint32_t> index;  // the copy's local index on that rank

  size_t num_vertices() const { return first.empty() ? 0 : first.size() - 1; }
  // Vertices with at least one copy elsewhere.
  size_t num_shared() const;
};

VertexLinks link_shared_vertices(const Comm& comm, const std::vector<uint64_t>& global_ids);

}  // namespace partet
