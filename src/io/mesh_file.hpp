// Reading and writing mesh files by extension: surfaces (.stl .off .obj .ply
// .mesh .msh), volume meshes (.mesh .msh .vtu .pvtu). Writes are atomic.
#pragma once

#include <string>
#include <vector>

#include "core/tet_mesh.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct WriteOptions {
  bool ascii = false;  // Gmsh .msh: ASCII instead of binary
};

// Extensions partet reads surfaces from / reads and writes volume meshes in.
const std::vector<std::string>& surface_extensions();
const std::vector<std::string>& volume_extensions();

// InputError naming the file when the extension is not one of the list.
void require_extension(const std::string& path, const std::vector<std::string>& allowed, const char* role);

SurfaceMesh read_surface_file(const std::string& path);
// .pvtu: the pieces are read and merged (vertices joined by exact coordinates).
TetMesh read_volume_file(const std::string& path);
// .mesh, .msh, .vtu: one file; .pvtu: an index and one piece (`<stem>_0.vtu`).
void write_volume_file(const TetMesh& mesh, const std::string& path, const WriteOptions& options);

// Surfaces: .off .obj .stl (ASCII) .ply (binary) .mesh .msh; exact coordinates.
void write_surface_file(const SurfaceMesh& surface, const std::string& path, const WriteOptions& options);

// Name of piece `rank` of the .pvtu index `path`: "dir/stem_<rank>.vtu".
std::string pvtu_piece_path(const std::string& path, int rank);

// Joins parts into one mesh: vertices with bitwise-equal coordinates (-0 == 0)
// become one; tets and triangles are renumbered, in part order.
TetMesh merge_parts(const std::vector<TetMesh>& parts);

}  // namespace partet
