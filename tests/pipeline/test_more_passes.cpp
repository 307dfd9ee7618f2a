// The more-passes alternative: on a small front's mesh, the optimizer with
// two more passes replaces the optimized mesh only when better in the
// optimizer's measures; the cube refined twice gets it, the cross keeps its
// three passes' mesh, a larger mesh does not try it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "io/mesh_file.hpp"
#include "pipeline/more_passes.hpp"
#include "surface/midpoint_refine.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::report_step;

nlohmann::json mesh_report(const std::string& in, const std::string& dir, const std::string& name) {
  const std::string base = dir + "/" + name;
  const auto r = test::run_partet(in + " -o " + base + ".vtu --quiet --report " + base + ".json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::run_partet("check " + base + ".vtu --surface " + in).exit_code, 0);
  return nlohmann::json::parse(test::read_text(base + ".json"));
}

TEST(MorePasses, BetterQualityIsNoWorseInAnyMeasureAndBetterInOne) {
  QualityStats a;
  a.tets = 100;
  a.min_dihedral_deg = 30;
  a.dihedral_under_10 = 0;
  a.radius_ratio_mean = 0.7;
  QualityStats b = a;
  EXPECT_FALSE(better_quality(a, b));
  b.min_dihedral_deg = 31;
  EXPECT_TRUE(better_quality(b, a));
  b.radius_ratio_mean = 0.69;
  EXPECT_FALSE(better_quality(b, a));
  EXPECT_FALSE(better_quality(a, b));
  QualityStats c = a;
  c.tets = 200;
  c.dihedral_under_10 = 1;  // a larger share under 10 degrees
  c.min_dihedral_deg = 40;
  EXPECT_FALSE(better_quality(c, a));
  EXPECT_FALSE(better_quality(a, QualityStats{}));
}

TEST(MorePasses, TheTwiceRefinedCubeGetsTheMorePassesMesh) {
  const std::string dir = test::scratch_dir("more_passes");
  const std::string cube = dir + "/cube-r2.off";
  write_surface_file(refine_midpoints(refine_midpoints(read_surface_file(test::data_path("good/cube.off")))), cube,
                     {});
  const auto report = mesh_report(cube, dir, "cube");
  const auto more = report_step(report, "more passes alternative")["counts"];
  ASSERT_TRUE(more["kept"].get<bool>());
  EXPECT_EQ(more["passes"], 5);
  // Three passes stop under 30 degrees; five lift it past 35.
  EXPECT_LT(report_step(report, "optimize")["counts"]["min dihedral after"].get<double>(), 30);
  EXPECT_GT(more["min dihedral"].get<double>(), 35);
  EXPECT_EQ(report_step(report, "write mesh")["counts"]["tets"], more["tets"]);
}

TEST(MorePasses, TheCrossKeepsItsThreePassesMesh) {
  const std::string dir = test::scratch_dir("more_passes_cross");
  const auto report = mesh_report(test::data_path("good/cross.off"), dir, "cross");
  const auto more = report_step(report, "more passes alternative")["counts"];
  EXPECT_FALSE(more["kept"].get<bool>());
  EXPECT_LT(more["min dihedral"].get<double>(),
            report_step(report, "optimize")["counts"]["min dihedral after"].get<double>());
  EXPECT_EQ(report_step(report, "write mesh")["counts"]["tets"], report_step(report, "optimize")["counts"]["tets"]);
}

TEST(MorePasses, NotTriedOnLargerMeshes) {
  const std::string dir = test::scratch_dir("more_passes_large");
  const auto report = mesh_report(test::data_path("good/sphere966.off"), dir, "sphere");
  EXPECT_TRUE(report_step(report, "more passes alternative").is_null());
  EXPECT_GT(report_step(report, "face removals (tree)")["counts"]["tets"].get<size_t>(), kMorePassesTets);
}

}  // namespace
}  // namespace partet
