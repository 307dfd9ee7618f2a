// An alternative mesh of the same surface, optimized and kept in place of
// the optimized mesh only when it is better in the optimizer's three
// measures (better_quality). The cone alternative and the other pass
// counts (pass_alternatives.hpp) all end this way.
#pragma once

#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"

namespace partet {

// `candidate` optimized with `options` replaces `mesh` (whose quality is
// `quality`, updated when it is replaced) when better_quality. Returns the
// report counts: passes, tets, min dihedral, % under 10 deg, mean radius
// ratio of the candidate, and whether it was kept.
// The report counts of a measure: min dihedral, % under 10 deg, mean
// radius ratio.
nlohmann::ordered_json quality_counts(const QualityStats& q);

nlohmann::ordered_json keep_better_alternative(TetMesh& mesh, TetMesh candidate, QualityStats& quality,
                                               const OptimizeOptions& options);

}  // namespace partet
