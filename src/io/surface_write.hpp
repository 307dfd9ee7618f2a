// Writers of the surface formats: OFF, OBJ, ASCII STL (17 significant
// digits, so they read back exactly) and binary little-endian PLY (double
// coordinates). Each returns the file's bytes; callers write atomically.
#pragma once

#include <string>

#include "surface/surface_mesh.hpp"

namespace partet {

std::string format_off(const SurfaceMesh& surface);
std::string format_obj(const SurfaceMesh& surface);
std::string format_stl_ascii(const SurfaceMesh& surface);
std::string format_ply_binary(const SurfaceMesh& surface);

}  // namespace partet
