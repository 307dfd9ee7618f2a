// Parsers and writers of the mesh formats (Medit .mesh, Gmsh .msh 4.1, VTK
// .vtu/.pvtu). A parse returns vertices, triangles and tets in a TetMesh
// (0-based indices). Writers return the file's bytes; callers write them
// atomically. Coordinates round-trip exactly (17 significant digits in text).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/tet_mesh.hpp"

namespace partet {

// What a parse keeps: a surface read wants triangles and refuses other
// polygons (quadrilaterals...); a volume read wants tets (and triangles).
enum class MeshRead { kSurface, kVolume };

TetMesh parse_medit(std::string_view bytes, const std::string& file, MeshRead what);
std::string format_medit(const TetMesh& mesh);

// Gmsh 4.1, ASCII or binary (either endianness check via the one-int marker).
TetMesh parse_gmsh(std::string_view bytes, const std::string& file, MeshRead what);
std::string format_gmsh(const TetMesh& mesh, bool binary);

// VTK XML UnstructuredGrid: written with base64 binary data (header UInt64);
// read in ascii, base64 binary (UInt32/UInt64 headers) and raw appended data,
// uncompressed. Point data "GlobalNodeId" is written when global_ids is set.
TetMesh parse_vtu(std::string_view bytes, const std::string& file);
std::string format_vtu(const TetMesh& mesh);

// Parallel index: lists piece files (relative paths as written).
std::vector<std::string> parse_pvtu_pieces(std::string_view bytes, const std::string& file);
std::string format_pvtu(const std::vector<std::string>& piece_files, bool with_global_ids);

}  // namespace partet
