// TetTopology's bookkeeping that the optimizer's trials rely on: a trial
// replace() and its reverse, with the incident tets restored, leave every
// slot and every vertex star (and its walk order) as they were; the
// neighbours of a star come each once, ascending (star_neighbours).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "optimize/tet_topology.hpp"
#include "optimize_test_util.hpp"

namespace partet {
namespace {

// A 2 x 2 x 2 Kuhn lattice whose one interior vertex, 13 at (1, 1, 1), is
// moved off the lattice a little so that no quality ties.
TetMesh lattice() {
  TetMesh m = test::kuhn_lattice(2);
  m.xyz[3 * 13] += 0.05;
  m.xyz[3 * 13 + 1] -= 0.03;
  return m;
}

struct Snapshot {
  std::vector<std::vector<uint32_t>> tets;   // per slot (empty when dead)
  std::vector<std::vector<uint32_t>> stars;  // per vertex, in walk order
};

// Slots past the last alive one are left out: a trial with more new tets
// than old ones appends slots, dead again after the reverse (the next new
// tets take them as they would have been appended).
Snapshot snapshot(const TetTopology& topo) {
  Snapshot s;
  uint32_t used = topo.slots();
  while (used > 0 && !topo.alive(used - 1)) --used;
  for (uint32_t t = 0; t < used; ++t)
    s.tets.push_back(topo.alive(t) ? std::vector<uint32_t>(topo.tet(t), topo.tet(t) + 4) : std::vector<uint32_t>{});
  for (uint32_t v = 0; v < topo.num_vertices(); ++v) {
    std::vector<uint32_t> star;
    topo.vertex_star(v, star);
    s.stars.push_back(star);
  }
  return s;
}

// Cones a new vertex at p to the outer faces of `cavity` and takes it out
// again, as insertion trials do; with `restore`, the incident tets too.
void trial(TetTopology& topo, const std::vector<uint32_t>& cavity, const double* p, bool restore) {
  std::vector<uint32_t> members = cavity, old_tets, new_tets, created, restored, incident;
  std::sort(members.begin(), members.end());
  topo.tet_vertices(cavity, old_tets);
  const uint32_t v = topo.add_vertex(p, 0);
  for (uint32_t t : cavity)
    for (uint32_t f = 0; f < 4; ++f) {
      const uint32_t other = topo.twin(4 * t + f);
      if (other != TetTopology::kNone && std::binary_search(members.begin(), members.end(), other / 4)) continue;
      new_tets.insert(new_tets.end(), topo.tet(t), topo.tet(t) + 4);
      new_tets[new_tets.size() - 4 + f] = v;
    }
  topo.incident_tets(old_tets, incident);
  topo.replace(cavity, new_tets, created);
  topo.replace(created, old_tets, restored);
  if (restore) topo.restore_incident(old_tets, incident, cavity, restored);
  topo.remove_last_vertex();
}

TEST(TetTopology, ATrialAndItsReverseLeaveNoTrace) {
  TetMesh m = lattice();
  TetTopology topo(m);
  const Snapshot before = snapshot(topo);
  // The centre's star (24 tets, as many outer faces), and the ring of an
  // edge from the centre (2 outer faces per tet).
  std::vector<uint32_t> star;
  topo.vertex_star(13, star);
  ASSERT_EQ(star.size(), 24u);
  const double near_centre[3] = {1.01, 0.98, 1.02};
  trial(topo, star, near_centre, true);
  EXPECT_EQ(snapshot(topo).tets, before.tets);
  EXPECT_EQ(snapshot(topo).stars, before.stars);

  TetTopology::Ring ring;
  const uint32_t* t = topo.tet(star[0]);
  const int centre = local_index(t, 13);
  ASSERT_TRUE(topo.edge_ring(star[0], centre, (centre + 1) % 4, ring));
  const double* a = topo.point(ring.a);
  const double* b = topo.point(ring.b);
  const double middle[3] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  trial(topo, std::vector<uint32_t>(ring.tets, ring.tets + ring.n), middle, true);
  EXPECT_EQ(snapshot(topo).tets, before.tets);
  EXPECT_EQ(snapshot(topo).stars, before.stars);

  // Without the restore, the slots come back but some star walks start
  // elsewhere: the restore is what makes a failed trial invisible.
  trial(topo, star, near_centre, false);
  EXPECT_EQ(snapshot(topo).tets, before.tets);
  EXPECT_NE(snapshot(topo).stars, before.stars);
}

TEST(TetTopology, StarNeighboursComeOnceAscending) {
  TetMesh m = lattice();
  TetTopology topo(m);
  std::vector<uint32_t> star, got;
  for (int round = 0; round < 2; ++round)  // the marks of one call do not leak into the next
    for (uint32_t v = 0; v < topo.num_vertices(); ++v) {
      topo.vertex_star(v, star);
      std::vector<uint32_t> want;
      for (uint32_t t : star)
        for (int k = 0; k < 4; ++k)
          if (topo.tet(t)[k] != v) want.push_back(topo.tet(t)[k]);
      std::sort(want.begin(), want.end());
      want.erase(std::unique(want.begin(), want.end()), want.end());
      topo.star_neighbours(v, star, got);
      EXPECT_EQ(got, want) << v;
    }
  topo.vertex_star(13, star);
  topo.star_neighbours(13, star, got);
  EXPECT_EQ(got.size(), 14u);  // the centre of a Kuhn lattice has 14 neighbours
}

}  // namespace
}  // namespace partet
