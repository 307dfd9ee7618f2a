// TetTopology's bookkeeping that the optimizer's trials rely on: a trial
// replace() and its reverse, with the incident tets restored, leave every
// slot and every vertex star (and its walk order) as they were; the
// neighbours of a star come each once, ascending (star_neighbours); the
// change marks name exactly the tets whose vertex stars a move or a
// replace touched, and a cone trial undone leaves them as they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "optimize/insertion.hpp"
#include "optimize/smoothing.hpp"
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

// The tets joining the outer faces of `cavity` to vertex v.
std::vector<uint32_t> cone_tets(const TetTopology& topo, const std::vector<uint32_t>& cavity, uint32_t v) {
  std::vector<uint32_t> members = cavity, new_tets;
  std::sort(members.begin(), members.end());
  for (uint32_t t : cavity)
    for (uint32_t f = 0; f < 4; ++f) {
      const uint32_t other = topo.twin(4 * t + f);
      if (other != TetTopology::kNone && std::binary_search(members.begin(), members.end(), other / 4)) continue;
      new_tets.insert(new_tets.end(), topo.tet(t), topo.tet(t) + 4);
      new_tets[new_tets.size() - 4 + f] = v;
    }
  return new_tets;
}

// Cones a new vertex at p to the outer faces of `cavity` and takes it out
// again, as insertion trials do; with `restore`, the incident tets too.
void trial(TetTopology& topo, const std::vector<uint32_t>& cavity, const double* p, bool restore) {
  std::vector<uint32_t> old_tets, created, restored, incident;
  topo.tet_vertices(cavity, old_tets);
  const uint32_t v = topo.add_vertex(p, 0);
  const std::vector<uint32_t> new_tets = cone_tets(topo, cavity, v);
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

// Per alive tet: whether it is unchanged since change count `count`.
std::vector<bool> unchanged(const TetTopology& topo, uint32_t count) {
  std::vector<bool> out;
  for (uint32_t t = 0; t < topo.slots(); ++t) out.push_back(topo.alive(t) && topo.unchanged_since(t, count));
  return out;
}

// Per alive tet: whether one of its vertices is in `touched`.
std::vector<bool> untouched(const TetTopology& topo, const std::vector<uint32_t>& touched) {
  std::vector<bool> out;
  for (uint32_t t = 0; t < topo.slots(); ++t) {
    bool clear = topo.alive(t);
    for (int k = 0; k < 4; ++k)
      clear = clear && std::find(touched.begin(), touched.end(), topo.tet(t)[k]) == touched.end();
    out.push_back(clear);
  }
  return out;
}

TEST(TetTopology, ChangeMarksFollowMovesAndReplacesAndTrialsUndone) {
  TetMesh m = test::kuhn_lattice(3);
  TetTopology topo(m);
  const uint32_t centre = 21;  // (1, 1, 1), interior
  std::vector<uint32_t> star, around;
  topo.vertex_star(centre, star);
  topo.star_neighbours(centre, star, around);
  around.push_back(centre);

  // A move changes the stars of the vertex and of its neighbours.
  const uint32_t before_move = topo.changes();
  const double nudged[3] = {1.02, 0.99, 1.01};
  topo.move_vertex(centre, nudged);
  const std::vector<bool> after_move = unchanged(topo, before_move);
  EXPECT_EQ(after_move, untouched(topo, around));
  EXPECT_GT(std::count(after_move.begin(), after_move.end(), true), 0);
  EXPECT_GT(std::count(after_move.begin(), after_move.end(), false), 0);

  // A cone trial undone (as insertion trials are) changes nothing.
  const uint32_t before_trial = topo.changes();
  std::vector<uint32_t> old_tets;
  topo.tet_vertices(star, old_tets);
  const double inside[3] = {1.05, 1.0, 0.97};
  const uint32_t v = topo.add_vertex(inside, 0);
  std::vector<uint32_t> new_tets = cone_tets(topo, star, v);
  SmoothingScratch scratch;
  ConeTrial trial;
  apply_cone(topo, star, old_tets, new_tets, scratch, trial);
  EXPECT_GT(topo.changes(), before_trial);
  undo_cone(topo, star, old_tets, trial);
  const std::vector<bool> after_trial = unchanged(topo, before_trial);
  EXPECT_EQ(std::count(after_trial.begin(), after_trial.end(), false), 0);

  // A replace kept changes the stars of the cavity's vertices.
  const uint32_t before_replace = topo.changes();
  std::vector<uint32_t> created;
  const uint32_t w = topo.add_vertex(inside, 0);
  for (uint32_t& x : new_tets)
    if (x == v) x = w;
  topo.replace(star, new_tets, created);
  std::vector<uint32_t> cavity_vertices = old_tets;
  cavity_vertices.push_back(w);
  const std::vector<bool> after_replace = unchanged(topo, before_replace);
  EXPECT_EQ(after_replace, untouched(topo, cavity_vertices));
  EXPECT_GT(std::count(after_replace.begin(), after_replace.end(), true), 0);
}

}  // namespace
}  // namespace partet
