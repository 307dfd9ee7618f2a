// Text for error messages that name entities: vertex ids with exact
// coordinates, triangles with their vertices, and "first few of N" lists.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/point_text.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

// "vertex 12 (x, y, z)"
std::string vertex_text(const SurfaceMesh& s, uint32_t v);
// "triangle 7 (vertices 1, 2, 3 at (..), (..), (..))"
std::string triangle_text(const SurfaceMesh& s, uint32_t t);

// How many offenders a message lists.
constexpr size_t kListedCases = 5;

// "<file>: <count> <what>\n  <case 1>\n  ...\n  (and N more)"
std::string case_list(const std::string& file, size_t count, const std::string& what,
                      const std::vector<std::string>& cases);

}  // namespace partet
