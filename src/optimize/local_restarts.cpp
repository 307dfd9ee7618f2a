// restart_around_worst (see local_restarts.hpp).
#include "optimize/local_restarts.hpp"

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

#include "core/compact_mesh.hpp"
#include "core/error.hpp"
#include "optimize/mesh_parts.hpp"
#include "optimize/tet_kernels.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

constexpr int kWidestRestartBand = *std::max_element(std::begin(kRestartLayers), std::end(kRestartLayers));

// The tet of lowest tet_quality, ties to the lowest index, and its quality:
// the qualities measured in blocks by the vectorized kernel, which gives
// tet_quality's values bit for bit.
std::pair<size_t, double> worst_tet(const TetMesh& mesh) {
  constexpr size_t kBlock = 256;
  std::vector<double> columns(12 * kBlock), quality(kBlock);
  const TetColumns p = column_view(columns.data(), kBlock);
  size_t worst = 0;
  double lowest = 0;
  for (size_t first = 0; first < mesh.num_tets(); first += kBlock) {
    const size_t n = std::min(kBlock, mesh.num_tets() - first);
    for (size_t k = 0; k < n; ++k) {
      const uint32_t* v = &mesh.tets[4 * (first + k)];
      for (size_t c = 0; c < 12; ++c) columns[c * kBlock + k] = mesh.point(v[c / 3])[c % 3];
    }
    tet_qualities(p, n, quality.data());
    for (size_t k = 0; k < n; ++k) {
      if (first + k == 0 || quality[k] < lowest) {
        worst = first + k;
        lowest = quality[k];
      }
    }
  }
  return {worst, lowest};
}

// The whole mesh's measure `whole` with the band's tets measured `before`
// replaced by tets measured `after`: better when the band's smallest angle
// rises and neither the share under 10 degrees nor the mean radius ratio
// gets worse. `whole` becomes the new measure's counts and mean when so.
bool band_improves(QualityStats& whole, const QualityStats& before, const QualityStats& after) {
  if (!(after.min_dihedral_deg > before.min_dihedral_deg)) return false;
  const double tets = static_cast<double>(whole.tets);
  const double new_tets = tets - static_cast<double>(before.tets) + static_cast<double>(after.tets);
  const double under = static_cast<double>(whole.dihedral_under_10);
  const double new_under = under - static_cast<double>(before.dihedral_under_10) +
                           static_cast<double>(after.dihedral_under_10);
  if (new_under * tets > under * new_tets) return false;
  const double sum = whole.radius_ratio_mean * tets;
  const double new_sum = sum - before.radius_ratio_mean * static_cast<double>(before.tets) +
                         after.radius_ratio_mean * static_cast<double>(after.tets);
  if (new_sum * tets < sum * new_tets) return false;
  whole.tets = whole.tets - before.tets + after.tets;
  whole.dihedral_under_10 = whole.dihedral_under_10 - before.dihedral_under_10 + after.dihedral_under_10;
  whole.radius_ratio_mean = new_sum / new_tets;
  return true;
}

}  // namespace

RestartStats restart_around_worst(TetMesh& mesh, QualityStats& quality, const OptimizeOptions& options) {
  PARTET_ASSERT(mesh.global_ids.empty(), "restart_around_worst: a mesh without global ids");
  RestartStats stats;
  if (mesh.num_tets() == 0) return stats;
  OptimizeOptions band_options = options;
  band_options.passes = options.passes + kRestartExtraPasses;
  band_options.insert_vertices = false;
  const double bar = quality_of_angle(mesh.num_tets() <= kSmallRestartTets
                                          ? std::max(kRestartAngle, options.quality_target_deg)
                                          : kRestartAngle);
  bool changed = false;
  for (int round = 0; round < kMaxRestarts; ++round) {
    const auto [worst, lowest] = worst_tet(mesh);
    if (!(lowest < bar)) break;
    std::vector<uint8_t> marked(mesh.num_vertices(), 0);
    for (int k = 0; k < 4; ++k) marked[mesh.tets[4 * worst + static_cast<size_t>(k)]] = 1;
    const std::vector<int> ring = tet_rings(mesh, std::move(marked), kWidestRestartBand);
    bool kept = false;
    for (const int layers : kRestartLayers) {
      std::vector<int32_t> part_of_tet(mesh.num_tets(), -1);
      for (size_t t = 0; t < ring.size(); ++t)
        if (ring[t] >= 0 && ring[t] <= layers) part_of_tet[t] = 0;
      std::vector<MeshPart> parts = split_mesh(mesh, part_of_tet, 1);
      const OptimizeStats band = optimize_mesh(parts[0].mesh, band_options, &parts[0].on_cut);
      ++stats.tried;
      if (!band_improves(quality, band.before, band.after)) continue;
      join_parts(mesh, part_of_tet, parts);
      ++stats.kept;
      kept = changed = true;
      break;
    }
    if (!kept) break;
  }
  if (changed) {
    drop_unused_vertices(mesh);
    quality = measure_quality(mesh);
  }
  return stats;
}

}  // namespace partet
