// delaunay_fill (front/delaunay_fill.hpp) on corpus surfaces, a refined
// one and generated shells (two bodies, a body with a cavity): every kept
// tet is positive, lies inside the surface and meets no input triangle
// beyond what it shares with it (checked by brute force); the front left
// is closed; the face removals close it into a valid mesh whose boundary
// is exactly the surface; the same input gives the same fill.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "check/validate.hpp"
#include "core/predicates.hpp"
#include "delaunay/tet_triangle_contact.hpp"
#include "front/delaunay_fill.hpp"
#include "front_case.hpp"
#include "surface/midpoint_refine.hpp"
#include "test_support.hpp"

namespace partet::test {
namespace {

// No kept tet meets an input triangle beyond their shared vertices. (That
// they lie inside, the validation of the closed mesh shows: its volume is
// the surface's.)
void expect_clear_of_the_surface(const TetMesh& kept, const SurfaceMesh& surface, size_t core_vertices,
                                 const std::string& name) {
  for (size_t t = 0; t < kept.num_tets(); ++t) {
    const uint32_t* v = &kept.tets[4 * t];
    const double* p[4] = {kept.point(v[0]), kept.point(v[1]), kept.point(v[2]), kept.point(v[3])};
    ASSERT_GT(orient3d(p[0], p[1], p[2], p[3]), 0) << name << " tet " << t;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min({p[0][k], p[1][k], p[2][k], p[3][k]});
      hi[k] = std::max({p[0][k], p[1][k], p[2][k], p[3][k]});
    }
    for (size_t s = 0; s < surface.num_triangles(); ++s) {
      uint32_t ids[3];
      const double* q[3];
      bool apart = false;
      for (int k = 0; k < 3; ++k) {
        ids[k] = static_cast<uint32_t>(core_vertices + surface.tris[3 * s + k]);
        q[k] = surface.point(surface.tris[3 * s + k]);
      }
      for (int k = 0; k < 3 && !apart; ++k)
        apart = std::max({q[0][k], q[1][k], q[2][k]}) < lo[k] || std::min({q[0][k], q[1][k], q[2][k]}) > hi[k];
      if (!apart) {
        ASSERT_FALSE(tet_meets_triangle_beyond_shared(p, v, q, ids)) << name << " tet " << t << " triangle " << s;
      }
    }
  }
}

// Every front edge is used once in each direction per pair of faces.
void expect_closed(const InitialFront& front, const std::string& name) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t f = 0; f < front.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) ++directed[{front.faces[3 * f + k], front.faces[3 * f + (k + 1) % 3]}];
  for (const auto& [edge, uses] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    ASSERT_TRUE(back != directed.end()) << name << " edge " << edge.first << "-" << edge.second;
    EXPECT_EQ(back->second, uses) << name;
  }
}

// Fills, checks the fill, closes the rest with the removals and checks the
// mesh; `keeps`: some tets are kept.
DelaunayFillCounts fill_and_close(FrontCase c, const std::string& name, bool keeps = true) {
  TetMesh mesh = c.b.core.mesh;
  const DelaunayFillCounts n = delaunay_fill(c.initial, c.b.tree, mesh);
  EXPECT_EQ(mesh.num_tets(), n.kept_tets) << name;
  EXPECT_EQ(n.kept_tets > 0, keeps) << name;
  EXPECT_EQ(mesh.xyz, c.initial.xyz) << name;
  expect_clear_of_the_surface(mesh, c.b.surface, c.initial.core_vertices, name);
  expect_closed(c.initial, name);
  EXPECT_EQ(close_front(c, mesh), 0u) << name;
  mesh.tris = c.b.surface.tris;
  for (uint32_t& v : mesh.tris) v += static_cast<uint32_t>(c.initial.core_vertices);
  mesh.global_ids = {};
  const ValidationResult r = validate_mesh(mesh, &c.b.surface);
  EXPECT_TRUE(r.valid) << name << ": " << format_text(r);
  return n;
}

TEST(DelaunayFill, CorpusSurfacesCloseIntoValidMeshes) {
  size_t missing = 0, removed = 0;
  for (const char* name : {"good/sphere966.off", "good/spool.off", "good/part.off", "good/joint.off"}) {
    const DelaunayFillCounts n = fill_and_close(front_case(name), name);
    missing += n.missing_triangles;
    removed += n.removed_tets;
  }
  // The CAD parts' needle triangles are not all Delaunay faces.
  EXPECT_GT(missing, 0u);
  EXPECT_GT(removed, 0u);
}

TEST(DelaunayFill, ARefinedSurfaceClosesIntoAValidMesh) {
  const SurfaceMesh eight = refine_midpoints(read_surface_file(data_path("good/eight.off")));
  const DelaunayFillCounts n = fill_and_close(front_case_of(build_surface(eight, "eight-r1")), "eight-r1");
  // Its coplanar quads mostly hold the other diagonal: flips bring the
  // input's back (edge_recovery.hpp).
  EXPECT_GT(n.recovered_edges, 100u);
}

// `surface` scaled by `factor` about the origin and moved by `shift`.
SurfaceMesh moved(SurfaceMesh surface, double factor, double shift) {
  for (double& x : surface.xyz) x = factor * x + shift;
  return surface;
}

TEST(DelaunayFill, TwoBodiesAndABodyWithACavity) {
  const SurfaceMesh sphere = read_surface_file(data_path("good/sphere966.off"));
  SurfaceMesh two = sphere;
  append(two, moved(sphere, 1, 20));
  const DelaunayFillCounts a = fill_and_close(front_case_of(build_surface(two, "two spheres")), "two spheres");
  SurfaceMesh hollow = moved(sphere, 4, 0);
  append(hollow, sphere);
  const DelaunayFillCounts b = fill_and_close(front_case_of(build_surface(hollow, "hollow sphere")), "hollow sphere");
  // Every component is kept or lies outside (the cavity's inside among them).
  EXPECT_EQ(a.dropped_components, 0u);
  EXPECT_EQ(b.dropped_components, 0u);
}

// A box's faces, refined, are grids of cocircular points: the Delaunay
// tetrahedralization takes one diagonal of each square as its insertion
// order breaks the ties, the input the other or the same. Where they
// differ the input triangles are missing and the tets on them removed
// (all of them when the order broke every tie against the input, as a
// plain Morton order did here); the removals close what is left.
TEST(DelaunayFill, PlanarGridsOfCocircularPointsStillClose) {
  SurfaceMesh box = shifted_box(0, 1);
  for (int round = 0; round < 3; ++round) box = refine_midpoints(box);
  const DelaunayFillCounts n = fill_and_close(front_case_of(build_surface(box, "box")), "box");
  EXPECT_GT(n.missing_triangles, 0u);
}

TEST(DelaunayFill, SameInputSameFill) {
  FrontCase a = front_case("good/spool.off"), b = front_case("good/spool.off");
  TetMesh ma = a.b.core.mesh, mb = b.b.core.mesh;
  delaunay_fill(a.initial, a.b.tree, ma);
  delaunay_fill(b.initial, b.b.tree, mb);
  EXPECT_EQ(ma.tets, mb.tets);
  EXPECT_EQ(a.initial.faces, b.initial.faces);
  EXPECT_EQ(a.initial.free_vertices, b.initial.free_vertices);
}

}  // namespace
}  // namespace partet::test
