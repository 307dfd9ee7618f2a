// Shared checks of the libFuzzer targets: a parse may throw InputError
// (expected on malformed bytes) but whatever it returns must be well formed;
// anything else (an InternalError or other exception, a sanitizer report, a
// broken result) is a finding and aborts the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/tet_mesh.hpp"
#include "surface/surface_mesh.hpp"

namespace partet::fuzz {

inline std::string_view as_bytes(const uint8_t* data, size_t size) {
  return std::string_view(reinterpret_cast<const char*>(data), size);
}

// Runs `parse_and_check`; bad input must end in an InputError naming `file`,
// and nothing else.
template <class Body>
void expect_input_error_only(std::string_view file, Body&& parse_and_check) {
  try {
    parse_and_check();
  } catch (const Error& e) {
    if (e.exit_code() != kExitInput) std::abort();
    if (std::string_view(e.what()).find(file) == std::string_view::npos) std::abort();
  }
}

// Every index in `cells` (groups of `arity`) names one of `num_vertices`.
inline void check_cells(const std::vector<uint32_t>& cells, size_t arity, size_t num_vertices) {
  if (cells.size() % arity != 0) std::abort();
  for (uint32_t v : cells)
    if (v >= num_vertices) std::abort();
}

// A surface read must have triangles, and all their vertices.
inline void check_surface(const SurfaceMesh& mesh) {
  if (mesh.xyz.size() % 3 != 0 || mesh.tris.empty()) std::abort();
  check_cells(mesh.tris, 3, mesh.num_vertices());
}

inline void check_volume(const TetMesh& mesh) {
  if (mesh.xyz.size() % 3 != 0) std::abort();
  check_cells(mesh.tris, 3, mesh.num_vertices());
  check_cells(mesh.tets, 4, mesh.num_vertices());
  if (!mesh.global_ids.empty() && mesh.global_ids.size() != mesh.num_vertices()) std::abort();
}

}  // namespace partet::fuzz
