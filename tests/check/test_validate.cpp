// Tests of the mesh validator: valid cubes and grids with and without their
// surface, and deliberately broken meshes, each reported as its own kind of
// problem. Grids of Kuhn-split cubes come with a boundary surface built
// independently from the grid (numbered differently from the mesh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "check/validate.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

// The 6 Kuhn tets of a cube, as corner bits (1: +x, 2: +y, 4: +z).
constexpr uint32_t kKuhn[24] = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7,
                                0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};

struct Grid {
  TetMesh mesh;
  SurfaceMesh surface;
};

// The occupied cells of an nx x ny x nz grid of cubes of side h, each split
// into 6 Kuhn tets (conforming: every cube face is split along the diagonal
// from its lowest to its highest corner), and the outward boundary of the
// occupied cells split the same way, with the vertex numbering reversed.
Grid kuhn_grid(int nx, int ny, int nz, const std::function<bool(int, int, int)>& occupied,
               double h = 0.1) {
  Grid g;
  auto id = [&](int i, int j, int k) {
    return static_cast<uint32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  const uint32_t nv = static_cast<uint32_t>((nx + 1) * (ny + 1) * (nz + 1));
  g.mesh.xyz.resize(3 * nv);
  g.surface.xyz.resize(3 * nv);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        double p[3] = {i * h, j * h, k * h};
        std::copy(p, p + 3, &g.mesh.xyz[3 * id(i, j, k)]);
        std::copy(p, p + 3, &g.surface.xyz[3 * (nv - 1 - id(i, j, k))]);
      }
  auto inside = [&](const int c[3]) {
    return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < nx && c[1] < ny && c[2] < nz &&
           occupied(c[0], c[1], c[2]);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int cell[3] = {i, j, k};
        if (!inside(cell)) continue;
        for (uint32_t b : kKuhn)
          g.mesh.tets.push_back(id(i + (b & 1), j + (b >> 1 & 1), k + (b >> 2 & 1)));
        for (int d = 0; d < 3; ++d)
          for (int s = 0; s < 2; ++s) {
            int next[3] = {i, j, k};
            next[d] += s ? 1 : -1;
            if (inside(next)) continue;
            int u = (d + 1) % 3, w = (d + 2) % 3;
            auto corner = [&](int du, int dw) {
              int c[3] = {i, j, k};
              c[d] += s;
              c[u] += du;
              c[w] += dw;
              return nv - 1 - id(c[0], c[1], c[2]);
            };
            uint32_t lo = corner(0, 0), pu = corner(1, 0), pw = corner(0, 1), hi = corner(1, 1);
            if (s)
              g.surface.tris.insert(g.surface.tris.end(), {lo, pu, hi, lo, hi, pw});
            else
              g.surface.tris.insert(g.surface.tris.end(), {lo, hi, pu, lo, pw, hi});
          }
      }
  return g;
}

Grid full_grid(int n, double h = 0.1) {
  return kuhn_grid(
      n, n, n, [](int, int, int) { return true; }, h);
}

// The unit cube as 6 Kuhn tets with its matching surface.
Grid unit_cube() { return full_grid(1, 1.0); }

bool mentions(const ValidationResult& r, const std::string& text) {
  for (const std::string& p : r.problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

std::string all_problems(const ValidationResult& r) {
  std::string s;
  for (const std::string& p : r.problems) s += p + "\n";
  return s;
}

TEST(ValidateCube, CubeTetsValidWithoutSurface) {
  ValidationResult r = validate_mesh(test::cube_tets(), nullptr);
  EXPECT_TRUE(r.valid) << all_problems(r);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.tets, 6u);
  EXPECT_EQ(r.interior_faces, 6u);
  EXPECT_EQ(r.boundary_faces, 12u);
  EXPECT_EQ(r.unused_vertices, 0u);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_DOUBLE_EQ(r.tet_volume, 1);
  EXPECT_FALSE(r.surface_volume.has_value());
  EXPECT_EQ(r.quality.tets, 6u);
}

TEST(ValidateCube, ValidWithSurface) {
  Grid cube = unit_cube();
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_TRUE(r.valid) << all_problems(r);
  ASSERT_TRUE(r.surface_volume.has_value());
  EXPECT_DOUBLE_EQ(*r.surface_volume, 1);
  EXPECT_DOUBLE_EQ(r.tet_volume, 1);
  EXPECT_EQ(r.boundary_faces, 12u);
}

TEST(ValidateCube, NegativeZeroMatchesZeroAndDuplicateSurfaceVerticesCountAsOne) {
  Grid cube = unit_cube();
  for (double& x : cube.mesh.xyz)
    if (x == 0) x = -0.0;
  // A second surface vertex at the position of surface vertex 0, used by
  // one triangle: vertices with equal coordinates are the same point.
  cube.surface.xyz.insert(cube.surface.xyz.end(), cube.surface.xyz.begin(),
                          cube.surface.xyz.begin() + 3);
  auto it = std::find(cube.surface.tris.begin(), cube.surface.tris.end(), 0u);
  *it = static_cast<uint32_t>(cube.surface.num_vertices() - 1);
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_TRUE(r.valid) << all_problems(r);
}

TEST(ValidateCube, DifferentFaceDiagonalIsABoundaryMismatch) {
  Grid cube = unit_cube();
  // Re-split the first surface quad along its other diagonal.
  uint32_t* t = cube.surface.tris.data();  // (lo, hi, pu), (lo, pw, hi)
  uint32_t lo = t[0], hi = t[1], pu = t[2], pw = t[4];
  uint32_t resplit[6] = {lo, pw, pu, pu, pw, hi};
  std::copy(resplit, resplit + 6, t);
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "2 boundary faces are not surface triangles")) << all_problems(r);
  EXPECT_TRUE(mentions(r, "2 surface triangles are not boundary faces")) << all_problems(r);
  EXPECT_EQ(r.problems.size(), 2u) << all_problems(r);
}

