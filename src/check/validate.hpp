// The validator behind `partet check`: is a tet mesh a valid, conforming
// mesh, and, when a surface is given, does it fill exactly that surface?
// Every decision is exact (orient3d, exact coordinate equality) except the
// volume comparison, which has a tolerance far above rounding and far below
// any real error (see validate.cpp). Valid means:
//  - vertex indices in range, no NaN or infinite coordinate;
//  - every tet positively oriented (orient3d > 0; zero volume is invalid);
//  - every face shared by at most two tets, which lie strictly on opposite
//    sides of it; no two tets with the same four vertices;
//  - with a surface: the boundary faces (used by one tet, oriented outward)
//    are exactly the surface's triangles, matched by coordinates, with the
//    same orientation, and the tet volume equals the enclosed volume;
//  - without a surface: the boundary faces form a closed surface (an
//    internal hole, e.g. a missing interior tet, is still closed: valid).
// Warnings do not make a mesh invalid: unused vertices, non-manifold but
// closed boundary edges.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct ValidationResult {
  bool valid = true;
  // One line per kind of problem: the count and the first few offenders
  // with tet ids, vertex ids and coordinates.
  std::vector<std::string> problems;
  std::vector<std::string> warnings;  // same form, not making the mesh invalid
  size_t vertices = 0;
  size_t tets = 0;
  size_t interior_faces = 0;             // faces shared by exactly two tets
  size_t boundary_faces = 0;             // faces used by exactly one tet
  size_t unused_vertices = 0;            // vertices no tet uses
  double tet_volume = 0;                 // sum of signed tet volumes
  std::optional<double> surface_volume;  // when a surface is given
  QualityStats quality;
};

// `surface` may be null. Throws InputError for a surface whose triangles
// index missing vertices, or a part of 2^30 tets or more.
ValidationResult validate_mesh(const TetMesh& mesh, const SurfaceMesh* surface);

void to_json(nlohmann::json& j, const ValidationResult& r);

// Human summary: verdict, counts, problems, warnings, quality table.
std::string format_text(const ValidationResult& r);

}  // namespace partet
