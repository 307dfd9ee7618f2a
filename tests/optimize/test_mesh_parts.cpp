// split_mesh, join_parts, cut_vertices and band_around: a split joined
// back unchanged is the same mesh; the cut vertices are exactly those on
// the cut plane; the band grows ring by ring; and parts of a real mesh
// optimized on their own join into a valid mesh with the same boundary and
// better tets.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "check/quality.hpp"
#include "check/validate.hpp"
#include "core/compact_mesh.hpp"
#include "io/mesh_file.hpp"
#include "optimize/mesh_parts.hpp"
#include "optimize/optimize.hpp"
#include "optimize_test_util.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using test::boundary_faces;
using test::kuhn_lattice;

double centroid(const TetMesh& m, size_t t, int k) {
  double sum = 0;
  for (int i = 0; i < 4; ++i) sum += m.point(m.tets[4 * t + static_cast<size_t>(i)])[k];
  return sum / 4;
}

// Tets by x of their centroid: part floor(x / width), at most parts - 1.
std::vector<int32_t> slabs_in_x(const TetMesh& m, double width, int parts) {
  std::vector<int32_t> part(m.num_tets());
  for (size_t t = 0; t < m.num_tets(); ++t)
    part[t] = std::min(parts - 1, static_cast<int32_t>(centroid(m, t, 0) / width));
  return part;
}

// Each tet as its four corners' coordinates in vertex index order, sorted
// (the joined mesh numbers the same vertices the same way).
std::vector<std::array<double, 12>> tets_by_coordinates(const TetMesh& m) {
  std::vector<std::array<double, 12>> out;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    std::array<uint32_t, 4> v;
    std::copy_n(&m.tets[4 * t], 4, v.begin());
    std::array<double, 12> c;
    std::sort(v.begin(), v.end());
    for (int i = 0; i < 4; ++i) std::copy_n(m.point(v[static_cast<size_t>(i)]), 3, &c[3 * static_cast<size_t>(i)]);
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(MeshParts, SplitAndJoinUnchangedIsTheSameMesh) {
  const TetMesh lattice = kuhn_lattice(4);
  TetMesh mesh = lattice;
  const std::vector<int32_t> part = slabs_in_x(mesh, 4.0 / 3, 3);
  std::vector<MeshPart> parts = split_mesh(mesh, part, 3);
  ASSERT_EQ(parts.size(), 3u);
  size_t tets = 0;
  for (const MeshPart& p : parts) {
    tets += p.mesh.num_tets();
    EXPECT_TRUE(std::is_sorted(p.whole.begin(), p.whole.end()));
    EXPECT_EQ(p.mesh.num_vertices(), p.whole.size());
    for (size_t i = 0; i < p.whole.size(); ++i)
      EXPECT_TRUE(std::equal(p.mesh.point(i), p.mesh.point(i) + 3, mesh.point(p.whole[i])));
    EXPECT_TRUE(validate_mesh(p.mesh, nullptr).valid);
  }
  EXPECT_EQ(tets, mesh.num_tets());
  const std::vector<int32_t> now = join_parts(mesh, part, parts);
  EXPECT_EQ(mesh.xyz, lattice.xyz);
  EXPECT_EQ(tets_by_coordinates(mesh), tets_by_coordinates(lattice));
  ASSERT_EQ(now.size(), mesh.num_tets());
  EXPECT_TRUE(std::is_sorted(now.begin(), now.end()));  // part by part
}

TEST(MeshParts, TetsInNoPartStayAsTheyAre) {
  const TetMesh lattice = kuhn_lattice(3);
  TetMesh mesh = lattice;
  std::vector<int32_t> part = slabs_in_x(mesh, 1.5, 2);
  for (int32_t& p : part) p = p == 1 ? -1 : 0;  // only the low half is a part
  std::vector<MeshPart> parts = split_mesh(mesh, part, 1);
  const std::vector<int32_t> now = join_parts(mesh, part, parts);
  EXPECT_EQ(tets_by_coordinates(mesh), tets_by_coordinates(lattice));
  EXPECT_EQ(std::count(now.begin(), now.end(), -1), std::count(part.begin(), part.end(), -1));
}

TEST(MeshParts, CutVerticesLieOnTheCutAndTheBandGrowsByRings) {
  const TetMesh mesh = kuhn_lattice(8);
  const std::vector<int32_t> part = slabs_in_x(mesh, 4, 2);  // cut at x = 4
  const std::vector<uint8_t> cut = cut_vertices(mesh, part);
  for (size_t v = 0; v < mesh.num_vertices(); ++v) EXPECT_EQ(cut[v] != 0, mesh.point(v)[0] == 4) << v;
  size_t previous = 0;
  for (int layers = 0; layers <= 2; ++layers) {
    const std::vector<uint8_t> band = band_around(mesh, cut, layers);
    size_t n = 0;
    for (size_t t = 0; t < mesh.num_tets(); ++t) {
      n += band[t];
      // Ring k reaches centroids within k + 1 cells of the cut plane.
      if (band[t]) {
        EXPECT_LT(std::abs(centroid(mesh, t, 0) - 4), layers + 1.0) << t;
      }
    }
    EXPECT_GT(n, previous) << layers;
    previous = n;
  }
  EXPECT_LT(previous, mesh.num_tets());  // two rings reach the cells from x = 1 to 7 only
}

TEST(MeshParts, PartsOptimizedAloneJoinIntoAValidBetterMesh) {
  const std::string out = test::scratch_dir("mesh_parts") + "/eight.vtu";
  const auto r = test::run_partet(test::data_path("good/eight.off") + " -o " + out + " --no-optimize -q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  TetMesh mesh = read_volume_file(out);
  mesh.global_ids.clear();
  const TetMesh original = mesh;
  const QualityStats before = measure_quality(mesh);
  // Four slabs across the body's extent in x.
  double lo = mesh.xyz[0], hi = mesh.xyz[0];
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    lo = std::min(lo, mesh.point(v)[0]);
    hi = std::max(hi, mesh.point(v)[0]);
  }
  std::vector<int32_t> part(mesh.num_tets());
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    part[t] = std::min(3, static_cast<int32_t>(4 * (centroid(mesh, t, 0) - lo) / (hi - lo)));
  std::vector<MeshPart> parts = split_mesh(mesh, part, 4);
  size_t inserted = 0;
  for (MeshPart& p : parts) {
    ASSERT_GT(p.mesh.num_tets(), 0u);
    inserted += optimize_mesh(p.mesh, OptimizeOptions{}).vertices_inserted;
  }
  join_parts(mesh, part, parts);
  EXPECT_GT(inserted, 0u);
  // The boundary is the same faces on the same vertices, which did not move.
  EXPECT_EQ(boundary_faces(mesh), boundary_faces(original));
  for (const auto& face : boundary_faces(original))
    for (uint32_t v : face) EXPECT_TRUE(std::equal(mesh.point(v), mesh.point(v) + 3, original.point(v)));
  drop_unused_vertices(mesh);
  const SurfaceMesh surface = read_surface_file(test::data_path("good/eight.off"));
  const ValidationResult v = validate_mesh(mesh, &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  const QualityStats after = measure_quality(mesh);
  EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_LT(after.dihedral_under_10 * before.tets, before.dihedral_under_10 * after.tets);
  EXPECT_GT(after.radius_ratio_mean, before.radius_ratio_mean);
}

}  // namespace
}  // namespace partet
