// run_check: read, validate, print.
#include "check/check_command.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "check/validate.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "surface/diagnose.hpp"

namespace partet {

int run_check(const CheckOptions& options) {
  TetMesh mesh = read_volume_file(options.mesh);
  SurfaceMesh surface;
  if (!options.surface.empty()) {
    surface = read_surface_file(options.surface);
    diagnose_surface(surface, options.surface);
  }
  ValidationResult result = validate_mesh(mesh, options.surface.empty() ? nullptr : &surface);
  if (options.json) {
    nlohmann::json j;
    to_json(j, result);
    j["mesh"] = options.mesh;
    if (!options.surface.empty()) j["surface"] = options.surface;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("%s: %s", options.mesh.c_str(), format_text(result).c_str());
  }
  return result.valid ? kExitOk : kExitInvalid;
}

}  // namespace partet
