// The tets around each vertex and its neighbours, for work that moves
// vertices but changes no tet (the relaxation sweeps). A breadth-first
// search of each star and a sort of its neighbours per call cost 6.5 % of
// a smooth input's run (femur, blobby, elephant, fandisk r1), nearly every
// free vertex being relaxed twice: one pass over the tets lists every
// star, and a vertex's neighbours are gathered from its star the first
// time they are asked for (when the relaxation is about to read that star
// anyway) and kept.
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
  // The vertices sharing a tet with v, ascending, each once (valid until
  // the neighbours of a vertex not asked for before are).
  std::span<const uint32_t> neighbours(uint32_t v);

 private:
  static constexpr uint32_t kNotYet = UINT32_MAX;
  const TetTopology& topo_;
  std::vector<uint32_t> star_first_, stars_;
  std::vector<uint32_t> neighbour_first_, neighbour_count_, neighbours_;  // per vertex, kNotYet until asked
  std::vector<uint32_t> mark_;  // per vertex: the vertex whose neighbours last took it
};

}  // namespace partet
