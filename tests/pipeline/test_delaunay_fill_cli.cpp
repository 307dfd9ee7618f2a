// The Delaunay fill on the command line (front/delaunay_fill.hpp): past
// kDelaunayFillTriangles the report has the step, the removals close what
// it leaves, the mesh is valid with the exact boundary and the same twice;
// --no-delaunay-fill leaves the whole gap to the removals; smaller surfaces
// are not filled.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "front/delaunay_fill.hpp"
#include "io/mesh_file.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

nlohmann::json run_report(const std::string& in, const std::string& out, const std::string& extra) {
  const auto r = run_partet(in + " -o " + out + ".vtu -q --report " + out + ".json " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(run_partet("check " + out + ".vtu --surface " + in).exit_code, 0) << in << " " << extra;
  return nlohmann::json::parse(read_text(out + ".json"));
}

TEST(DelaunayFillCli, FillsLargerSurfacesAndCanBeTurnedOff) {
  const std::string dir = scratch_dir("fill_cli");
  const std::string in = data_path("good/spool.off");
  ASSERT_GT(read_surface_file(in).num_triangles(), kDelaunayFillTriangles);
  const nlohmann::json on = run_report(in, dir + "/on", "");
  const nlohmann::json fill = report_step(on, "delaunay fill");
  ASSERT_FALSE(fill.is_null());
  const auto& c = fill["counts"];
  EXPECT_GT(c["kept tets"].get<size_t>(), c["delaunay tets"].get<size_t>() / 2);
  EXPECT_LT(report_step(on, "face removals (tree)")["counts"]["tets"].get<size_t>(), c["kept tets"].get<size_t>());
  EXPECT_EQ(on["options"]["delaunay_fill"], true);
  run_report(in, dir + "/again", "");
  EXPECT_EQ(read_text(dir + "/on.vtu"), read_text(dir + "/again.vtu"));
  const nlohmann::json off = run_report(in, dir + "/off", "--no-delaunay-fill");
  EXPECT_TRUE(report_step(off, "delaunay fill").is_null());
  EXPECT_EQ(off["options"]["delaunay_fill"], false);
  EXPECT_GT(report_step(off, "face removals (tree)")["counts"]["tets"].get<size_t>(),
            report_step(on, "face removals (tree)")["counts"]["tets"].get<size_t>());
}

TEST(DelaunayFillCli, SmallSurfacesAreLeftToTheRemovals) {
  const std::string dir = scratch_dir("fill_cli_small");
  const std::string in = data_path("good/dragknob.off");
  ASSERT_LE(read_surface_file(in).num_triangles(), kDelaunayFillTriangles);
  EXPECT_TRUE(report_step(run_report(in, dir + "/d", ""), "delaunay fill").is_null());
}

}  // namespace
}  // namespace partet::test
