// optimize_distributed: partition, per-rank parts, join and band (see
// distributed_optimize.hpp).
#include "parallel/distributed_optimize.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "check/quality.hpp"
#include "core/compact_mesh.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "optimize/mesh_parts.hpp"
#include "parallel/mesh_scatter.hpp"
#include "parallel/write_parts.hpp"

namespace partet {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180;

// The counts of `x` added to `into` (not before/after, passes or seconds).
void add_counts(OptimizeStats& into, const OptimizeStats& x) {
  into.flips_23 += x.flips_23;
  into.flips_32 += x.flips_32;
  into.flips_44 += x.flips_44;
  into.edge_removals += x.edge_removals;
  into.multi_face_removals += x.multi_face_removals;
  into.vertices_inserted += x.vertices_inserted;
  into.vertices_collapsed += x.vertices_collapsed;
  into.vertices_removed += x.vertices_removed;
  into.vertices_moved += x.vertices_moved;
  into.vertices_relaxed += x.vertices_relaxed;
  into.sheets_lifted += x.sheets_lifted;
  into.needles_split += x.needles_split;
  into.topology_seconds += x.topology_seconds;
  into.insertion_seconds += x.insertion_seconds;
  into.smoothing_seconds += x.smoothing_seconds;
  into.relaxation_seconds += x.relaxation_seconds;
  into.measure_seconds += x.measure_seconds;
}

// Every rank's counts and seconds summed, on every rank.
OptimizeStats sum_over_ranks(const Comm& comm, const OptimizeStats& x) {
  int64_t counts[] = {static_cast<int64_t>(x.flips_23),          static_cast<int64_t>(x.flips_32),
                      static_cast<int64_t>(x.flips_44),          static_cast<int64_t>(x.edge_removals),
                      static_cast<int64_t>(x.multi_face_removals), static_cast<int64_t>(x.vertices_inserted),
                      static_cast<int64_t>(x.vertices_collapsed), static_cast<int64_t>(x.vertices_removed),
                      static_cast<int64_t>(x.vertices_moved),     static_cast<int64_t>(x.vertices_relaxed),
                      static_cast<int64_t>(x.sheets_lifted),      static_cast<int64_t>(x.needles_split)};
  comm.sum(counts, std::size(counts));
  OptimizeStats out;
  size_t k = 0;
  for (size_t* field : {&out.flips_23, &out.flips_32, &out.flips_44, &out.edge_removals, &out.multi_face_removals,
                        &out.vertices_inserted, &out.vertices_collapsed, &out.vertices_removed, &out.vertices_moved,
                        &out.vertices_relaxed, &out.sheets_lifted, &out.needles_split})
    *field = static_cast<size_t>(counts[k++]);
  out.topology_seconds = comm.sum(x.topology_seconds);
  out.insertion_seconds = comm.sum(x.insertion_seconds);
  out.smoothing_seconds = comm.sum(x.smoothing_seconds);
  out.relaxation_seconds = comm.sum(x.relaxation_seconds);
  out.measure_seconds = comm.sum(x.measure_seconds);
  out.passes = x.passes;
  return out;
}

// The band pass on rank 0 (see the header, step 4): returns its stats.
OptimizeStats optimize_band(TetMesh& mesh, const std::vector<int32_t>& part_of_tet, const OptimizeOptions& options,
                            size_t& band_tets) {
  std::vector<uint8_t> marked = cut_vertices(mesh, part_of_tet);
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    if (tet_shape(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])).min_dihedral_rad <
        kBandAngle * kDegree)
      for (int i = 0; i < 4; ++i) marked[v[i]] = 1;
  }
  const std::vector<uint8_t> band = band_around(mesh, std::move(marked), 1);
  std::vector<int32_t> in_band(mesh.num_tets());
  band_tets = 0;
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    in_band[t] = band[t] ? 0 : -1;
    band_tets += band[t];
  }
  std::vector<MeshPart> parts = split_mesh(mesh, in_band, 1);
  OptimizeOptions band_options = options;
  band_options.passes = std::min(options.passes, kBandPasses);
  band_options.set_aside_stuck_on_frozen = true;
  const OptimizeStats n = optimize_mesh(parts[0].mesh, band_options, &parts[0].on_cut);
  join_parts(mesh, in_band, parts);
  return n;
}

}  // namespace

DistributedOptimizeStats optimize_distributed(const Comm& comm, TetMesh& mesh, const OptimizeOptions& options) {
  DistributedOptimizeStats out;
  const bool root = comm.rank() == 0;
  PARTET_ASSERT(mesh.global_ids.empty(), "optimize_distributed: a whole mesh has no global ids");
  if (comm.size() == 1) {
    out.totals = optimize_mesh(mesh, options);
    out.tets_per_rank = {static_cast<int64_t>(out.totals.before.tets)};
    out.part_seconds = {out.totals.seconds};
    drop_unused_vertices(mesh);
    return out;
  }
  const Stopwatch clock;
  QualityStats before;
  if (root) before = measure_quality(mesh);
  const std::vector<int32_t> part_of_tet = partition_tets(comm, mesh);
  std::vector<MeshPart> parts;
  if (root) parts = split_mesh(mesh, part_of_tet, comm.size());
  MeshPart own = scatter_parts(comm, parts);
  out.tets_per_rank = comm.all_gather(static_cast<int64_t>(own.mesh.num_tets()));
  const double part_start = clock.wall();
  OptimizeOptions part_options = options;
  part_options.set_aside_stuck_on_frozen = true;
  const OptimizeStats mine =
      own.mesh.num_tets() > 0 ? optimize_mesh(own.mesh, part_options, &own.on_cut) : OptimizeStats{};
  out.part_seconds = comm.all_gather(clock.wall() - part_start);
  const std::vector<std::string> optimized = comm.gather(serialize_part(own.mesh), 0);
  out.totals = sum_over_ranks(comm, mine);
  out.totals.before = before;
  if (root) {
    for (size_t r = 0; r < parts.size(); ++r) parts[r].mesh = deserialize_part(optimized[r]);
    const std::vector<int32_t> joined = join_parts(mesh, part_of_tet, parts);
    parts.clear();
    const double band_start = clock.wall();
    add_counts(out.totals, optimize_band(mesh, joined, options, out.band_tets));
    out.band_seconds = clock.wall() - band_start;
    drop_unused_vertices(mesh);
    out.totals.after = measure_quality(mesh);
  }
  out.totals.seconds = clock.wall();
  return out;
}

}  // namespace partet
