// Nesting of the disjoint closed shells of a surface: for each shell, how
// many other shells enclose it, by exact ray parity (a ray from one of its
// vertices, crossing counted with exact predicates; a ray that grazes an
// edge or a vertex is replaced by another direction).
#pragma once

#include <cstdint>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace partet {

// Precondition: shells are closed and pairwise disjoint (no intersections).
std::vector<uint32_t> shell_depths(const SurfaceMesh& surface, const std::vector<uint32_t>& shell_of_triangle,
                                   uint32_t shell_count);

// Exact parity test: is `p` (not on the closed shell) inside the closed shell
// formed by the triangles `tris` of `surface`? `far` is a length larger than
// the distance from p to any point of the shell.
bool point_inside_shell(const SurfaceMesh& surface, const std::vector<uint32_t>& tris, const double* p,
                        double far);

}  // namespace partet
