// The cone alternative: the cone of a star-shaped surface to its deepest
// kernel point is a valid mesh of it; it replaces the front's mesh only
// when no worse in any of the optimizer's three measures; the command line
// keeps it on the once-refined icosahedron and not on the cross.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "check/validate.hpp"
#include "io/mesh_file.hpp"
#include "pipeline/cone_alternative.hpp"
#include "surface/midpoint_refine.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::report_step;

TetMesh surface_only(const SurfaceMesh& s) {
  TetMesh m;
  m.xyz = s.xyz;
  m.tris = s.tris;
  return m;
}

TEST(ConeAlternative, TheConeOfAConvexSurfaceIsAValidMeshOfIt) {
  const SurfaceMesh box = test::box_surface(2, 1, 1);
  TetMesh cone;
  ASSERT_TRUE(cone_mesh(surface_only(box), cone));
  EXPECT_EQ(cone.num_tets(), 12u);
  EXPECT_EQ(cone.num_vertices(), 9u);
  EXPECT_EQ(cone.tris, box.tris);
  const ValidationResult r = validate_mesh(cone, &box);
  EXPECT_TRUE(r.valid) << format_text(r);
  EXPECT_DOUBLE_EQ(measure_quality(cone).volume, 2.0);
}

TEST(ConeAlternative, NoConeWhereNoPointSeesTheWholeSurface) {
  SurfaceMesh two = test::box_surface();
  test::append(two, test::shifted_box(3, 1));
  TetMesh cone;
  EXPECT_FALSE(cone_mesh(surface_only(two), cone));
  EXPECT_FALSE(cone_mesh(surface_only(read_surface_file(test::data_path("good/joint.off"))), cone));
}

TEST(ConeAlternative, KeptOnlyWhenNoWorseInAnyMeasure) {
  // The cube's cone (12 tets of 45 degrees, radius ratio 0.64) has the
  // better smallest angle but a lower radius ratio than the 6 tets around
  // a diagonal (35.3 degrees, 0.72): the mesh stays.
  TetMesh mesh = test::cube_tets();
  const TetMesh before = mesh;
  OptimizeOptions options;
  QualityStats quality = measure_quality(mesh);
  nlohmann::ordered_json c = try_cone_alternative(mesh, quality, options);
  EXPECT_TRUE(c["star-shaped"].get<bool>());
  EXPECT_FALSE(c["kept"].get<bool>());
  EXPECT_DOUBLE_EQ(c["min dihedral"].get<double>(), 45.0);
  EXPECT_EQ(mesh.tets, before.tets);
  EXPECT_EQ(mesh.xyz, before.xyz);
}

TEST(ConeAlternative, TheRefinedIcosahedronGetsItsConeAndTheCrossItsFrontMesh) {
  const std::string dir = test::scratch_dir("cone_alternative");
  const std::string ico = dir + "/icosahedron-r1.off";
  write_surface_file(refine_midpoints(read_surface_file(test::data_path("good/icosahedron.off"))), ico, {});
  auto r = test::run_partet(ico + " -o " + dir + "/i.vtu --quiet --report " + dir + "/i.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::run_partet("check " + dir + "/i.vtu --surface " + ico).exit_code, 0);
  const auto i = nlohmann::json::parse(test::read_text(dir + "/i.json"));
  const auto cone = report_step(i, "cone alternative")["counts"];
  ASSERT_TRUE(cone["kept"].get<bool>());
  // The front's mesh: over a thousand tets, its smallest angle about 34 degrees.
  EXPECT_GT(report_step(i, "cone alternative")["counts"]["min dihedral"].get<double>(),
            report_step(i, "optimize")["counts"]["min dihedral after"].get<double>() + 10);
  EXPECT_EQ(report_step(i, "write mesh")["counts"]["tets"], 80);

  const std::string cross = test::data_path("good/cross.off");
  r = test::run_partet(cross + " -o " + dir + "/c.vtu --quiet --report " + dir + "/c.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto c = nlohmann::json::parse(test::read_text(dir + "/c.json"));
  EXPECT_TRUE(report_step(c, "cone alternative")["counts"]["star-shaped"].get<bool>());
  EXPECT_FALSE(report_step(c, "cone alternative")["counts"]["kept"].get<bool>());
  // The front's mesh as the pass alternatives left it (two passes').
  EXPECT_EQ(report_step(c, "write mesh")["counts"]["tets"],
            report_step(c, "fewer passes alternative")["counts"]["tets"]);
}

TEST(ConeAlternative, NotTriedOnLargerSurfaces) {
  const std::string dir = test::scratch_dir("cone_alternative_large");
  const std::string in = test::data_path("good/sphere966.off");
  auto r = test::run_partet(in + " -o " + dir + "/s.vtu --quiet --report " + dir + "/s.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = nlohmann::json::parse(test::read_text(dir + "/s.json"));
  EXPECT_TRUE(report_step(s, "cone alternative").is_null());
}

}  // namespace
}  // namespace partet
