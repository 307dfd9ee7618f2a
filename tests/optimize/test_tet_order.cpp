// sort_tets_by_space (optimize/tet_order.hpp): the same tets, each with its
// vertices in the same order, by ascending Morton key of their centroids;
// tets with one key keep their old order; a mesh of one tet or none is
// left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "octree/box_morton.hpp"
#include "optimize/tet_order.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

uint64_t centroid_key(const BoxMorton& grid, const TetMesh& m, size_t t) {
  double c[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) c[i] += 0.25 * m.point(m.tets[4 * t + k])[i];
  return grid.key(c);
}

std::vector<std::vector<uint32_t>> tet_list(const TetMesh& m) {
  std::vector<std::vector<uint32_t>> out;
  for (size_t t = 0; t < m.num_tets(); ++t) out.emplace_back(&m.tets[4 * t], &m.tets[4 * t] + 4);
  return out;
}

TEST(TetOrder, ShuffledLatticeComesBackInMortonOrder) {
  TetMesh m = test::kuhn_lattice(4);
  std::vector<std::vector<uint32_t>> tets = tet_list(m);
  std::shuffle(tets.begin(), tets.end(), std::mt19937(5));
  m.tets.clear();
  for (const auto& t : tets) m.tets.insert(m.tets.end(), t.begin(), t.end());
  const TetMesh before = m;
  sort_tets_by_space(m);
  ASSERT_EQ(m.num_tets(), before.num_tets());
  EXPECT_EQ(m.xyz, before.xyz);
  auto a = tet_list(before), b = tet_list(m);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  const BoxMorton grid(m.xyz);
  for (size_t t = 1; t < m.num_tets(); ++t) EXPECT_LE(centroid_key(grid, m, t - 1), centroid_key(grid, m, t));
}

TEST(TetOrder, TetsWithOneKeyKeepTheirOrder) {
  // Two tets with one centroid (the same corners listed differently).
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  m.tets = {4, 1, 2, 3, 1, 2, 3, 0, 0, 2, 1, 3};
  sort_tets_by_space(m);
  const std::vector<uint32_t> expected = {1, 2, 3, 0, 0, 2, 1, 3, 4, 1, 2, 3};
  EXPECT_EQ(m.tets, expected);
  TetMesh one;
  one.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  one.tets = {0, 1, 2, 3};
  sort_tets_by_space(one);
  EXPECT_EQ(one.tets, (std::vector<uint32_t>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace partet
