// build_edge_table: sort half-edges by undirected key, group, link twins.
#include "surface/edge_table.hpp"

#include <utility>

#include "core/keyed_sort.hpp"

namespace partet {

EdgeTable build_edge_table(const SurfaceMesh& surface) {
  const size_t nh = surface.tris.size();
  std::vector<KeyedIndex> keyed(nh);
  for (uint32_t h = 0; h < nh; ++h) {
    uint64_t a = half_edge_from(surface, h), b = half_edge_to(surface, h);
    if (a > b) std::swap(a, b);
    keyed[h] = {(a << 32) | b, h};
  }
  sort_keyed_in_index_order(keyed);

  EdgeTable table;
  table.half_edges.resize(nh);
  table.twin.assign(nh, EdgeTable::kNone);
  table.edge_start.reserve(nh / 2 + 2);
  for (size_t i = 0; i < nh; ++i) {
    if (i == 0 || keyed[i].first != keyed[i - 1].first) table.edge_start.push_back(static_cast<uint32_t>(i));
    table.half_edges[i] = keyed[i].second;
  }
  table.edge_start.push_back(static_cast<uint32_t>(nh));
  for (size_t e = 0; e + 1 < table.edge_start.size(); ++e) {
    if (table.edge_size(e) != 2) continue;
    uint32_t h0 = table.half_edges[table.edge_start[e]];
    uint32_t h1 = table.half_edges[table.edge_start[e] + 1];
    table.twin[h0] = h1;
    table.twin[h1] = h0;
  }
  return table;
}

}  // namespace partet
