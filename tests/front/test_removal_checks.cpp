// The live front store (FrontStore: edges, the other faces on an edge,
// leaf lists) and the exact face removal checks (RemovalChecks) on fronts
// made by hand over a one-leaf octree: closing a tet, a vertex inside the
// candidate, a new edge piercing a front face, a front edge crossing a new
// face, a duplicate face, and touching cases at shared vertices and edges
// that must be accepted; what blocked a removal keeps blocking it while it
// is on the front, and only then.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/predicates.hpp"
#include "front/front.hpp"
#include "front/initial_front.hpp"
#include "front/removal_checks.hpp"
#include "hand_front.hpp"

namespace partet::test {
namespace {

RemovalVerdict verdict(const Front& front, uint32_t f, uint32_t p) {
  NearFront near;
  gather_near_front(front, {0}, near);
  return check_removal(front, f, p, near);
}

// The unit corner tet 0 = origin, 1 = x, 2 = y, 3 = z, outward faces.
const std::vector<double> kTetXyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<uint32_t> kTetOutward = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1};

// A triangular bipyramid: equator A = 0, B = 1, C = 2 (counterclockwise
// from +z), apexes N = 3 above and S = 4 below; outward faces.
const std::vector<double> kBipyramidXyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1, 0.3, 0.3, -1};
const std::vector<uint32_t> kBipyramidOutward = {0, 1, 3, 1, 2, 3, 2, 0, 3, 1, 0, 4, 2, 1, 4, 0, 2, 4};

// Index of the front face with vertex set {a, b, c}.
uint32_t face_on(const Front& front, uint32_t a, uint32_t b, uint32_t c) {
  const uint32_t f = front.find_face(a, b, c);
  EXPECT_NE(f, kNoIndex);
  return f;
}

// Every alive face's edges: the other faces for_each_other_face_on_edge
// visits are those a scan of all alive faces finds on the edge.
void expect_other_faces_found(const Front& front) {
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t u = front.face(f)[k], w = front.face(f)[(k + 1) % 3];
      std::vector<uint32_t> visited, want;
      front.for_each_other_face_on_edge(f, u, w, [&](uint32_t g) { visited.push_back(g); });
      for (uint32_t g = 0; g < front.num_face_slots(); ++g) {
        if (g == f || !front.alive(g)) continue;
        const uint32_t* h = front.face(g);
        if (std::count(h, h + 3, u) && std::count(h, h + 3, w)) want.push_back(g);
      }
      std::sort(visited.begin(), visited.end());
      EXPECT_EQ(visited, want) << f << " " << u << "-" << w;
    }
  }
}

TEST(FrontStore, FindsTheOtherFacesOnAnEdge) {
  // The bipyramid: two faces on every edge.
  HandFront h = hand_front(kBipyramidXyz, kBipyramidOutward);
  Front front(h.initial, h.tree, h.root);
  expect_other_faces_found(front);
  std::vector<uint32_t> added, shrunk;
  front.apply_tet(face_on(front, 0, 1, 3), 2, added, shrunk);
  expect_other_faces_found(front);

  // Two tets joined at edge 0-1 only: four faces on that edge.
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0.5, 1, 0.2, 0.5, 0.5, 1, 0.5, -1, 0.2, 0.5, -0.5, -1};
  std::vector<uint32_t> outward;
  for (const std::array<uint32_t, 4>& tet : {std::array<uint32_t, 4>{0, 1, 2, 3}, std::array<uint32_t, 4>{0, 1, 4, 5}})
    for (int l = 0; l < 4; ++l) {
      std::array<uint32_t, 3> face;
      for (int k = 0, n = 0; k < 4; ++k)
        if (k != l) face[n++] = tet[k];
      const double* p[4] = {&xyz[3 * face[0]], &xyz[3 * face[1]], &xyz[3 * face[2]], &xyz[3 * tet[l]]};
      if (orient3d(p[0], p[1], p[2], p[3]) < 0) std::swap(face[0], face[1]);
      outward.insert(outward.end(), face.begin(), face.end());
    }
  HandFront pinched = hand_front(xyz, outward);
  Front two(pinched.initial, pinched.tree, pinched.root);
  EXPECT_EQ(two.edge_uses(0, 1), 4u);
  expect_other_faces_found(two);
}

