// Surface diagnosis on the bundled corpus files and on generated cases:
// every refusal names the problem, accepted surfaces come out oriented.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "io/mesh_file.hpp"
#include "surface/diagnose.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::append;
using test::box_surface;
using test::data_path;
using test::shifted_box;

void flip_all(SurfaceMesh& s) {
  for (size_t t = 0; t < s.num_triangles(); ++t) std::swap(s.tris[3 * t + 1], s.tris[3 * t + 2]);
}

// True when triangle t's normal points away from `p`.
bool faces_outward_from(const SurfaceMesh& s, size_t t, const double* p) {
  const uint32_t* v = &s.tris[3 * t];
  return orient3d(s.point(v[0]), s.point(v[1]), s.point(v[2]), p) < 0;
}

std::string diagnosis_error(SurfaceMesh s) {
  try {
    diagnose_surface(s, "gen.off");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Diagnose, GoodCorpusFilesAreAccepted) {
  for (const auto& entry : std::filesystem::directory_iterator(data_path("good"))) {
    SCOPED_TRACE(entry.path().string());
    SurfaceMesh s = read_surface_file(entry.path().string());
    SurfaceSummary sum = diagnose_surface(s, entry.path().string());
    EXPECT_GE(sum.shells, 1u);
    EXPECT_GT(sum.volume, 0.0);
  }
}

TEST(Diagnose, FixableFilesAreReorientedWithANote) {
  for (const char* name : {"fixable/tet-shuffled.off", "fixable/blobby-shuffled.off"}) {
    SCOPED_TRACE(name);
    SurfaceMesh s = read_surface_file(data_path(name));
    SurfaceSummary sum = diagnose_surface(s, name);
    EXPECT_GT(sum.reoriented, 0u);
    ASSERT_FALSE(sum.notes.empty());
    EXPECT_NE(sum.notes.back().find("reoriented"), std::string::npos);
    EXPECT_GT(sum.volume, 0.0);
    // Diagnosing again changes nothing.
    SurfaceSummary again = diagnose_surface(s, name);
    EXPECT_EQ(again.reoriented, 0u);
  }
}

TEST(Diagnose, BadCorpusFilesAreRefusedWithTheirReason) {
  struct Case {
    const char* file;
    const char* reason;
  };
  for (Case c : {Case{"bad/holes.off", "open edges"}, Case{"bad/mushroom.off", "open edges"},
                 Case{"bad/surface1.stl", "open edges"}, Case{"bad/object.stl", "open edges"},
                 Case{"bad/object.stl", "intersecting triangles"},
                 Case{"bad/cow.off", "intersect"}, Case{"bad/elk.off", "intersect"},
                 Case{"bad/cube_quad.off", "4 vertices"}}) {
    SCOPED_TRACE(c.file);
    std::string path = data_path(c.file);
    try {
      SurfaceMesh s = read_surface_file(path);
      diagnose_surface(s, path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      std::string what = e.what();
      EXPECT_NE(what.find(c.reason), std::string::npos) << what;
      EXPECT_NE(what.find(path), std::string::npos) << what;
    }
  }
}

TEST(Diagnose, BoxIsAcceptedWithItsVolume) {
  SurfaceMesh s = box_surface(2, 3, 4);
  SurfaceSummary sum = diagnose_surface(s, "box");
  EXPECT_EQ(sum.shells, 1u);
  EXPECT_EQ(sum.cavities, 0u);
  EXPECT_EQ(sum.reoriented, 0u);
  EXPECT_EQ(sum.edges, 18u);
  EXPECT_DOUBLE_EQ(sum.volume, 24.0);
  EXPECT_EQ(sum.bbox[3], 2.0);
}

// A tet 1e-18 high across 0.27 (the cavity a 2-rank run left on
// stress-check seed 1790): positive by exact orient3d, but its volume's
// sign in doubles is rounding, so it would be oriented by a guess. Either
// way round it is refused as flat.
TEST(Diagnose, ShellFlatToDoublesIsRefused) {
  SurfaceMesh s = test::flat_tet_of_seed_1790();
  ASSERT_NE(orient3d(s.point(0), s.point(1), s.point(2), s.point(3)), 0);
  EXPECT_NE(diagnosis_error(s).find("it is flat"), std::string::npos);
  flip_all(s);
  EXPECT_NE(diagnosis_error(s).find("it is flat"), std::string::npos);
}

TEST(Diagnose, InwardBoxIsTurnedOutward) {
  SurfaceMesh s = box_surface();
  flip_all(s);
  SurfaceSummary sum = diagnose_surface(s, "box");
  EXPECT_EQ(sum.reoriented, 12u);
  EXPECT_DOUBLE_EQ(sum.volume, 1.0);
  double centre[3] = {0.5, 0.5, 0.5};
  for (size_t t = 0; t < s.num_triangles(); ++t) EXPECT_TRUE(faces_outward_from(s, t, centre));
}

TEST(Diagnose, NanCoordinatesAreNamed) {
  SurfaceMesh s = box_surface();
  s.xyz[3 * 5 + 1] = std::nan("");
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("NaN"), std::string::npos);
  EXPECT_NE(e.find("vertex 5"), std::string::npos);
}

TEST(Diagnose, DegenerateTrianglesAreNamed) {
  SurfaceMesh s = box_surface();
  // A vertex on the segment between two others: an exactly collinear triangle.
  s.xyz.insert(s.xyz.end(), {0.5, 0.0, 0.0});
  s.tris.insert(s.tris.end(), {0, 1, 8});
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("degenerate"), std::string::npos) << e;
  EXPECT_NE(e.find("triangle 12"), std::string::npos) << e;
}

