// optimize_step: the distributed optimizer and its report counts (see
// optimize_step.hpp).
#include "pipeline/optimize_step.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "parallel/distributed_optimize.hpp"

namespace partet {

ojson optimize_step(const Comm& comm, TetMesh& mesh, const OptimizeOptions& options, QualityStats& after) {
  const DistributedOptimizeStats d = optimize_distributed(comm, mesh, options);
  if (comm.rank() != 0) return ojson::object();
  const OptimizeStats& n = d.totals;
  after = n.after;
  ojson c;
  for (const auto& [when, q] : {std::pair{"before", n.before}, std::pair{"after", n.after}}) {
    const double tets = static_cast<double>(std::max<size_t>(q.tets, 1));
    c[std::string("min dihedral ") + when] = q.min_dihedral_deg;
    c[std::string("max dihedral ") + when] = q.max_dihedral_deg;
    c[std::string("% under 10 deg ") + when] = 100.0 * static_cast<double>(q.dihedral_under_10) / tets;
    c[std::string("mean radius ratio ") + when] = q.radius_ratio_mean;
  }
  c["2-3 flips"] = n.flips_23;
  c["3-2 flips"] = n.flips_32;
  c["4-4 flips"] = n.flips_44;
  c["edge removals"] = n.edge_removals;
  c["multi-face removals"] = n.multi_face_removals;
  c["vertices inserted"] = n.vertices_inserted;
  c["vertices collapsed"] = n.vertices_collapsed;
  c["vertices removed"] = n.vertices_removed;
  c["vertices moved"] = n.vertices_moved;
  c["vertices relaxed"] = n.vertices_relaxed;
  c["sheets lifted"] = n.sheets_lifted;
  c["needles split"] = n.needles_split;
  c["passes"] = n.passes;
  c["topology s"] = n.topology_seconds;
  c["insertion s"] = n.insertion_seconds;
  c["smoothing s"] = n.smoothing_seconds;
  c["relaxation s"] = n.relaxation_seconds;
  c["measure s"] = n.measure_seconds;
  if (comm.size() > 1) {
    c["tets per rank"] = d.tets_per_rank;
    c["split s"] = d.split_seconds;
    c["part s per rank"] = d.part_seconds;
    c["join s"] = d.join_seconds;
    c["band tets"] = d.band_tets;
    c["crossing tets"] = d.crossing_tets;
    c["band s"] = d.band_seconds;
  }
  c["tets"] = mesh.num_tets();
  return c;
}

}  // namespace partet