TEST(FrontStore, HashesEdgesAndLeafLists) {
  HandFront h = hand_front(kBipyramidXyz, kBipyramidOutward);
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(front.num_alive_faces(), 6u);
  EXPECT_EQ(front.edge_uses(0, 1), 2u);
  EXPECT_EQ(front.edge_uses(3, 4), 0u);
  EXPECT_EQ(front.vertex_uses(3), 3u);
  EXPECT_EQ(front.find_face(3, 1, 0), front.find_face(0, 1, 3));
  int listed = 0;
  for (uint32_t e = front.first_face_entry(0); e != kNoIndex; e = front.next_entry(e)) ++listed;
  EXPECT_EQ(listed, 6);
  EXPECT_FALSE(front.leaf_front_empty(0));

  // Upper tet (A, B, N) + C: closes 3 faces, adds the equator (A, C, B).
  std::vector<uint32_t> added, shrunk;
  const uint32_t base = face_on(front, 0, 1, 3);
  EXPECT_EQ(front.apply_tet(base, 2, added, shrunk), 2);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_EQ(front.num_alive_faces(), 4u);
  EXPECT_EQ(front.vertex_uses(3), 0u);
  EXPECT_EQ(front.edge_uses(0, 3), 0u);
  EXPECT_EQ(front.edge_uses(0, 1), 2u);
  EXPECT_EQ(front.leaf_changed(0), 1u);
  EXPECT_EQ(front.changes(), 1u);
  int vertices = 0;
  for (uint32_t v = front.first_vertex(0); v != kNoIndex; v = front.next_vertex(v)) {
    EXPECT_NE(v, 3u);
    ++vertices;
  }
  EXPECT_EQ(vertices, 4);

  // The lower tet closes the rest.
  EXPECT_EQ(verdict(front, added[0], 4), RemovalVerdict::kValid);
  EXPECT_EQ(front.apply_tet(added[0], 4, added, shrunk), 3);
  EXPECT_EQ(front.num_alive_faces(), 0u);
  EXPECT_TRUE(front.leaf_front_empty(0));
}

TEST(RemovalChecks, SingleTetClosesItsFourFaces) {
  HandFront h = hand_front(kTetXyz, kTetOutward);
  Front front(h.initial, h.tree, h.root);
  const uint32_t base = face_on(front, 0, 1, 2);
  EXPECT_EQ(verdict(front, base, 3), RemovalVerdict::kValid);
  EXPECT_EQ(verdict(front, base, 0), RemovalVerdict::kNotPositive);
  std::vector<uint32_t> added, shrunk;
  EXPECT_EQ(front.apply_tet(base, 3, added, shrunk), 3);
  EXPECT_TRUE(added.empty());
  EXPECT_EQ(front.num_alive_faces(), 0u);
  EXPECT_TRUE(front.leaf_front_empty(0));
}

TEST(RemovalChecks, BackSideTargetIsNotPositive) {
  std::vector<double> xyz = kTetXyz;
  xyz.insert(xyz.end(), {0.2, 0.2, -1});
  HandFront h = hand_front(xyz, kTetOutward);
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 4), RemovalVerdict::kNotPositive);
}

TEST(RemovalChecks, VertexInsideTheCandidate) {
  // A small closed obstacle (a tet, facing out of itself into the region)
  // floats inside the corner tet.
  std::vector<double> xyz = kTetXyz;
  xyz.insert(xyz.end(), {0.1, 0.1, 0.1, 0.2, 0.1, 0.1, 0.1, 0.2, 0.1, 0.1, 0.1, 0.2});
  std::vector<uint32_t> faces = kTetOutward;
  // The obstacle's faces listed facing into it: the front faces face out
  // of it, into the region to mesh.
  faces.insert(faces.end(), {5, 7, 6, 4, 6, 7, 4, 7, 5, 4, 5, 6});
  HandFront h = hand_front(xyz, faces);
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 3), RemovalVerdict::kVertexInside);
}

TEST(RemovalChecks, VertexOnTheNewFaceIsInside) {
  std::vector<double> xyz = kTetXyz;
  xyz.insert(xyz.end(), {0.25, 0.25, 0.5, 2, 2, 2, 2, 3, 2});
  std::vector<uint32_t> faces = kTetOutward;
  faces.insert(faces.end(), {4, 5, 6});
  HandFront h = hand_front(xyz, faces);
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 3), RemovalVerdict::kVertexInside);
}

