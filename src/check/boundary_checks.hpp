// Checks on the boundary faces of a tet mesh (faces used by exactly one tet,
// given as face codes 4*tet + local face, see tet_faces.hpp, and taken
// outward oriented): against a surface, or, without one, for closedness.
// Each appends one line per kind of problem to `problems`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/tet_mesh.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

// The boundary faces must be exactly the surface's triangles with the same
// orientation. Mesh and surface vertices are matched by exact coordinates
// (-0.0 equals 0.0), so the two numberings may differ; surface vertices with
// equal coordinates count as one.
void match_boundary_to_surface(const TetMesh& mesh, const std::vector<uint32_t>& boundary,
                               const SurfaceMesh& surface, std::vector<std::string>& problems);

// The boundary faces must form a closed surface: every boundary edge is used
// as often in one direction as in the other. An edge used by more than two
// faces that way is closed but non-manifold (two parts touching along an
// edge): a warning, not a problem.
void check_boundary_closed(const TetMesh& mesh, const std::vector<uint32_t>& boundary,
                           std::vector<std::string>& problems, std::vector<std::string>& warnings);

// Signed volume enclosed by an oriented closed surface: the sum over its
// triangles of det(a-o, b-o, c-o)/6, compensated. The reference point o,
// the centre of the bounding box, keeps the terms of the size of the object
// even far from the origin (for a closed surface the sum does not depend on
// o). Triangles oriented outward give a positive volume.
// Both functions throw InputError for a surface vertex index out of range.
double enclosed_volume(const SurfaceMesh& surface);

}  // namespace partet
