// Other pass counts for small meshes. What the optimizer's passes reach is
// not monotone in their number: a fourth and fifth pass lift the cube
// refined twice (192 triangles) from 29.98 to 35.26 degrees and cost the
// cross 13 degrees, and the cross's best (43.1 degrees) can come from two
// passes as well as from three, depending on rounding a change elsewhere
// moves. So on a front's mesh of at most kPassAlternativeTets tets, where a
// run of the optimizer costs milliseconds, the front's mesh is optimized
// again with every pass at the target (the later passes otherwise work on
// fewer tets: optimize.cpp, kLaterPassAngles; the cube refined twice then
// stops at 30.2 degrees where the passes at the target reach 35.3), with
// kExtraPasses more passes, then with kFewerPasses fewer (those two at the
// target throughout as well), and each replaces the mesh kept so far only
// when it is better (better_quality: no worse in any of the optimizer's
// three measures and better in one).
#pragma once

#include <cstddef>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"
#include "pipeline/report.hpp"

namespace partet {

constexpr size_t kPassAlternativeTets = 1024;
constexpr int kExtraPasses = 2;
constexpr int kFewerPasses = 1;

// The report steps "passes at the target alternative" (only when
// options.lower_later_targets), "more passes alternative" and "fewer
// passes alternative" (only when options.passes > kFewerPasses): on
// rank 0 (`root`), `front_mesh` optimized with the other pass count
// replaces `mesh` (whose quality is `quality`, updated when it is
// replaced) when better. Every rank calls it.
void run_pass_alternatives(RunReport& report, bool root, TetMesh& mesh, const TetMesh& front_mesh,
                           QualityStats& quality, const OptimizeOptions& options);

}  // namespace partet