TEST(RemovalChecks, NewEdgePiercesAFrontFace) {
  // A wide triangle at z = 0.5 slices the corner tet; its vertices are far
  // outside, so only the edges p-0, p-1, p-2 see it. The base face's other
  // faces are absent: the new edges are new.
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, -1, 0.5, 3, -1, 0.5, -1, 3, 0.5};
  HandFront h = hand_front(xyz, {0, 2, 1, 4, 5, 6});
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 3), RemovalVerdict::kEdgeCrossesFace);
}

TEST(RemovalChecks, FrontEdgeCrossesANewFace) {
  // A thin triangle at z = 0.3 whose edge u-v crosses the faces x = 0 and
  // y = 0 of the corner tet; its third vertex is outside, and no tet edge
  // meets it.
  const std::vector<double> xyz = {0, 0, 0,    1,   0,    0,   0,   1,     0,  0, 0, 1,
                                   -0.1, 0.2, 0.3, 0.2, -0.1, 0.3, 0.5, -0.39, 0.3};
  HandFront h = hand_front(xyz, {0, 2, 1, 4, 5, 6});
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 3), RemovalVerdict::kFaceCrossesEdge);
}

TEST(RemovalChecks, DuplicateFaceIsRejected) {
  // The tet would lie on the meshed side of a face oriented like its own
  // new face.
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  // Front faces (0, 1, 2) and (0, 1, 3): the second is the new face
  // (a, b, p) of the tet (0, 1, 2) + 3 with the same orientation.
  HandFront h = hand_front(xyz, {0, 2, 1, 0, 3, 1});
  Front front(h.initial, h.tree, h.root);
  EXPECT_EQ(verdict(front, face_on(front, 0, 1, 2), 3), RemovalVerdict::kDuplicateFace);
}

TEST(RemovalChecks, ClosingTetsInABipyramidAreValid) {
  HandFront h = hand_front(kBipyramidXyz, kBipyramidOutward);
  Front front(h.initial, h.tree, h.root);
  const uint32_t upper = face_on(front, 0, 1, 3);
  // Apex C: closes two faces, the new equator face touches the rest of
  // the front along shared edges only.
  EXPECT_EQ(verdict(front, upper, 2), RemovalVerdict::kValid);
  // Apex S: the new edge N-S passes through the middle, touching every
  // face at N or S only.
  EXPECT_EQ(verdict(front, upper, 4), RemovalVerdict::kValid);
}

TEST(RemovalChecks, CoplanarTouchAtASharedVertex) {
  // An extra face in the equator plane z = 0 sharing vertex A: outside the
  // new face (A, C, B)'s angle at A it is a touch; inside, its edge runs
  // over the new face.
  std::vector<double> xyz = kBipyramidXyz;
  xyz.insert(xyz.end(), {-1, -0.2, 0, -0.2, -1, 0});
  std::vector<uint32_t> faces = kBipyramidOutward;
  faces.insert(faces.end(), {0, 5, 6});
  {
    HandFront h = hand_front(xyz, faces);
    Front front(h.initial, h.tree, h.root);
    EXPECT_EQ(verdict(front, face_on(front, 0, 1, 3), 2), RemovalVerdict::kValid);
  }
  xyz = kBipyramidXyz;
  xyz.insert(xyz.end(), {2, 0.5, 0, 2, 1, 0});
  {
    HandFront h = hand_front(xyz, faces);
    Front front(h.initial, h.tree, h.root);
    EXPECT_EQ(verdict(front, face_on(front, 0, 1, 3), 2), RemovalVerdict::kFaceCrossesEdge);
  }
}

TEST(RemovalChecks, SegmentFromASharedVertex) {
  const double s[3] = {0, 0, 0}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0};
  const double above[3] = {0.2, 0.2, 1}, inside[3] = {0.2, 0.2, 0}, along[3] = {2, 0, 0};
  const double outside[3] = {-1, -1, 0}, beside[3] = {0, -1, 0};
  EXPECT_FALSE(meets_beyond_shared_vertex(s, above, t1, t2));
  EXPECT_TRUE(meets_beyond_shared_vertex(s, inside, t1, t2));
  EXPECT_TRUE(meets_beyond_shared_vertex(s, along, t1, t2));
  EXPECT_FALSE(meets_beyond_shared_vertex(s, outside, t1, t2));
  EXPECT_FALSE(meets_beyond_shared_vertex(s, beside, t1, t2));
}

