// The more-passes alternative (see more_passes.hpp).
#include "pipeline/more_passes.hpp"

#include <utility>

#include "core/compact_mesh.hpp"

namespace partet {

nlohmann::ordered_json try_more_passes(TetMesh& mesh, TetMesh front_mesh, QualityStats& quality,
                                       const OptimizeOptions& options) {
  OptimizeOptions more = options;
  more.passes += kExtraPasses;
  const OptimizeStats stats = optimize_mesh(front_mesh, more);
  if (stats.vertices_collapsed + stats.vertices_removed > 0) drop_unused_vertices(front_mesh);
  const QualityStats& q = stats.after;
  const bool kept = better_quality(q, quality);
  nlohmann::ordered_json c;
  c["passes"] = stats.passes;
  c["tets"] = front_mesh.num_tets();
  c["min dihedral"] = q.min_dihedral_deg;
  c["% under 10 deg"] = 100.0 * static_cast<double>(q.dihedral_under_10) / static_cast<double>(q.tets);
  c["mean radius ratio"] = q.radius_ratio_mean;
  c["kept"] = kept;
  if (kept) {
    mesh = std::move(front_mesh);
    quality = q;
  }
  return c;
}

}  // namespace partet