TEST(Diagnose, DuplicateTrianglesAreNamed) {
  SurfaceMesh s = box_surface();
  s.tris.insert(s.tris.end(), {0, 1, 3});  // triangle 0 (0, 3, 1) reversed
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("duplicate"), std::string::npos) << e;
}

TEST(Diagnose, OpenEdgesAreNamed) {
  SurfaceMesh s = box_surface();
  s.tris.resize(s.tris.size() - 3);
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("3 open edges"), std::string::npos) << e;
  EXPECT_NE(e.find("holes"), std::string::npos) << e;
}

TEST(Diagnose, NonManifoldEdgesAreRefusedForNow) {
  // Two boxes sharing the edge x = y = 1 (same vertex ids): four triangles on it.
  SurfaceMesh s = box_surface();
  SurfaceMesh t = box_surface();
  for (size_t v = 0; v < t.num_vertices(); ++v) {
    t.xyz[3 * v] += 1.0;
    t.xyz[3 * v + 1] += 1.0;
  }
  uint32_t base = static_cast<uint32_t>(s.num_vertices());
  append(s, t);
  for (uint32_t& v : s.tris) {
    if (v == base) v = 3;      // (1, 1, 0)
    if (v == base + 4) v = 7;  // (1, 1, 1)
  }
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("non-manifold edges"), std::string::npos) << e;
  EXPECT_NE(e.find("not supported yet"), std::string::npos) << e;
}

TEST(Diagnose, PinchedVerticesAreNamed) {
  // Two boxes touching at one corner (the same vertex id).
  SurfaceMesh s = box_surface();
  SurfaceMesh t = shifted_box(1, 1);
  uint32_t base = static_cast<uint32_t>(s.num_vertices());
  append(s, t);
  for (uint32_t& v : s.tris)
    if (v == base) v = 7;  // t's corner (1,1,1) is s's vertex 7
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("non-manifold vertices"), std::string::npos) << e;
  EXPECT_NE(e.find("vertex 7"), std::string::npos) << e;
}

TEST(Diagnose, CornerTouchWithTwoVertexIdsIsAnIntersection) {
  SurfaceMesh s = box_surface();
  append(s, shifted_box(1, 1));
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("intersect"), std::string::npos) << e;
}

TEST(Diagnose, OverlappingBoxesIntersect) {
  SurfaceMesh s = box_surface();
  append(s, shifted_box(0.5, 1));
  std::string e = diagnosis_error(s);
  EXPECT_NE(e.find("intersecting triangles"), std::string::npos) << e;
}

TEST(Diagnose, BallWithCavityIsOrientedByNesting) {
  SurfaceMesh s = shifted_box(0, 4);
  SurfaceMesh inner = shifted_box(1, 2);  // given outward: must face into the cavity
  append(s, inner);
  SurfaceSummary sum = diagnose_surface(s, "cavity");
  EXPECT_EQ(sum.shells, 2u);
  EXPECT_EQ(sum.cavities, 1u);
  EXPECT_EQ(sum.reoriented, 12u);
  EXPECT_DOUBLE_EQ(sum.volume, 64.0 - 8.0);
  // Outer triangles face away from the body, cavity triangles into the cavity.
  double centre[3] = {2, 2, 2};
  for (size_t t = 0; t < 12; ++t) EXPECT_TRUE(faces_outward_from(s, t, centre));
  for (size_t t = 12; t < 24; ++t) EXPECT_FALSE(faces_outward_from(s, t, centre));
}

TEST(Diagnose, BodyWithThreeCavities) {
  SurfaceMesh s = shifted_box(0, 10);
  flip_all(s);
  append(s, shifted_box(1, 2));
  append(s, shifted_box(4, 2));
  append(s, shifted_box(7, 2.5));
  SurfaceSummary sum = diagnose_surface(s, "three");
  EXPECT_EQ(sum.shells, 4u);
  EXPECT_EQ(sum.cavities, 3u);
  EXPECT_DOUBLE_EQ(sum.volume, 1000.0 - 8.0 - 8.0 - 15.625);
}

TEST(Diagnose, IslandInsideCavityBoundsMaterialAgain) {
  SurfaceMesh s = shifted_box(0, 10);
  append(s, shifted_box(2, 6));  // cavity
  SurfaceMesh island = shifted_box(4, 2);
  flip_all(island);
  append(s, island);  // material inside the cavity
  SurfaceSummary sum = diagnose_surface(s, "island");
  EXPECT_EQ(sum.shells, 3u);
  EXPECT_EQ(sum.cavities, 1u);
  EXPECT_DOUBLE_EQ(sum.volume, 1000.0 - 216.0 + 8.0);
}

TEST(Diagnose, TwoDisjointBodies) {
  SurfaceMesh s = box_surface();
  SurfaceMesh other = shifted_box(3, 1);
  flip_all(other);
  append(s, other);
  SurfaceSummary sum = diagnose_surface(s, "two");
  EXPECT_EQ(sum.shells, 2u);
  EXPECT_EQ(sum.cavities, 0u);
  EXPECT_EQ(sum.reoriented, 12u);
  EXPECT_DOUBLE_EQ(sum.volume, 2.0);
}

TEST(Diagnose, UnusedVerticesAreDroppedWithANote) {
  SurfaceMesh s = box_surface();
  s.xyz.insert(s.xyz.begin(), {9, 9, 9});
  for (uint32_t& v : s.tris) ++v;
  SurfaceSummary sum = diagnose_surface(s, "extra");
  EXPECT_EQ(sum.unused_vertices, 1u);
  EXPECT_EQ(s.num_vertices(), 8u);
  EXPECT_EQ(s.xyz[0], 0.0);
}

}  // namespace
}  // namespace partet
