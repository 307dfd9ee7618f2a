// Front faces paired across the wedges around an edge (front_cavities.hpp):
// tet-shaped cavities pinched along one edge pair their own two faces
// whatever the order the faces come in; coplanar apexes and an odd count
// are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/predicates.hpp"
#include "front/front_cavities.hpp"
#include "hand_front.hpp"

namespace partet::test {
namespace {

// Edge x = 0, y = 1 along z; each cavity is the tet (x, y, apex, apex').
// Its faces are written outward (hand_front reverses them into the front).
std::vector<uint32_t> outward_tets(const std::vector<double>& xyz, const std::vector<std::array<uint32_t, 4>>& tets) {
  std::vector<uint32_t> faces;
  for (const auto& t : tets) {
    for (int k = 0; k < 4; ++k) {
      uint32_t a = t[(k + 1) % 4], b = t[(k + 2) % 4], c = t[(k + 3) % 4];
      if (orient3d(&xyz[3 * a], &xyz[3 * b], &xyz[3 * c], &xyz[3 * t[k]]) > 0) std::swap(b, c);
      faces.insert(faces.end(), {a, b, c});
    }
  }
  return faces;
}

struct Wedges {
  std::vector<uint32_t> on_edge;  // front faces on edge (0, 1)
  std::vector<uint32_t> partner;
  bool paired = false;
};

Wedges pair_on_edge(const std::vector<double>& xyz, const std::vector<std::array<uint32_t, 4>>& tets,
                    bool reverse_order = false) {
  const HandFront h = hand_front(xyz, outward_tets(xyz, tets));
  const Front front(h.initial, h.tree, h.root);
  Wedges w;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    const uint32_t* t = front.face(f);
    const bool has0 = t[0] == 0 || t[1] == 0 || t[2] == 0, has1 = t[0] == 1 || t[1] == 1 || t[2] == 1;
    if (front.alive(f) && has0 && has1) w.on_edge.push_back(f);
  }
  if (reverse_order) std::reverse(w.on_edge.begin(), w.on_edge.end());
  w.paired = pair_faces_around_edge(front, 0, 1, w.on_edge, w.partner);
  return w;
}

// Apexes around the z axis at the given angles (degrees), at mid height.
std::vector<double> edge_and_apexes(const std::vector<double>& degrees) {
  std::vector<double> xyz = {0, 0, 0, 0, 0, 1};
  for (double d : degrees) {
    const double r = d * 3.14159265358979323846 / 180;
    xyz.insert(xyz.end(), {std::cos(r), std::sin(r), 0.5});
  }
  return xyz;
}

TEST(FrontCavities, TwoPinchedCavitiesPairTheirOwnFaces) {
  const auto xyz = edge_and_apexes({0, 60, 170, 250});
  for (bool reverse : {false, true}) {
    const Wedges w = pair_on_edge(xyz, {{0, 1, 2, 3}, {0, 1, 4, 5}}, reverse);
    ASSERT_EQ(w.on_edge.size(), 4u);
    ASSERT_TRUE(w.paired);
    // Faces come cavity by cavity (two per tet, in the order written, or
    // reversed): each face's partner is the other face of its tet.
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(w.partner[i], w.on_edge[i ^ 1]) << i;
  }
}

TEST(FrontCavities, ThreeCavitiesAroundOneEdge) {
  const auto xyz = edge_and_apexes({10, 80, 130, 200, 260, 320});
  const Wedges w = pair_on_edge(xyz, {{0, 1, 2, 3}, {0, 1, 4, 5}, {0, 1, 6, 7}});
  ASSERT_EQ(w.on_edge.size(), 6u);
  ASSERT_TRUE(w.paired);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(w.partner[i], w.on_edge[i ^ 1]) << i;
}

TEST(FrontCavities, CoplanarApexesAndOddCountsAreRefused) {
  // The second cavity's first apex lies on the half-plane of the first
  // cavity's second apex, twice as far from the edge: the two faces lie
  // in one plane on one side of the edge, and which comes first around it
  // is not told by orient3d signs.
  auto coplanar = edge_and_apexes({0, 60, 60, 250});
  coplanar[3 * 4] = 2 * coplanar[3 * 3];
  coplanar[3 * 4 + 1] = 2 * coplanar[3 * 3 + 1];
  EXPECT_FALSE(pair_on_edge(coplanar, {{0, 1, 2, 3}, {0, 1, 4, 5}}).paired);
  const HandFront h = hand_front(edge_and_apexes({0, 60}), outward_tets(edge_and_apexes({0, 60}), {{0, 1, 2, 3}}));
  const Front front(h.initial, h.tree, h.root);
  std::vector<uint32_t> partner;
  EXPECT_FALSE(pair_faces_around_edge(front, 0, 1, {0, 1, 2}, partner));
}

}  // namespace
}  // namespace partet::test
