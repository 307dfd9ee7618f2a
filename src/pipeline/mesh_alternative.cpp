// An alternative mesh kept when better (see mesh_alternative.hpp).
#include "pipeline/mesh_alternative.hpp"

#include <utility>

#include "core/compact_mesh.hpp"

namespace partet {

nlohmann::ordered_json quality_counts(const QualityStats& q) {
  nlohmann::ordered_json c;
  c["min dihedral"] = q.min_dihedral_deg;
  c["% under 10 deg"] = q.tets ? 100.0 * static_cast<double>(q.dihedral_under_10) / static_cast<double>(q.tets) : 0.0;
  c["mean radius ratio"] = q.radius_ratio_mean;
  return c;
}

nlohmann::ordered_json keep_better_alternative(TetMesh& mesh, TetMesh candidate, QualityStats& quality,
                                               const OptimizeOptions& options) {
  const OptimizeStats stats = optimize_mesh(candidate, options);
  if (stats.vertices_collapsed + stats.vertices_removed > 0) drop_unused_vertices(candidate);
  const QualityStats& q = stats.after;
  const bool kept = better_quality(q, quality);
  nlohmann::ordered_json c;
  c["passes"] = stats.passes;
  c["tets"] = candidate.num_tets();
  c.update(quality_counts(q));
  c["kept"] = kept;
  if (kept) {
    mesh = std::move(candidate);
    quality = q;
  }
  return c;
}

}  // namespace partet
