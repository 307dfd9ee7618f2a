// The other pass counts for small meshes (see pass_alternatives.hpp).
#include "pipeline/pass_alternatives.hpp"

#include "pipeline/mesh_alternative.hpp"

namespace partet {

void run_pass_alternatives(RunReport& report, bool root, TetMesh& mesh, const TetMesh& front_mesh,
                           QualityStats& quality, const OptimizeOptions& options) {
  auto alternative = [&](int passes) {
    if (!root) return nlohmann::ordered_json::object();
    OptimizeOptions other = options;
    other.passes = passes;
    other.lower_later_targets = false;
    return keep_better_alternative(mesh, front_mesh, quality, other);
  };
  if (options.lower_later_targets)
    report.run_step("passes at the target alternative", [&] { return alternative(options.passes); });
  report.run_step("more passes alternative", [&] { return alternative(options.passes + kExtraPasses); });
  if (options.passes > kFewerPasses)
    report.run_step("fewer passes alternative", [&] { return alternative(options.passes - kFewerPasses); });
}

}  // namespace partet
