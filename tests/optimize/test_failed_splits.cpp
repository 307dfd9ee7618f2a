// FailedSplits: a refused ring is known again from every tet around its
// edge and from either end (the ring then comes rotated or reversed), and
// no longer once a point of the ring moves; other edges are not known.
#include <gtest/gtest.h>

#include <vector>

#include "optimize/failed_splits.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

// Every ring around the edge (a, b), one per tet having it and per order
// of its ends.
std::vector<TetTopology::Ring> rings_around(const TetTopology& topo, uint32_t a, uint32_t b) {
  std::vector<TetTopology::Ring> rings;
  for (uint32_t t = 0; t < topo.slots(); ++t) {
    const int i = local_index(topo.tet(t), a), j = local_index(topo.tet(t), b);
    if (!topo.alive(t) || i < 0 || j < 0) continue;
    for (const auto& [x, y] : {std::pair{i, j}, std::pair{j, i}}) {
      TetTopology::Ring ring;
      EXPECT_TRUE(topo.edge_ring(t, x, y, ring));
      rings.push_back(ring);
    }
  }
  return rings;
}

TEST(FailedSplits, KnowsARingFromEveryTetAndEndUntilAPointMoves) {
  // The 2 x 2 x 2 Kuhn lattice: vertex 13, (1, 1, 1), is the interior one.
  TetMesh mesh = test::kuhn_lattice(2);
  TetTopology topo(mesh);
  std::vector<uint32_t> star, neighbours;
  topo.vertex_star(13, star);
  topo.star_neighbours(13, star, neighbours);
  ASSERT_GE(neighbours.size(), 2u);
  const uint32_t w = neighbours[0], other = neighbours[1];
  const std::vector<TetTopology::Ring> rings = rings_around(topo, 13, w);
  ASSERT_GE(rings.size(), 8u);  // four tets or more, both orders
  FailedSplits failed(16);
  EXPECT_FALSE(failed.known(topo, rings[0]));
  failed.add(topo, rings[0]);
  for (const TetTopology::Ring& ring : rings) EXPECT_TRUE(failed.known(topo, ring));
  for (const TetTopology::Ring& ring : rings_around(topo, 13, other)) EXPECT_FALSE(failed.known(topo, ring));

  // A ring vertex moves a little (the tets stay positive): a new ring.
  const uint32_t r = rings[0].vertices[0];
  double x[3] = {topo.point(r)[0], topo.point(r)[1], topo.point(r)[2]};
  x[0] += 1e-3;
  topo.move_vertex(r, x);
  for (const TetTopology::Ring& ring : rings_around(topo, 13, w)) EXPECT_FALSE(failed.known(topo, ring));
}

}  // namespace
}  // namespace partet
