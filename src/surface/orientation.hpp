// Consistent orientation of a closed manifold triangle surface and its
// shells (edge-connected components), then the orientation of each shell
// from its nesting: a shell inside an even number of others bounds material
// from outside (enclosed volume positive), one inside an odd number bounds a
// cavity (its triangles face into the cavity, enclosed volume negative).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "surface/edge_table.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct ShellInfo {
  std::vector<uint32_t> shell_of_triangle;
  uint32_t count = 0;
  std::vector<uint32_t> depth;   // per shell: how many other shells enclose it
  std::vector<double> volume;    // per shell: signed enclosed volume after orientation
  size_t reoriented = 0;         // triangles whose vertex order was reversed
};

// Makes every shell consistently oriented (each edge used once in each
// direction), then orients each shell by its nesting depth. Precondition:
// closed, edge- and vertex-manifold, no self-intersections, no degenerate
// triangles. Throws InputError naming `file` for a non-orientable shell or
// one that encloses no volume.
ShellInfo orient_shells(SurfaceMesh& surface, const EdgeTable& edges, const std::string& file);

}  // namespace partet
