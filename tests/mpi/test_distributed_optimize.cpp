// The optimizer on the ranks' parts (optimize_distributed) on 1, 2 and 4
// ranks: from the same unoptimized mesh the result is valid against the
// surface, its boundary is the same triangles on the same points, it is
// better than before (smallest angle, share under 10 degrees, mean radius
// ratio), every rank had a part, and a second run gives the same mesh;
// the whole command on P ranks reports the parts, the band and the tets
// along its shares' cuts (the band optimized on the ranks too), writes the
// same file twice, and writes a .pvtu as one balanced piece per rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "check/quality.hpp"
#include "check/validate.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "parallel/comm.hpp"
#include "parallel/distributed_optimize.hpp"
#include "pipeline/mesh_command.hpp"
#include "mpi/mpi_scratch.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::shared_dir;

MeshOptions mesh_options(const std::string& surface, const std::string& output) {
  MeshOptions o;
  o.input = test::data_path(surface);
  o.output = output;
  o.quiet = true;
  return o;
}

// The faces of one tet, as sorted coordinate triples of their corners.
std::vector<std::array<double, 9>> boundary_points(const TetMesh& m) {
  std::vector<std::array<uint32_t, 3>> faces;
  for (size_t t = 0; t < m.num_tets(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<uint32_t, 3> f;
      for (int i = 0, k = 0; i < 4; ++i)
        if (i != skip) f[static_cast<size_t>(k++)] = m.tets[4 * t + static_cast<size_t>(i)];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<double, 9>> out;
  for (size_t i = 0; i < faces.size(); ++i) {
    const bool twin = (i > 0 && faces[i - 1] == faces[i]) || (i + 1 < faces.size() && faces[i + 1] == faces[i]);
    if (twin) continue;
    std::array<std::array<double, 3>, 3> corners;
    for (size_t k = 0; k < 3; ++k) std::copy_n(m.point(faces[i][k]), 3, corners[k].begin());
    std::sort(corners.begin(), corners.end());
    std::array<double, 9> flat;
    for (size_t k = 0; k < 3; ++k) std::copy_n(corners[k].begin(), 3, &flat[3 * k]);
    out.push_back(flat);
  }
  std::sort(out.begin(), out.end());
  return out;
}

class DistributedOptimize : public testing::TestWithParam<const char*> {};

TEST_P(DistributedOptimize, ValidBetterSameBoundaryEveryRankHasAPart) {
  const Comm comm = Comm::world();
  const Log log(comm.rank(), false, false);
  const std::string dir = shared_dir(comm, "optimize");
  MeshOptions raw = mesh_options(GetParam(), dir + "/raw.vtu");
  raw.optimize_passes = 0;
  ASSERT_EQ(run_mesh(raw, comm, log), kExitOk);
  TetMesh mesh;
  if (comm.rank() == 0) {
    mesh = read_volume_file(raw.output);
    mesh.global_ids.clear();
  }
  const TetMesh original = mesh;
  const DistributedOptimizeStats stats = optimize_distributed(comm, mesh, OptimizeOptions{});
  ASSERT_EQ(stats.tets_per_rank.size(), static_cast<size_t>(comm.size()));
  for (int64_t tets : stats.tets_per_rank) EXPECT_GT(tets, 0);
  TetMesh again = original;
  optimize_distributed(comm, again, OptimizeOptions{});
  if (comm.rank() != 0) {
    EXPECT_EQ(mesh.num_tets(), 0u);
    return;
  }
  EXPECT_EQ(std::accumulate(stats.tets_per_rank.begin(), stats.tets_per_rank.end(), int64_t{0}),
            static_cast<int64_t>(original.num_tets()));
  if (comm.size() > 1) {
    // The band is optimized in shares on the ranks, then rank 0 takes the
    // tets along the shares' cuts (and the band's tets still under 2
    // degrees: on these small CAD meshes, most of it; the shares'
    // insertions can make it more tets than the band had).
    EXPECT_GT(stats.band_tets, 0u);
    EXPECT_GT(stats.crossing_tets, 0u);
  }
  const SurfaceMesh surface = read_surface_file(test::data_path(GetParam()));
  const ValidationResult v = validate_mesh(mesh, &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  EXPECT_EQ(v.unused_vertices, 0u);
  EXPECT_EQ(boundary_points(mesh), boundary_points(original));
  const QualityStats before = measure_quality(original), after = measure_quality(mesh);
  EXPECT_EQ(stats.totals.before.tets, before.tets);
  EXPECT_EQ(stats.totals.after.tets, after.tets);
  EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_LT(after.dihedral_under_10 * before.tets, before.dihedral_under_10 * after.tets);
  EXPECT_GT(after.radius_ratio_mean, before.radius_ratio_mean);
  EXPECT_EQ(again.xyz, mesh.xyz);
  EXPECT_EQ(again.tets, mesh.tets);
}

TEST_P(DistributedOptimize, TheCommandReportsThePartsAndWritesTheSameMeshTwice) {
  const Comm comm = Comm::world();
  const Log log(comm.rank(), false, false);
  const std::string dir = shared_dir(comm, "optimize_command");
  for (const char* name : {"a", "b"}) {
    MeshOptions o = mesh_options(GetParam(), dir + "/" + name + ".vtu");
    o.report = dir + "/" + name + ".json";
    ASSERT_EQ(run_mesh(o, comm, log), kExitOk);
  }
  if (comm.rank() != 0) return;
  EXPECT_EQ(test::read_text(dir + "/a.vtu"), test::read_text(dir + "/b.vtu"));
  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir + "/a.json"));
  const auto& steps = report["steps"];
  const auto optimize = std::find_if(steps.begin(), steps.end(), [](const auto& s) { return s["name"] == "optimize"; });
  ASSERT_NE(optimize, steps.end());
  const auto& counts = (*optimize)["counts"];
  EXPECT_EQ((*optimize)["cpu_s"].size(), static_cast<size_t>(comm.size()));
  if (comm.size() > 1) {
    ASSERT_TRUE(counts.contains("tets per rank"));
    EXPECT_EQ(counts["tets per rank"].size(), static_cast<size_t>(comm.size()));
    EXPECT_EQ(counts["part s per rank"].size(), static_cast<size_t>(comm.size()));
    // The phases' times, in turn, fit in the step's time (up to the skew
    // of the ranks' clocks, well under 10 ms).
    double slowest_part = 0;
    for (const auto& s : counts["part s per rank"]) slowest_part = std::max(slowest_part, s.get<double>());
    const double split = counts["split s"].get<double>(), join = counts["join s"].get<double>();
    EXPECT_GE(split, 0);
    EXPECT_GE(join, 0);
    EXPECT_LE(split + slowest_part + join + counts["band s"].get<double>(),
              (*optimize)["wall_s"][0].get<double>() + 0.01);
    EXPECT_GT(counts["band tets"].get<int64_t>(), 0);
    EXPECT_GT(counts["crossing tets"].get<int64_t>(), 0);
  } else {
    EXPECT_FALSE(counts.contains("band tets"));
  }
  const SurfaceMesh surface = read_surface_file(test::data_path(GetParam()));
  const ValidationResult v = validate_mesh(read_volume_file(dir + "/a.vtu"), &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
}

// A .pvtu is written in one piece per rank, of equal tet counts (within
// one), which together are the mesh the one-file output holds.
TEST_P(DistributedOptimize, PvtuPiecesAreTheRanksBalancedParts) {
  const Comm comm = Comm::world();
  const Log log(comm.rank(), false, false);
  const std::string dir = shared_dir(comm, "optimize_pieces");
  ASSERT_EQ(run_mesh(mesh_options(GetParam(), dir + "/one.vtu"), comm, log), kExitOk);
  ASSERT_EQ(run_mesh(mesh_options(GetParam(), dir + "/pieces.pvtu"), comm, log), kExitOk);
  if (comm.rank() != 0) return;
  const TetMesh one = read_volume_file(dir + "/one.vtu");
  const TetMesh pieces = read_volume_file(dir + "/pieces.pvtu");
  EXPECT_EQ(pieces.num_tets(), one.num_tets());
  EXPECT_EQ(boundary_points(pieces), boundary_points(one));
  const SurfaceMesh surface = read_surface_file(test::data_path(GetParam()));
  const ValidationResult v = validate_mesh(pieces, &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  size_t fewest = one.num_tets(), most = 0;
  for (int r = 0; r < comm.size(); ++r) {
    const TetMesh piece = read_volume_file(pvtu_piece_path(dir + "/pieces.pvtu", r));
    fewest = std::min(fewest, piece.num_tets());
    most = std::max(most, piece.num_tets());
    // Pieces of several ranks number their vertices by the whole mesh's.
    EXPECT_EQ(piece.global_ids.size(), comm.size() > 1 ? piece.num_vertices() : 0) << r;
  }
  EXPECT_LE(most - fewest, 1u);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, DistributedOptimize, testing::Values("good/eight.off", "good/pipe.off"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param).substr(5, std::string(info.param).find('.') - 5);
                         });

}  // namespace
}  // namespace partet
