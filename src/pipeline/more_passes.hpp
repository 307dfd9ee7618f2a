// The more-passes alternative for small meshes. What the optimizer's
// passes reach is not monotone in their number: a fourth and fifth pass
// lift the cube refined twice (192 triangles) from 29.98 to 35.26 degrees,
// and cost the cross 13 degrees. So on a front's mesh of at most
// kMorePassesTets tets, where a run of the optimizer costs milliseconds,
// the front's mesh is optimized once more with kExtraPasses more passes and
// replaces the optimized mesh only when it is better (better_quality: no
// worse in any of the optimizer's three measures and better in one).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"

namespace partet {

constexpr size_t kMorePassesTets = 1024;
constexpr int kExtraPasses = 2;

// `front_mesh` optimized with options.passes + kExtraPasses replaces `mesh`
// (whose quality is `quality`, updated when it is replaced) when better.
// Returns what was tried, for the run report.
nlohmann::ordered_json try_more_passes(TetMesh& mesh, TetMesh front_mesh, QualityStats& quality,
                                       const OptimizeOptions& options);

}  // namespace partet
