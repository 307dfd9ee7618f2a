// Parsers and writers of the mesh formats (Medit .mesh, Gmsh .msh 4.1, VTK
// .vtu/.pvtu). A parse returns vertices, triangles and tets in a TetMesh
// (0-based indices). Writers return the file's bytes (the .vtu writer can
// also stream them); callers write them atomically. Coordinates round-trip exactly (17 significant digits in text).
// Malformed input throws InputError naming the file and the line (text) or
// byte offset (binary, XML); counts are checked against the bytes present
// before anything is allocated, so hostile input cannot exhaust memory.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/tet_mesh.hpp"

namespace partet {

// What a parse keeps: a surface read wants triangles and refuses other
// polygons (quadrilaterals, higher-order faces); a volume read wants tets
// (and triangles) and refuses other volume elements (hexahedra, tet10...).
// Both skip the lower-dimensional rest (points, edges, ridges...).
enum class MeshRead { kSurface, kVolume };

// Medit .mesh ASCII (MeshVersionFormatted 1-4, Dimension 3); written as
// version 2 with 17-digit coordinates, references 1.
TetMesh parse_medit(std::string_view bytes, const std::string& file, MeshRead what);
std::string format_medit(const TetMesh& mesh);

// Gmsh 4.1, ASCII or binary (either byte order, told by the one-int marker;
// sparse node tags). Written with one volume entity (and one surface entity
// for the triangles); binary in the host's byte order with 8-byte size_t.
TetMesh parse_gmsh(std::string_view bytes, const std::string& file, MeshRead what);
std::string format_gmsh(const TetMesh& mesh, bool binary);

// VTK XML UnstructuredGrid: written with inline base64 binary data (header
// UInt64), tets only (boundary triangles are not written as cells); read in
// ascii, inline base64 (UInt32/UInt64 headers) and appended raw or base64
// data, either byte order, uncompressed; tetra cells (10) into tets, triangle
// cells (5) into tris, any other cell type refused. Point data "GlobalNodeId"
// is written when global_ids is set, and read when present.
TetMesh parse_vtu(std::string_view bytes, const std::string& file);
std::string format_vtu(const TetMesh& mesh);
// The same text handed to `sink` in pieces of about a megabyte, so a large
// mesh is written without its whole file in memory.
void write_vtu(const TetMesh& mesh, const std::function<void(std::string_view)>& sink);

// Parallel index: lists piece files (relative paths as written).
std::vector<std::string> parse_pvtu_pieces(std::string_view bytes, const std::string& file);
std::string format_pvtu(const std::vector<std::string>& piece_files, bool with_global_ids);

}  // namespace partet