// Closes alive face g with a tet on a new apex one unit ahead of it.
void close_with_new_apex(Front& front, uint32_t g) {
  const uint32_t* t = front.face(g);
  const double *a = front.point(t[0]), *b = front.point(t[1]), *c = front.point(t[2]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double apex[3] = {(a[0] + b[0] + c[0]) / 3 + n[0] / len, (a[1] + b[1] + c[1]) / 3 + n[1] / len,
                          (a[2] + b[2] + c[2]) / 3 + n[2] / len};
  const uint32_t p = front.add_vertex(apex, 1000 + front.num_vertices());
  std::vector<uint32_t> added, shrunk;
  front.apply_tet(g, p, added, shrunk);
  EXPECT_FALSE(front.alive(g));
}

// Why the removal (f, p) fails, checked against the whole front.
RemovalBlocker blocker_of(const Front& front, uint32_t f, uint32_t p) {
  NearFront near;
  gather_near_front(front, {0}, near);
  RemovalBlocker why;
  EXPECT_NE(check_removal(front, f, p, near, &why), RemovalVerdict::kValid);
  return why;
}

// On the front of `outward`, the tet on face (0, 1, 2) with apex 3 fails
// with `verdict`, blocked by the face on vertices `g`, until a tet closes
// that face.
void expect_blocked_until_closed(const std::vector<double>& xyz, const std::vector<uint32_t>& outward,
                                 const std::array<uint32_t, 3>& g, RemovalVerdict verdict) {
  HandFront h = hand_front(xyz, outward);
  Front front(h.initial, h.tree, h.root);
  const uint32_t base = face_on(front, 0, 1, 2), blocking = face_on(front, g[0], g[1], g[2]);
  const RemovalBlocker why = blocker_of(front, base, 3);
  EXPECT_EQ(why.verdict, verdict);
  EXPECT_EQ(why.entity, blocking);
  EXPECT_TRUE(still_blocked(front, base, 3, why));
  close_with_new_apex(front, blocking);
  EXPECT_FALSE(still_blocked(front, base, 3, why));
}

// The blocker of each failing configuration above, and still_blocked: true
// while the blocker is on the front, false once a tet closed it.
TEST(RemovalChecks, BlockersBlockWhileOnTheFront) {
  {
    // The corner tet with its slanted face dented in to E = 4: E lies in
    // the tet (0, 1, 2) + 3, and the region is the three tets coned to E.
    std::vector<double> xyz = kTetXyz;
    xyz.insert(xyz.end(), {0.25, 0.25, 0.25});
    HandFront h = hand_front(xyz, {1, 2, 4, 2, 3, 4, 3, 1, 4, 0, 3, 2, 0, 1, 3, 0, 2, 1});
    Front front(h.initial, h.tree, h.root);
    const uint32_t base = face_on(front, 0, 1, 2);
    const RemovalBlocker why = blocker_of(front, base, 3);
    EXPECT_EQ(why.verdict, RemovalVerdict::kVertexInside);
    EXPECT_EQ(why.entity, 4u);
    EXPECT_TRUE(still_blocked(front, base, 3, why));
    std::vector<uint32_t> added, shrunk;
    for (const auto& t : {std::array<uint32_t, 3>{0, 1, 2}, {0, 2, 3}, {0, 3, 1}})
      front.apply_tet(face_on(front, t[0], t[1], t[2]), 4, added, shrunk);
    EXPECT_EQ(front.num_alive_faces(), 0u);
    EXPECT_FALSE(still_blocked(front, base, 3, why));
  }
  // The configurations of NewEdgePiercesAFrontFace, FrontEdgeCrossesANewFace
  // and DuplicateFaceIsRejected.
  expect_blocked_until_closed({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, -1, 0.5, 3, -1, 0.5, -1, 3, 0.5},
                              {0, 2, 1, 4, 5, 6}, {4, 5, 6}, RemovalVerdict::kEdgeCrossesFace);
  expect_blocked_until_closed(
      {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -0.1, 0.2, 0.3, 0.2, -0.1, 0.3, 0.5, -0.39, 0.3}, {0, 2, 1, 4, 5, 6},
      {4, 5, 6}, RemovalVerdict::kFaceCrossesEdge);
  expect_blocked_until_closed(kTetXyz, {0, 2, 1, 0, 3, 1}, {0, 1, 3}, RemovalVerdict::kDuplicateFace);
}

}  // namespace
}  // namespace partet::test