TEST(ValidateCube, FlippedTet) {
  Grid cube = unit_cube();
  std::swap(cube.mesh.tets[0], cube.mesh.tets[1]);
  ValidationResult without = validate_mesh(cube.mesh, nullptr);
  EXPECT_FALSE(without.valid);
  EXPECT_TRUE(mentions(without, "1 tets are inverted (orient3d < 0): tet 0 [1 0 3 7] (1, 0, 0)"))
      << all_problems(without);
  ValidationResult with = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_TRUE(mentions(with, "inverted"));
  EXPECT_TRUE(mentions(with, "wrong orientation")) << all_problems(with);
}

TEST(ValidateCube, AllFlippedListsFiveOffenders) {
  TetMesh m = test::cube_tets();
  for (size_t t = 0; t < m.num_tets(); ++t) std::swap(m.tets[4 * t], m.tets[4 * t + 1]);
  ValidationResult r = validate_mesh(m, nullptr);
  ASSERT_TRUE(mentions(r, "6 tets are inverted")) << all_problems(r);
  const std::string& line = r.problems[0];
  EXPECT_NE(line.find("tet 4 ["), std::string::npos);
  EXPECT_EQ(line.find("tet 5 ["), std::string::npos);
  EXPECT_NE(line.find("(and 1 more)"), std::string::npos);
  EXPECT_NEAR(r.tet_volume, -1, 1e-15);
}

TEST(ValidateCube, ReversedSurfaceHasWrongOrientation) {
  Grid cube = unit_cube();
  for (size_t t = 0; t < cube.surface.num_triangles(); ++t)
    std::swap(cube.surface.tris[3 * t + 1], cube.surface.tris[3 * t + 2]);
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "12 boundary faces have the wrong orientation")) << all_problems(r);
  EXPECT_TRUE(mentions(r, "differs from the surface's enclosed volume")) << all_problems(r);
  EXPECT_DOUBLE_EQ(*r.surface_volume, -1);
}

TEST(ValidateCube, MissingTetIsClosedWithoutSurfaceButMismatchesSurface) {
  Grid cube = unit_cube();
  cube.mesh.tets.erase(cube.mesh.tets.begin(), cube.mesh.tets.begin() + 4);
  ValidationResult without = validate_mesh(cube.mesh, nullptr);
  EXPECT_TRUE(without.valid) << all_problems(without);
  EXPECT_EQ(without.boundary_faces, 12u);
  EXPECT_EQ(without.interior_faces, 4u);
  EXPECT_NEAR(without.tet_volume, 5.0 / 6, 1e-15);

  ValidationResult with = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(with.valid);
  EXPECT_TRUE(mentions(with, "2 boundary faces are not surface triangles")) << all_problems(with);
  EXPECT_TRUE(mentions(with, "2 surface triangles are not boundary faces")) << all_problems(with);
  EXPECT_TRUE(mentions(with, "differs from the surface's enclosed volume")) << all_problems(with);
}

TEST(ValidateCube, DuplicatedTet) {
  Grid cube = unit_cube();
  cube.mesh.tets.insert(cube.mesh.tets.end(), {0, 1, 3, 7});
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "1 pairs of tets are duplicates (same four vertices): tet 0 [0 1 3 7]"))
      << all_problems(r);
  EXPECT_TRUE(mentions(r, "and tet 6 [0 1 3 7]")) << all_problems(r);
  EXPECT_TRUE(mentions(r, "faces are shared by more than two tets")) << all_problems(r);
}

