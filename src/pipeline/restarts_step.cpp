// local_restarts (see restarts_step.hpp).
#include "pipeline/restarts_step.hpp"

#include "optimize/local_restarts.hpp"
#include "pipeline/mesh_alternative.hpp"

namespace partet {

nlohmann::ordered_json local_restarts(TetMesh& mesh, QualityStats& quality, const OptimizeOptions& options) {
  const RestartStats stats = restart_around_worst(mesh, quality, options);
  nlohmann::ordered_json c;
  c["tried"] = stats.tried;
  c["kept"] = stats.kept;
  c.update(quality_counts(quality));
  return c;
}

}  // namespace partet
