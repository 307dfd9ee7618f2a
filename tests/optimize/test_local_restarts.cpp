// restart_around_worst: the band around the worst tet optimized again is
// kept only when the whole mesh gets better (a valid mesh, the same
// boundary, a higher smallest angle, no larger share under 10 degrees, no
// lower mean radius ratio, and the measure it keeps is the mesh's); the
// same mesh twice; nothing tried on a mesh with no tet under the bar (10
// degrees, the quality target on small meshes); and partet's own run (the report step "local restarts") lifts joint's
// smallest angle past what the optimizer left.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "check/validate.hpp"
#include "io/mesh_file.hpp"
#include "optimize/local_restarts.hpp"
#include "optimize_test_util.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::boundary_faces;

// Data surface `name` meshed without the optimizer, without global ids.
TetMesh unoptimized(const std::string& name) {
  const std::string out = test::scratch_dir("local_restarts") + "/" + name + ".vtu";
  const auto r = test::run_partet(test::data_path("good/" + name + ".off") + " -o " + out + " --no-optimize -q");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  TetMesh mesh = read_volume_file(out);
  mesh.global_ids.clear();
  return mesh;
}

TEST(LocalRestarts, KeptBandsMakeTheWholeMeshBetter) {
  TetMesh mesh = unoptimized("part");
  const TetMesh original = mesh;
  const QualityStats before = measure_quality(mesh);
  ASSERT_LT(before.min_dihedral_deg, kRestartAngle);
  QualityStats quality = before;
  const RestartStats stats = restart_around_worst(mesh, quality, OptimizeOptions{});
  EXPECT_GE(stats.tried, stats.kept);
  ASSERT_GT(stats.kept, 0u);
  const SurfaceMesh surface = read_surface_file(test::data_path("good/part.off"));
  const ValidationResult v = validate_mesh(mesh, &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  EXPECT_EQ(boundary_faces(mesh).size(), boundary_faces(original).size());
  const QualityStats after = measure_quality(mesh);
  EXPECT_EQ(quality.tets, after.tets);
  EXPECT_EQ(quality.dihedral_under_10, after.dihedral_under_10);
  EXPECT_DOUBLE_EQ(quality.min_dihedral_deg, after.min_dihedral_deg);
  EXPECT_NEAR(quality.radius_ratio_mean, after.radius_ratio_mean, 1e-12);
  EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_LE(after.dihedral_under_10 * before.tets, before.dihedral_under_10 * after.tets);
  EXPECT_GE(after.radius_ratio_mean, before.radius_ratio_mean);
}

TEST(LocalRestarts, SameMeshTwice) {
  TetMesh a = unoptimized("joint"), b = a;
  QualityStats qa = measure_quality(a), qb = qa;
  const RestartStats sa = restart_around_worst(a, qa, OptimizeOptions{});
  const RestartStats sb = restart_around_worst(b, qb, OptimizeOptions{});
  EXPECT_GT(sa.tried, 0u);
  EXPECT_EQ(sa.tried, sb.tried);
  EXPECT_EQ(sa.kept, sb.kept);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.xyz, b.xyz);
}

TEST(LocalRestarts, NothingTriedWithoutATetUnderTheBar) {
  TetMesh mesh = test::kuhn_lattice(3);
  const TetMesh original = mesh;
  QualityStats quality = measure_quality(mesh);
  ASSERT_GE(quality.min_dihedral_deg, kRestartAngle);
  const RestartStats stats = restart_around_worst(mesh, quality, OptimizeOptions{});
  EXPECT_EQ(stats.tried, 0u);
  EXPECT_EQ(mesh.tets, original.tets);
  EXPECT_EQ(mesh.xyz, original.xyz);
}

// Data surface `name` meshed and optimized as partet does but for the
// restarts (the optimizer run here on the unoptimized mesh).
TetMesh optimized(const std::string& name) {
  TetMesh mesh = unoptimized(name);
  optimize_mesh(mesh, OptimizeOptions{});
  return mesh;
}

TEST(LocalRestarts, SmallMeshesGoOnUnderTheQualityTarget) {
  // The ellipsoid's 2,625 tets, optimized: no tet under 10 degrees, but
  // under the 40 of the quality target, and a band lifts the worst.
  const TetMesh mesh = optimized("ellipsoid");
  ASSERT_LE(mesh.num_tets(), kSmallRestartTets);
  const QualityStats before = measure_quality(mesh);
  ASSERT_GT(before.min_dihedral_deg, kRestartAngle);
  ASSERT_LT(before.min_dihedral_deg, OptimizeOptions{}.quality_target_deg);
  TetMesh restarted = mesh;
  QualityStats quality = before;
  const RestartStats stats = restart_around_worst(restarted, quality, OptimizeOptions{});
  EXPECT_GT(stats.kept, 0u);
  EXPECT_GT(quality.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_GE(quality.radius_ratio_mean, before.radius_ratio_mean);
  const SurfaceMesh surface = read_surface_file(test::data_path("good/ellipsoid.off"));
  EXPECT_TRUE(validate_mesh(restarted, &surface).valid);
  // With the target at 10 degrees the bar is 10: nothing to restart.
  OptimizeOptions low;
  low.quality_target_deg = 10;
  TetMesh unchanged = mesh;
  QualityStats q = before;
  EXPECT_EQ(restart_around_worst(unchanged, q, low).tried, 0u);
  EXPECT_EQ(unchanged.tets, mesh.tets);
}

TEST(LocalRestarts, LargerMeshesRestartOnlyUnderTenDegrees) {
  // sphere966's 12,621 tets, optimized: worst tet near 20 degrees.
  TetMesh mesh = optimized("sphere966");
  ASSERT_GT(mesh.num_tets(), kSmallRestartTets);
  QualityStats quality = measure_quality(mesh);
  ASSERT_GT(quality.min_dihedral_deg, kRestartAngle);
  const TetMesh original = mesh;
  EXPECT_EQ(restart_around_worst(mesh, quality, OptimizeOptions{}).tried, 0u);
  EXPECT_EQ(mesh.tets, original.tets);
}

TEST(LocalRestarts, TheRunLiftsJointsSmallestAngle) {
  const std::string dir = test::scratch_dir("local_restarts_run");
  const std::string in = test::data_path("good/joint.off");
  const auto r = test::run_partet(in + " -o " + dir + "/joint.vtu --quiet --report " + dir + "/joint.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::run_partet("check " + dir + "/joint.vtu --surface " + in).exit_code, 0);
  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir + "/joint.json"));
  const nlohmann::json restarts = test::report_step(report, "local restarts")["counts"];
  ASSERT_GT(restarts["kept"].get<int>(), 0);
  double before = test::report_step(report, "optimize")["counts"]["min dihedral after"].get<double>();
  for (const char* step : {"more passes alternative", "fewer passes alternative"}) {
    const nlohmann::json c = test::report_step(report, step)["counts"];
    if (c["kept"].get<bool>()) before = c["min dihedral"].get<double>();
  }
  EXPECT_GT(restarts["min dihedral"].get<double>(), before);
  const QualityStats written = measure_quality(read_volume_file(dir + "/joint.vtu"));
  EXPECT_NEAR(written.min_dihedral_deg, restarts["min dihedral"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace partet
