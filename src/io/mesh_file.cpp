// Dispatch of file reads and writes by extension, .pvtu pieces, merging.
#include "io/mesh_file.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "core/error.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_formats.hpp"
#include "io/surface_formats.hpp"
#include "io/surface_write.hpp"

namespace partet {

const std::vector<std::string>& surface_extensions() {
  static const std::vector<std::string> list{"stl", "off", "obj", "ply", "mesh", "msh"};
  return list;
}

const std::vector<std::string>& volume_extensions() {
  static const std::vector<std::string> list{"mesh", "msh", "vtu", "pvtu"};
  return list;
}

void require_extension(const std::string& path, const std::vector<std::string>& allowed, const char* role) {
  std::string ext = file_extension(path);
  if (std::find(allowed.begin(), allowed.end(), ext) != allowed.end()) return;
  std::string list;
  for (const auto& e : allowed) list += (list.empty() ? "." : ", .") + e;
  throw InputError(path + ": unknown " + role + " format '" + (ext.empty() ? "(no extension)" : "." + ext) +
                   "'; partet knows " + list);
}

SurfaceMesh read_surface_file(const std::string& path) {
  require_extension(path, surface_extensions(), "surface");
  std::string ext = file_extension(path);
  std::string bytes = read_file_bytes(path);
  if (ext == "stl") return parse_stl(bytes, path);
  if (ext == "off") return parse_off(bytes, path);
  if (ext == "obj") return parse_obj(bytes, path);
  if (ext == "ply") return parse_ply(bytes, path);
  TetMesh m = ext == "mesh" ? parse_medit(bytes, path, MeshRead::kSurface) : parse_gmsh(bytes, path, MeshRead::kSurface);
  if (m.tris.empty()) throw InputError(path + ": the file holds no triangles");
  SurfaceMesh s;
  s.xyz = std::move(m.xyz);
  s.tris = std::move(m.tris);
  return s;
}

void write_surface_file(const SurfaceMesh& surface, const std::string& path, const WriteOptions& options) {
  require_extension(path, surface_extensions(), "surface");
  std::string ext = file_extension(path);
  if (ext == "off") return write_file_atomic(path, format_off(surface));
  if (ext == "obj") return write_file_atomic(path, format_obj(surface));
  if (ext == "stl") return write_file_atomic(path, format_stl_ascii(surface));
  if (ext == "ply") return write_file_atomic(path, format_ply_binary(surface));
  TetMesh m;
  m.xyz = surface.xyz;
  m.tris = surface.tris;
  if (ext == "mesh") return write_file_atomic(path, format_medit(m));
  write_file_atomic(path, format_gmsh(m, !options.ascii));
}

std::string pvtu_piece_path(const std::string& path, int rank) {
  std::string stem = path.substr(0, path.size() - std::strlen(".pvtu"));
  return stem + "_" + std::to_string(rank) + ".vtu";
}

TetMesh read_volume_file(const std::string& path) {
  require_extension(path, volume_extensions(), "volume mesh");
  std::string ext = file_extension(path);
  std::string bytes = read_file_bytes(path);
  if (ext == "mesh") return parse_medit(bytes, path, MeshRead::kVolume);
  if (ext == "msh") return parse_gmsh(bytes, path, MeshRead::kVolume);
  if (ext == "vtu") return parse_vtu(bytes, path);
  std::vector<std::string> pieces = parse_pvtu_pieces(bytes, path);
  size_t slash = path.find_last_of('/');
  std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::vector<TetMesh> parts;
  for (const auto& piece : pieces) {
    std::string piece_path = !piece.empty() && piece[0] == '/' ? piece : dir + piece;
    parts.push_back(parse_vtu(read_file_bytes(piece_path), piece_path));
  }
  return merge_parts(parts);
}

void write_volume_file(const TetMesh& mesh, const std::string& path, const WriteOptions& options) {
  require_extension(path, volume_extensions(), "volume mesh");
  std::string ext = file_extension(path);
  if (ext == "mesh") return write_file_atomic(path, format_medit(mesh));
  if (ext == "msh") return write_file_atomic(path, format_gmsh(mesh, !options.ascii));
  if (ext == "vtu") {
    AtomicFile file(path);
    write_vtu(mesh, [&](std::string_view bytes) { file.write(bytes); });
    file.commit();
    return;
  }
  std::string piece = pvtu_piece_path(path, 0);
  write_file_atomic(piece, format_vtu(mesh));
  write_file_atomic(path, format_pvtu({file_basename(piece)}, !mesh.global_ids.empty()));
}

namespace {

struct CoordKey {
  uint64_t bits[3];
  bool operator==(const CoordKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};

struct CoordHash {
  size_t operator()(const CoordKey& k) const {
    uint64_t h = k.bits[0] * 0x9E3779B97F4A7C15ull;
    h ^= k.bits[1] + 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= k.bits[2] + 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

CoordKey key_of(const double* p) {
  CoordKey k;
  for (int i = 0; i < 3; ++i) {
    double v = p[i] == 0.0 ? 0.0 : p[i];  // -0 and 0 are one point
    std::memcpy(&k.bits[i], &v, sizeof v);
  }
  return k;
}

}  // namespace

TetMesh merge_parts(const std::vector<TetMesh>& parts) {
  TetMesh out;
  std::unordered_map<CoordKey, uint32_t, CoordHash> index;
  for (const TetMesh& part : parts) {
    std::vector<uint32_t> local(part.num_vertices());
    for (size_t v = 0; v < part.num_vertices(); ++v) {
      auto [it, fresh] = index.try_emplace(key_of(part.point(v)), static_cast<uint32_t>(out.num_vertices()));
      if (fresh) out.xyz.insert(out.xyz.end(), part.point(v), part.point(v) + 3);
      local[v] = it->second;
    }
    for (uint32_t v : part.tets) out.tets.push_back(local.at(v));
    for (uint32_t v : part.tris) out.tris.push_back(local.at(v));
  }
  return out;
}

}  // namespace partet
