// The Delaunay fill step (see fill_step.hpp).
#include "pipeline/fill_step.hpp"

#include "front/delaunay_fill.hpp"

namespace partet {

ojson fill_step(InitialFront& front, const LinearOctree& tree, TetMesh& core) {
  const DelaunayFillCounts n = delaunay_fill(front, tree, core);
  ojson c;
  c["delaunay tets"] = n.delaunay_tets;
  c["recovered edges"] = n.recovered_edges;
  c["recovered faces"] = n.recovered_faces;
  c["missing triangles"] = n.missing_triangles;
  c["removed tets"] = n.removed_tets;
  c["kept tets"] = n.kept_tets;
  c["dropped components"] = n.dropped_components;
  c["front faces"] = front.num_faces();
  c["free vertices"] = front.free_vertices;
  c["walk steps"] = n.walk_steps;
  c["cavity tets"] = n.cavity_tets;
  return c;
}

}  // namespace partet
