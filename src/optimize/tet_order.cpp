// sort_tets_by_space (see tet_order.hpp).
#include "optimize/tet_order.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "core/keyed_sort.hpp"
#include "octree/box_morton.hpp"

namespace partet {

void sort_tets_by_space(TetMesh& mesh) {
  const size_t nt = mesh.num_tets();
  if (nt < 2) return;
  const BoxMorton grid(mesh.xyz);
  std::vector<KeyedIndex> keyed(nt);
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    double centre[3];
    for (int k = 0; k < 3; ++k)
      centre[k] = 0.25 * (mesh.point(v[0])[k] + mesh.point(v[1])[k] + mesh.point(v[2])[k] + mesh.point(v[3])[k]);
    keyed[t] = {grid.key(centre), static_cast<uint32_t>(t)};
  }
  sort_keyed_in_index_order(keyed);
  std::vector<uint32_t> tets(mesh.tets.size());
  for (size_t t = 0; t < nt; ++t) std::copy_n(&mesh.tets[4 * size_t{keyed[t].second}], 4, &tets[4 * t]);
  mesh.tets = std::move(tets);
}

}  // namespace partet
