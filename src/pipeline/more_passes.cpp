// The more-passes alternative (see more_passes.hpp).
#include "pipeline/more_passes.hpp"

#include <utility>

#include "pipeline/mesh_alternative.hpp"

namespace partet {

nlohmann::ordered_json try_more_passes(TetMesh& mesh, TetMesh front_mesh, QualityStats& quality,
                                       const OptimizeOptions& options) {
  OptimizeOptions more = options;
  more.passes += kExtraPasses;
  return keep_better_alternative(mesh, std::move(front_mesh), quality, more);
}

}  // namespace partet
