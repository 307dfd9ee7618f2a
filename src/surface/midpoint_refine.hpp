// 1:4 midpoint refinement of a triangulated surface: every triangle is split
// into four at its edge midpoints (computed once per edge, so neighbours
// share them). The same shape with four times the triangles, each original
// triangle's four exactly coplanar up to the rounding of the midpoints:
// benchmarks and the corpus check use it to make large inputs, tests to make
// hard ones.
#pragma once

#include "surface/surface_mesh.hpp"

namespace partet {

SurfaceMesh refine_midpoints(const SurfaceMesh& in);

}  // namespace partet
