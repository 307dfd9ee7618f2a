// Per tet slot or per vertex: the change count (TetTopology::changes) when
// a local search on it last found nothing. A search that reads only what
// `kUnchanged` watches (the stars of a tet's vertices, or one vertex's
// star) would find nothing again while that holds, and is not run: the
// same decisions on the same tets and points.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "optimize/tet_topology.hpp"

namespace partet {

template <bool (TetTopology::*kUnchanged)(uint32_t, uint32_t) const>
class FailureRecord {
 public:
  bool known(const TetTopology& topo, uint32_t i) const {
    return i < at_.size() && at_[i] != 0 && (topo.*kUnchanged)(i, at_[i]);
  }
  void add(const TetTopology& topo, uint32_t i) {
    if (at_.size() <= i) at_.resize(std::max<size_t>(i + 1, 2 * at_.size()), 0);
    at_[i] = topo.changes();
  }

 private:
  std::vector<uint32_t> at_;
};

}  // namespace partet