TEST(ValidateCube, OverlappingSeventhTet) {
  Grid cube = unit_cube();
  // (0, 1, 2, 7) is positive and overlaps the Kuhn tets around edge 0-7;
  // its face (0, 1, 7) is already shared by two of them.
  cube.mesh.tets.insert(cube.mesh.tets.end(), {0, 1, 2, 7});
  for (const SurfaceMesh* surface :
       {static_cast<const SurfaceMesh*>(nullptr), static_cast<const SurfaceMesh*>(&cube.surface)}) {
    ValidationResult r = validate_mesh(cube.mesh, surface);
    EXPECT_FALSE(r.valid);
    EXPECT_TRUE(mentions(r, "faces are shared by more than two tets")) << all_problems(r);
    EXPECT_TRUE(mentions(r, "in tets 0 5 6") || mentions(r, "in tets 5 0 6") ||
                mentions(r, "in tets 0 6 5") || mentions(r, "in tets 6 0 5") ||
                mentions(r, "in tets 5 6 0") || mentions(r, "in tets 6 5 0"))
        << all_problems(r);
  }
}

TEST(ValidateCube, MovedBoundaryVertex) {
  Grid cube = unit_cube();
  cube.mesh.xyz[3 * 6 + 2] = 1.25;  // vertex 6 = (0, 1, 1) moves outward
  ValidationResult without = validate_mesh(cube.mesh, nullptr);
  EXPECT_TRUE(without.valid) << all_problems(without);
  ValidationResult with = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(with.valid);
  EXPECT_TRUE(mentions(with, "boundary faces are not surface triangles")) << all_problems(with);
  EXPECT_TRUE(mentions(with, "surface triangles are not boundary faces")) << all_problems(with);
  EXPECT_TRUE(mentions(with, "(0, 1, 1.25)")) << all_problems(with);
}

TEST(ValidateCube, OutOfRangeIndex) {
  Grid cube = unit_cube();
  cube.mesh.tets[4 * 3 + 2] = 99;
  ValidationResult r = validate_mesh(cube.mesh, &cube.surface);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "1 tets have a vertex index out of range (8 vertices): tet 3 [0 6 99 7]"))
      << all_problems(r);
  EXPECT_TRUE(mentions(r, "out of range (1, 1, 1)")) << all_problems(r);
  EXPECT_EQ(r.quality.tets, 5u);
}

TEST(ValidateCube, NaNCoordinate) {
  Grid cube = unit_cube();
  cube.mesh.xyz[3 * 4 + 1] = std::numeric_limits<double>::quiet_NaN();
  ValidationResult r = validate_mesh(cube.mesh, nullptr);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "1 vertices have a NaN or infinite coordinate: vertex 4 (0, nan, 1)"))
      << all_problems(r);
  EXPECT_EQ(r.quality.tets, 4u);
  EXPECT_FALSE(std::isnan(r.tet_volume));
  nlohmann::json j = r;
  EXPECT_NO_THROW(static_cast<void>(j.dump()));
}

TEST(ValidateFold, TwoTetsOnTheSameSideOfTheirSharedFace) {
  // Both tets positive, sharing face (0, 1, 2) with both apexes above it.
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 2};
  m.tets = {0, 1, 2, 3, 0, 1, 2, 4};
  ValidationResult r = validate_mesh(m, nullptr);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "1 pairs of tets lie on the same side of their shared face: tet 0"))
      << all_problems(r);
  EXPECT_TRUE(mentions(r, "boundary edges are open")) << all_problems(r);
  EXPECT_FALSE(mentions(r, "inverted"));
}

TEST(ValidateFold, FlatAndRepeatedVertexTetsAreDegenerate) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  m.tets = {0, 1, 2, 3, 0, 1, 2, 2};
  ValidationResult r = validate_mesh(m, nullptr);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(mentions(r, "2 tets are degenerate (zero volume, orient3d = 0): tet 0 [0 1 2 3]"))
      << all_problems(r);
  EXPECT_FALSE(mentions(r, "duplicates")) << all_problems(r);
  EXPECT_EQ(r.quality.radius_ratio_min, 0);
  EXPECT_EQ(r.quality.dihedral_under_5, 2u);
}

TEST(ValidateCube, RefinedByCentroidsIsValidWithSurface) {
  Grid cube = unit_cube();
  TetMesh refined;
  refined.xyz = cube.mesh.xyz;
  for (size_t t = 0; t < cube.mesh.num_tets(); ++t) {
    const uint32_t* v = &cube.mesh.tets[4 * t];
    uint32_t centre = static_cast<uint32_t>(refined.num_vertices());
    for (int k = 0; k < 3; ++k)
      refined.xyz.push_back((cube.mesh.point(v[0])[k] + cube.mesh.point(v[1])[k] +
                             cube.mesh.point(v[2])[k] + cube.mesh.point(v[3])[k]) /
                            4);
    for (int replaced = 0; replaced < 4; ++replaced)
      for (int k = 0; k < 4; ++k) refined.tets.push_back(k == replaced ? centre : v[k]);
  }
  ValidationResult r = validate_mesh(refined, &cube.surface);
  EXPECT_TRUE(r.valid) << all_problems(r);
  EXPECT_EQ(r.tets, 24u);
  EXPECT_EQ(r.boundary_faces, 12u);
  EXPECT_EQ(r.interior_faces, 42u);
  EXPECT_NEAR(r.tet_volume, 1, 1e-15);
}

