// The tets around each vertex and its neighbours, gathered once for work
// that moves vertices but changes no tet (the relaxation sweeps). A
// breadth-first search of each star and a sort of its neighbours per call
// cost 6.5 % of a smooth input's run (femur, blobby, elephant, fandisk r1),
// nearly every free vertex being relaxed twice; one pass over the tets
// lists them all.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "optimize/tet_topology.hpp"

namespace partet {

class VertexIncidence {
 public:
  // From the alive tets of `topo`, which must not change while this is
  // used (vertices may move).
  explicit VertexIncidence(const TetTopology& topo);

  // The alive tets having v, in ascending slot order.
  std::span<const uint32_t> star(uint32_t v) const {
    return {stars_.data() + star_first_[v], stars_.data() + star_first_[v + 1]};
  }
  // The vertices sharing a tet with v, ascending, each once.
  std::span<const uint32_t> neighbours(uint32_t v) const {
    return {neighbours_.data() + neighbour_first_[v], neighbours_.data() + neighbour_first_[v + 1]};
  }

 private:
  std::vector<uint32_t> star_first_, stars_;
  std::vector<uint32_t> neighbour_first_, neighbours_;
};

}  // namespace partet
