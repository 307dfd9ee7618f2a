// local_restarts (see restarts_step.hpp).
#include "pipeline/restarts_step.hpp"

#include "optimize/local_restarts.hpp"

namespace partet {

nlohmann::ordered_json local_restarts(TetMesh& mesh, QualityStats& quality, const OptimizeOptions& options) {
  const RestartStats stats = restart_around_worst(mesh, quality, options);
  nlohmann::ordered_json c;
  c["tried"] = stats.tried;
  c["kept"] = stats.kept;
  c["min dihedral"] = quality.min_dihedral_deg;
  c["% under 10 deg"] = quality.tets ? 100.0 * static_cast<double>(quality.dihedral_under_10) /
                                           static_cast<double>(quality.tets)
                                     : 0.0;
  c["mean radius ratio"] = quality.radius_ratio_mean;
  return c;
}

}  // namespace partet
