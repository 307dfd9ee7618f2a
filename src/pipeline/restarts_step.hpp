// The report step "local restarts": restart_around_worst on the finished
// mesh (optimize/local_restarts.hpp) and its counts.
#pragma once

#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"

namespace partet {

// On rank 0's whole mesh, whose measure `quality` is kept up to date.
nlohmann::ordered_json local_restarts(TetMesh& mesh, QualityStats& quality, const OptimizeOptions& options);

}  // namespace partet
