// Parsers of the surface-only formats. Each takes the whole file in memory
// and the file's name (for messages), and returns the triangles with 0-based
// vertex indices. Malformed input throws InputError naming the file and the
// line (text) or byte offset (binary). Faces that are not triangles are
// refused with their index and vertex count. Coordinates are kept exactly.
#pragma once

#include <string>
#include <string_view>

#include "surface/surface_mesh.hpp"

namespace partet {

// STL, ASCII or binary (told apart by content, not by the "solid" keyword
// alone); vertices with exactly equal coordinates are merged.
SurfaceMesh parse_stl(std::string_view bytes, const std::string& file);
// OFF, also COFF/NOFF/CNOFF headers, '#' comments and per-face colours.
SurfaceMesh parse_off(std::string_view bytes, const std::string& file);
// Wavefront OBJ: `v` and `f` (v, v/vt, v//vn, v/vt/vn; negative indices);
// other statements are ignored.
SurfaceMesh parse_obj(std::string_view bytes, const std::string& file);
// PLY, ASCII and binary little-endian (and big-endian): `vertex` x y z and
// `face` vertex_indices (or vertex_index) lists; other properties skipped.
SurfaceMesh parse_ply(std::string_view bytes, const std::string& file);

}  // namespace partet
