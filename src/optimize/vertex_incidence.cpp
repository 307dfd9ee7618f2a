// VertexIncidence (see vertex_incidence.hpp): the stars by a counting pass
// over the slots; a vertex's neighbours from its star, marked once and
// sorted, on the first call.
#include "optimize/vertex_incidence.hpp"

#include <algorithm>

namespace partet {

VertexIncidence::VertexIncidence(const TetTopology& topo) : topo_(topo) {
  const size_t n = topo.num_vertices();
  star_first_.assign(n + 1, 0);
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t))
      for (int k = 0; k < 4; ++k) ++star_first_[topo.tet(t)[k] + 1];
  for (size_t v = 0; v < n; ++v) star_first_[v + 1] += star_first_[v];
  stars_.resize(star_first_[n]);
  std::vector<uint32_t> next(star_first_.begin(), star_first_.end() - 1);
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t))
      for (int k = 0; k < 4; ++k) stars_[next[topo.tet(t)[k]]++] = t;
  neighbour_first_.assign(n, kNotYet);
  neighbour_count_.assign(n, 0);
  mark_.assign(n, kNotYet);
}

std::span<const uint32_t> VertexIncidence::neighbours(uint32_t v) {
  if (neighbour_first_[v] == kNotYet) {
    const size_t begin = neighbours_.size();
    for (uint32_t t : star(v))
      for (int k = 0; k < 4; ++k) {
        const uint32_t u = topo_.tet(t)[k];
        if (u == v || mark_[u] == v) continue;
        mark_[u] = v;
        neighbours_.push_back(u);
      }
    std::sort(neighbours_.begin() + static_cast<std::ptrdiff_t>(begin), neighbours_.end());
    neighbour_first_[v] = static_cast<uint32_t>(begin);
    neighbour_count_[v] = static_cast<uint32_t>(neighbours_.size() - begin);
  }
  return {neighbours_.data() + neighbour_first_[v], neighbour_count_[v]};
}

}  // namespace partet
