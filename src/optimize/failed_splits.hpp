// Edge splits that were refused, remembered by what they read: the ring of
// tets around the edge (its two ends, its ring vertices in order, and the
// points of all of them). A split reads nothing else, so the same ring offered
// again would be refused again and is not tried (up to rounding: from another
// tet the ring lists its tets rotated, and the trial's smoothing sums in that
// order; on 5 of the 64 r0 and r1 inputs that decided a trial somewhere, and
// their meshes differ a little). The tets around a wide dihedral angle share
// their widest edge and each offered it the same split, the needles around a
// long edge the same: on handle r1, 30 % of the insertion's edge splits and
// 37 % of the needle splits repeated a refused one (the optimizer 0.79 ->
// 0.67 s, the same mesh). Rings are keyed by a 64-bit hash; a collision
// skips one trial (never a change to the mesh). The refusals are kept in a
// KeyCache, so the oldest may be forgotten. The caller keeps one set per
// acceptance rule and bar: a split refused under one may pay under another.
#pragma once

#include <cstddef>
#include <cstdint>

#include "optimize/key_cache.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

class FailedSplits {
 public:
  // For about `rings` refusals at a time (KeyCache).
  explicit FailedSplits(size_t rings) : refused_(rings) {}
  bool known(const TetTopology& topo, const TetTopology::Ring& ring) const {
    return refused_.find(key(topo, ring)) != nullptr;
  }
  void add(const TetTopology& topo, const TetTopology::Ring& ring) { refused_.put(key(topo, ring), 1); }

 private:
  static uint64_t key(const TetTopology& topo, const TetTopology::Ring& ring);
  KeyCache refused_;
};

}  // namespace partet
