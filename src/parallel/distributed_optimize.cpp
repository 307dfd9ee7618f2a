// optimize_distributed: partition, per-rank parts, join and band (see
// distributed_optimize.hpp).
#include "parallel/distributed_optimize.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "check/quality.hpp"
#include "core/compact_mesh.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "optimize/mesh_parts.hpp"
#include "parallel/mesh_scatter.hpp"

namespace partet {

namespace {

// The counts of the optimizer's stats (not before/after or passes) and
// their seconds, as one list: what the parts and the band add up.
std::array<size_t*, 12> counts_of(OptimizeStats& s) {
  return {&s.flips_23,           &s.flips_32,          &s.flips_44,         &s.edge_removals,
          &s.multi_face_removals, &s.vertices_inserted, &s.vertices_collapsed, &s.vertices_removed,
          &s.vertices_moved,      &s.vertices_relaxed,  &s.sheets_lifted,    &s.needles_split};
}
std::array<double*, 5> seconds_of(OptimizeStats& s) {
  return {&s.topology_seconds, &s.insertion_seconds, &s.smoothing_seconds, &s.relaxation_seconds,
          &s.measure_seconds};
}

// The counts and seconds of `x` added to `into`.
void add_counts(OptimizeStats& into, OptimizeStats x) {
  const auto to = counts_of(into), from = counts_of(x);
  for (size_t k = 0; k < to.size(); ++k) *to[k] += *from[k];
  const auto to_s = seconds_of(into), from_s = seconds_of(x);
  for (size_t k = 0; k < to_s.size(); ++k) *to_s[k] += *from_s[k];
}

// Every rank's counts and seconds summed, on every rank (passes: this rank's).
OptimizeStats sum_over_ranks(const Comm& comm, OptimizeStats x) {
  std::vector<int64_t> counts;
  for (size_t* c : counts_of(x)) counts.push_back(static_cast<int64_t>(*c));
  comm.sum(counts.data(), counts.size());
  OptimizeStats out;
  const auto fields = counts_of(out);
  for (size_t k = 0; k < fields.size(); ++k) *fields[k] = static_cast<size_t>(counts[k]);
  const auto to_s = seconds_of(out), from_s = seconds_of(x);
  for (size_t k = 0; k < to_s.size(); ++k) *to_s[k] = comm.sum(*from_s[k]);
  out.passes = x.passes;
  return out;
}

// The band (see the header, step 4) of a mesh cut into the parts of
// `part_of_tet` (the ranks' parts, then the band's shares): the tets with
// a vertex on a cut or on a tet under kBandAngle degrees, grown by one
// ring. Per tet, 0 in the band, -1 not; `band_tets` is increased by its
// size.
std::vector<int32_t> band_of(const TetMesh& mesh, const std::vector<int32_t>& part_of_tet, size_t& band_tets) {
  std::vector<uint8_t> marked = cut_vertices(mesh, part_of_tet);
  const std::vector<uint8_t> under = tets_under_angle(mesh, kBandAngle);
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    if (under[t])
      for (int i = 0; i < 4; ++i) marked[mesh.tets[4 * t + static_cast<size_t>(i)]] = 1;
  const std::vector<uint8_t> band = band_around(mesh, std::move(marked), 1);
  std::vector<int32_t> in_band(mesh.num_tets());
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    in_band[t] = band[t] ? 0 : -1;
    band_tets += band[t];
  }
  return in_band;
}

// The band's options: at most kBandPasses passes, worst tets stuck on a
// frozen vertex set aside.
OptimizeOptions band_options(const OptimizeOptions& options) {
  OptimizeOptions out = options;
  out.passes = std::min(options.passes, kBandPasses);
  out.set_aside_stuck_on_frozen = true;
  return out;
}

// `part`'s cut flags or'ed with `frozen` (per vertex of the mesh it was
// split from; vertices beyond it are free).
void freeze_also(MeshPart& part, const std::vector<uint8_t>& frozen) {
  for (size_t i = 0; i < part.whole.size(); ++i)
    if (part.whole[i] < frozen.size() && frozen[part.whole[i]]) part.on_cut[i] = 1;
}

// Step 4 (see the header): the band cut into P shares, optimized on the
// ranks, and the shares' own band (band_of again) on rank 0. Collective;
// `mesh` and `part_of_tet` are rank 0's. Returns every rank's counts
// summed, with rank 0's last pass.
OptimizeStats optimize_band(const Comm& comm, TetMesh& mesh, const std::vector<int32_t>& part_of_tet,
                            const OptimizeOptions& options, DistributedOptimizeStats& out) {
  const bool root = comm.rank() == 0;
  const OptimizeOptions band = band_options(options);
  std::vector<int32_t> in_band;
  MeshPart whole_band;
  if (root) {
    in_band = band_of(mesh, part_of_tet, out.band_tets);
    whole_band = std::move(split_mesh(mesh, in_band, 1)[0]);
  }
  const std::vector<int32_t> share_of = partition_tets(comm, whole_band.mesh);
  std::vector<MeshPart> shares;
  if (root) {
    shares = split_mesh(whole_band.mesh, share_of, comm.size());
    for (MeshPart& share : shares) freeze_also(share, whole_band.on_cut);
  }
  MeshPart own = scatter_parts(comm, shares);
  const OptimizeStats mine = own.mesh.num_tets() > 0 ? optimize_mesh(own.mesh, band, &own.on_cut) : OptimizeStats{};
  comm.idle_barrier();
  gather_parts(comm, own, shares);
  OptimizeStats total = sum_over_ranks(comm, mine);
  if (!root) return total;
  const std::vector<int32_t> share_now = join_parts(whole_band.mesh, share_of, shares);
  shares.clear();
  const std::vector<int32_t> in_crossing = band_of(whole_band.mesh, share_now, out.crossing_tets);
  std::vector<MeshPart> crossing = split_mesh(whole_band.mesh, in_crossing, 1);
  freeze_also(crossing[0], whole_band.on_cut);
  if (crossing[0].mesh.num_tets() > 0) add_counts(total, optimize_mesh(crossing[0].mesh, band, &crossing[0].on_cut));
  join_parts(whole_band.mesh, in_crossing, crossing);
  join_parts(mesh, in_band, {whole_band});
  return total;
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
  out.split_seconds = part_start;
  OptimizeOptions part_options = options;
  part_options.set_aside_stuck_on_frozen = true;
  const OptimizeStats mine =
      own.mesh.num_tets() > 0 ? optimize_mesh(own.mesh, part_options, &own.on_cut) : OptimizeStats{};
  const double part_seconds = clock.wall() - part_start;
  comm.idle_barrier();  // the ranks done first sleep until the last part is optimized
  out.part_seconds = comm.all_gather(part_seconds);
  gather_parts(comm, own, parts);
  out.totals = sum_over_ranks(comm, mine);
  out.totals.before = before;
  std::vector<int32_t> joined;
  if (root) {
    joined = join_parts(mesh, part_of_tet, parts);
    parts.clear();
  }
  const double band_start = clock.wall();
  // After the slowest part (the ranks' clocks started apart: never below 0).
  out.join_seconds =
      std::max(0.0, band_start - part_start - *std::max_element(out.part_seconds.begin(), out.part_seconds.end()));
  add_counts(out.totals, optimize_band(comm, mesh, joined, options, out));
  out.band_seconds = clock.wall() - band_start;
  if (root) {
    drop_unused_vertices(mesh);
    out.totals.after = measure_quality(mesh);
  }
  out.totals.seconds = clock.wall();
  return out;
}

}  // namespace partet
