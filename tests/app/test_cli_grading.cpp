// `--grading R` on the command line: the default's slower size growth
// against the plain 2:1 balance (more tets, better ones, both valid), the
// option in the report, and radii out of range as input errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace partet {
namespace {

using test::data_path;
using test::report_step;
using test::run_partet;
using test::scratch_dir;

TEST(CliGrading, TheDefaultGrowsSizesSlowerForBetterTets) {
  // sphere966 (1,848 triangles; 256 core leaves at grading 1, 312 at 2):
  // the default radius 2 keeps each size around finer octants for two
  // octants, where the plain balance lets it double after one, so fewer
  // tets sit on size transitions (mean radius ratio before optimization
  // 0.726 -> 0.743, after it 0.758 -> 0.773, for 4 % more tets).
  const std::string dir = scratch_dir("cli_grading");
  const std::string in = data_path("good/sphere966.off");
  for (const char* run : {"g1", "g2"}) {
    const std::string extra = std::string(run) == "g1" ? " --grading 1" : "";
    auto r = run_partet(in + " -o " + dir + "/" + run + ".vtu --quiet --report " + dir + "/" + run + ".json" + extra);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    auto check = run_partet("check " + dir + "/" + run + ".vtu --surface " + in);
    EXPECT_EQ(check.exit_code, 0) << check.output;
  }
  const auto plain = nlohmann::json::parse(test::read_text(dir + "/g1.json"));
  const auto graded = nlohmann::json::parse(test::read_text(dir + "/g2.json"));
  EXPECT_EQ(plain["options"]["grading"], 1);
  EXPECT_EQ(graded["options"]["grading"], 2);
  const auto count = [](const nlohmann::json& j, const char* step, const char* what) {
    return report_step(j, step)["counts"][what].get<double>();
  };
  EXPECT_GT(count(graded, "build octree", "leaves"), count(plain, "build octree", "leaves"));
  EXPECT_GT(count(graded, "optimize", "tets"), count(plain, "optimize", "tets"));
  EXPECT_GT(count(graded, "optimize", "mean radius ratio before"),
            count(plain, "optimize", "mean radius ratio before") + 0.01);
  EXPECT_GT(count(graded, "optimize", "mean radius ratio after"),
            count(plain, "optimize", "mean radius ratio after") + 0.005);
}

TEST(CliGrading, RadiiOutOfRangeAreInputErrors) {
  const std::string dir = scratch_dir("cli_grading_bad");
  for (const char* radius : {"0", "5", "-1"}) {
    auto r = run_partet(data_path("good/cube.off") + " -o " + dir + "/c.vtu --grading " + radius);
    EXPECT_EQ(r.exit_code, 2) << radius << "\n" << r.output;
    EXPECT_NE(r.output.find("--grading"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace partet
