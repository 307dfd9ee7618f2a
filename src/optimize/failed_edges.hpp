// Edges whose removal found nothing, remembered with the change count
// (TetTopology::changes) of the search. An edge removal reads only the
// ring of tets around the edge, all in the stars of its two ends, so while
// neither end's star has changed it would find nothing again. The tets
// around a bad edge are mostly bad too, and each offered the flip search
// the same removal. Kept in a KeyCache: the oldest may be forgotten, and a
// forgotten edge is only searched again.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "optimize/key_cache.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

class FailedEdges {
 public:
  // For about `edges` failures at a time (KeyCache).
  explicit FailedEdges(size_t edges) : failed_(edges) {}
  bool known(const TetTopology& topo, uint32_t a, uint32_t b) const {
    const uint32_t* at = failed_.find(key(a, b));
    return at && topo.vertex_unchanged_since(a, *at) && topo.vertex_unchanged_since(b, *at);
  }
  void add(const TetTopology& topo, uint32_t a, uint32_t b) { failed_.put(key(a, b), topo.changes()); }

 private:
  static uint64_t key(uint32_t a, uint32_t b) { return uint64_t{std::min(a, b)} << 32 | std::max(a, b); }
  KeyCache failed_;
};

}  // namespace partet
