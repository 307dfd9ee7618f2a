// The other pass counts: on a small front's mesh, the optimizer with every
// pass at the target, then two more passes, then one fewer (those two at
// the target too), replaces the mesh kept so far only when better in the
// optimizer's measures; the cube refined twice gets the passes at the
// target, the pipe the five passes' mesh, the cross the two passes' mesh,
// a larger mesh tries none.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "io/mesh_file.hpp"
#include "io/surface_write.hpp"
#include "pipeline/pass_alternatives.hpp"
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

TEST(PassAlternatives, BetterQualityIsNoWorseInAnyMeasureAndBetterInOne) {
  QualityStats a;
  a.tets = 100;
  a.min_dihedral_deg = 30;
  a.dihedral_under_10 = 0;
  a.radius_ratio_mean = 0.7;
  QualityStats b = a;
  EXPECT_FALSE(better_quality(a, b));
  b.min_dihedral_deg = 31;
  EXPECT_TRUE(better_quality(b, a));
  // A mean radius ratio less than kRadiusRatioSlack lower does not count
  // against a larger smallest angle; more does.
  b.radius_ratio_mean = 0.7 - kRadiusRatioSlack / 2;
  EXPECT_TRUE(better_quality(b, a));
  EXPECT_FALSE(better_quality(a, b));
  b.radius_ratio_mean = 0.7 - 2 * kRadiusRatioSlack;
  EXPECT_FALSE(better_quality(b, a));
  EXPECT_FALSE(better_quality(a, b));
  // Equal angles: a lower mean radius ratio is no gain, even within the slack.
  QualityStats d = a;
  d.radius_ratio_mean = 0.7 - kRadiusRatioSlack / 2;
  EXPECT_FALSE(better_quality(d, a));
  EXPECT_TRUE(better_quality(a, d));
  QualityStats c = a;
  c.tets = 200;
  c.dihedral_under_10 = 1;  // a larger share under 10 degrees
  c.min_dihedral_deg = 40;
  EXPECT_FALSE(better_quality(c, a));
  EXPECT_FALSE(better_quality(a, QualityStats{}));
}

double min_angle_of(const nlohmann::json& counts) {
  return (counts.contains("min dihedral after") ? counts["min dihedral after"] : counts["min dihedral"]).get<double>();
}

// The run of data surface `name` (refined `rounds` times): its report, the
// optimize step's counts (three passes) and the alternatives'; `written`
// the tets written.
struct PassRun {
  nlohmann::json report, three, target, more, fewer, written;
};

PassRun pass_run(const std::string& name, int rounds = 0) {
  PassRun r;
  const std::string dir = test::scratch_dir("pass_alternatives_" + name);
  std::string in = test::data_path("good/" + name + ".off");
  if (rounds > 0) {
    SurfaceMesh surface = read_surface_file(in);
    for (int k = 0; k < rounds; ++k) surface = refine_midpoints(surface);
    in = dir + "/refined.off";
    std::ofstream(in) << format_off(surface);
  }
  r.report = mesh_report(in, dir, name);
  r.three = report_step(r.report, "optimize")["counts"];
  r.target = report_step(r.report, "passes at the target alternative")["counts"];
  r.more = report_step(r.report, "more passes alternative")["counts"];
  r.fewer = report_step(r.report, "fewer passes alternative")["counts"];
  r.written = report_step(r.report, "write mesh")["counts"]["tets"];
  return r;
}

// Three passes with the later ones on the tets under 25 and 10 degrees
// stop at 30.2 degrees on the cube refined twice (TetGen -q: 30.4); at the
// target throughout they reach 35.3, which the other alternatives keep.
TEST(PassAlternatives, TheTwiceRefinedCubeGetsThePassesAtTheTarget) {
  const auto [report, three, target, more, fewer, written] = pass_run("cube", 2);
  EXPECT_LT(min_angle_of(three), 31);
  ASSERT_TRUE(target["kept"].get<bool>());
  EXPECT_GT(min_angle_of(target), 35);
  EXPECT_FALSE(more["kept"].get<bool>());
  EXPECT_FALSE(fewer["kept"].get<bool>());
  EXPECT_EQ(written, target["tets"]);
}

TEST(PassAlternatives, ThePipeGetsTheFivePassesMesh) {
  const auto [report, three, target, more, fewer, written] = pass_run("pipe");
  ASSERT_TRUE(more["kept"].get<bool>());
  EXPECT_EQ(more["passes"], 5);
  EXPECT_GE(min_angle_of(more), min_angle_of(three));
  EXPECT_LT(more["% under 10 deg"].get<double>(), three["% under 10 deg after"].get<double>());
  // Two passes reach five passes' smallest angle with more slivers: not
  // better than the mesh kept.
  EXPECT_FALSE(fewer["kept"].get<bool>());
  EXPECT_EQ(fewer["passes"], 2);
  EXPECT_GT(fewer["% under 10 deg"].get<double>(), more["% under 10 deg"].get<double>());
  EXPECT_EQ(written, more["tets"]);
}

TEST(PassAlternatives, TheCrossGetsTheTwoPassesMesh) {
  const auto [report, three, target, more, fewer, written] = pass_run("cross");
  EXPECT_FALSE(target["kept"].get<bool>());
  EXPECT_FALSE(more["kept"].get<bool>());
  ASSERT_TRUE(fewer["kept"].get<bool>());
  // Three passes stop near 30 degrees; two reach past 40 (Gmsh: 39.5).
  EXPECT_LT(min_angle_of(three), 35);
  EXPECT_GT(min_angle_of(fewer), 40);
  EXPECT_EQ(written, fewer["tets"]);
}

TEST(PassAlternatives, NotTriedOnLargerMeshes) {
  const auto [report, three, target, more, fewer, written] = pass_run("sphere966");
  EXPECT_TRUE(target.is_null());
  EXPECT_TRUE(more.is_null());
  EXPECT_TRUE(fewer.is_null());
  EXPECT_GT(written.get<size_t>(), kPassAlternativeTets);
}

}  // namespace
}  // namespace partet