TEST(ValidateGrid, TwentyCubedKuhnGridIsValid) {
  Grid g = full_grid(20);
  ASSERT_EQ(g.mesh.num_tets(), 48000u);
  ValidationResult with = validate_mesh(g.mesh, &g.surface);
  EXPECT_TRUE(with.valid) << all_problems(with);
  EXPECT_EQ(with.boundary_faces, 4800u);
  EXPECT_EQ(with.interior_faces, 93600u);
  EXPECT_NEAR(with.tet_volume, 8, 1e-12);
  EXPECT_NEAR(*with.surface_volume, 8, 1e-12);
  EXPECT_NEAR(with.quality.min_dihedral_deg, 45, 1e-9);
  ValidationResult without = validate_mesh(g.mesh, nullptr);
  EXPECT_TRUE(without.valid) << all_problems(without);
}

TEST(ValidateGrid, RemovedInteriorTetIsAHoleAgainstTheSurface) {
  Grid g = full_grid(20);
  size_t cell = 10 + 20 * (10 + 20 * 10);
  auto first = g.mesh.tets.begin() + static_cast<std::ptrdiff_t>(4 * 6 * cell);
  g.mesh.tets.erase(first, first + 4);
  ValidationResult without = validate_mesh(g.mesh, nullptr);
  EXPECT_TRUE(without.valid) << all_problems(without);
  EXPECT_EQ(without.boundary_faces, 4804u);
  ValidationResult with = validate_mesh(g.mesh, &g.surface);
  EXPECT_FALSE(with.valid);
  EXPECT_TRUE(mentions(with, "4 boundary faces are not surface triangles")) << all_problems(with);
  EXPECT_TRUE(mentions(with, "differs from the surface's enclosed volume")) << all_problems(with);
  EXPECT_FALSE(mentions(with, "surface triangles are not boundary faces")) << all_problems(with);
}

TEST(ValidateGrid, CubesTouchingAlongAnEdgeAreValidWithWarnings) {
  Grid g = kuhn_grid(2, 2, 1, [](int i, int j, int) { return i == j; });
  for (const SurfaceMesh* surface :
       {static_cast<const SurfaceMesh*>(nullptr), static_cast<const SurfaceMesh*>(&g.surface)}) {
    ValidationResult r = validate_mesh(g.mesh, surface);
    EXPECT_TRUE(r.valid) << all_problems(r);
    EXPECT_EQ(r.unused_vertices, 4u);
    EXPECT_NEAR(r.tet_volume, 0.002, 1e-15);
  }
  ValidationResult r = validate_mesh(g.mesh, nullptr);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_NE(r.warnings[0].find("1 boundary edges are non-manifold"), std::string::npos);
  EXPECT_NE(r.warnings[1].find("4 vertices are not used by any tet"), std::string::npos);
}

TEST(ValidateReport, JsonAndText) {
  Grid cube = unit_cube();
  ValidationResult good = validate_mesh(cube.mesh, &cube.surface);
  nlohmann::json j = good;
  EXPECT_EQ(j["valid"], true);
  EXPECT_EQ(j["tets"], 6);
  EXPECT_EQ(j["boundary_faces"], 12);
  EXPECT_EQ(j["interior_faces"], 6);
  EXPECT_DOUBLE_EQ(j["surface_volume"].get<double>(), 1);
  EXPECT_EQ(j["quality"]["tets"], 6);
  EXPECT_TRUE(j["problems"].empty());
  std::string text = format_text(good);
  EXPECT_EQ(text.rfind("VALID\n", 0), 0u) << text;
  EXPECT_NE(text.find("surface volume"), std::string::npos) << text;
  EXPECT_NE(text.find("dihedral angle   min 45  max 90 degrees"), std::string::npos) << text;

  cube.mesh.tets.resize(20);
  ValidationResult bad = validate_mesh(cube.mesh, nullptr);
  nlohmann::json jb = bad;
  EXPECT_EQ(jb["valid"], bad.valid);
  EXPECT_TRUE(jb["surface_volume"].is_null());
  std::string bad_text = format_text(bad);
  EXPECT_EQ(bad.valid, bad_text.rfind("VALID\n", 0) == 0) << bad_text;
}

}  // namespace
}  // namespace partet
