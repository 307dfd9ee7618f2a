// TetTopology's bookkeeping that the optimizer's trials rely on: a trial
// vertex smoothed in its would-be star (smooth_new_vertex) lands where
// smooth_vertex takes it once the star is in the mesh, and a failed
// insertion leaves every slot, every vertex star (and its walk order) and
// every change mark as they were; the constructor links each face to the
// other tet on it; the neighbours of a star come each
// once, ascending (star_neighbours); the change marks name exactly the
// tets whose vertex stars a move or a replace touched.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "optimize/insertion.hpp"
#include "optimize/smoothing.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize/vertex_incidence.hpp"
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

// Slots past the last alive one are left out.
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

// Every face is linked to the other tet having its three vertices, or to
// none on the boundary; the 8 x 8 x 8 lattice leaves more faces unmatched
// at a time than the builder's first table holds.
TEST(TetTopology, TwinsAreTheTetsSharingEachFace) {
  TetMesh mesh = test::kuhn_lattice(8);
  std::map<std::array<uint32_t, 3>, std::vector<uint32_t>> sides;
  for (uint32_t t = 0; t < mesh.num_tets(); ++t)
    for (uint32_t f = 0; f < 4; ++f) {
      std::array<uint32_t, 3> key;
      int n = 0;
      for (uint32_t k = 0; k < 4; ++k)
        if (k != f) key[n++] = mesh.tets[4 * t + k];
      std::sort(key.begin(), key.end());
      sides[key].push_back(4 * t + f);
    }
  const TetTopology topo(mesh);
  size_t boundary = 0;
  for (const auto& [key, codes] : sides) {
    ASSERT_LE(codes.size(), 2u);
    if (codes.size() == 1) {
      EXPECT_EQ(topo.twin(codes[0]), TetTopology::kNone);
      ++boundary;
      continue;
    }
    EXPECT_EQ(topo.twin(codes[0]), codes[1]);
    EXPECT_EQ(topo.twin(codes[1]), codes[0]);
  }
  EXPECT_EQ(boundary, 6u * 8 * 8 * 2);
}

// A tet listed twice lies on the same side of each of its faces as its
// copy: the builder refuses the mesh instead of linking them.
TEST(TetTopology, TwoTetsOnOneSideOfAFaceAreAnInternalError) {
  TetMesh mesh = test::kuhn_lattice(1);
  mesh.tets.insert(mesh.tets.end(), mesh.tets.begin(), mesh.tets.begin() + 4);
  EXPECT_THROW(TetTopology topo(mesh), InternalError);
}

TEST(TetTopology, ATrialVertexSmoothsAsInTheMesh) {
  TetMesh m = lattice(), n = lattice();
  TetTopology topo(m), applied(n);
  std::vector<uint32_t> star;
  topo.vertex_star(13, star);
  ASSERT_EQ(star.size(), 24u);
  const Snapshot before = snapshot(topo);
  const uint32_t changes = topo.changes();
  // A vertex well off the centre of the centre's star: smoothing moves it.
  const double off_centre[3] = {1.15, 0.9, 1.1};
  const uint32_t v = topo.add_vertex(off_centre, 0);
  const std::vector<uint32_t> new_tets = cone_tets(topo, star, v);
  for (size_t i = 0; i < new_tets.size(); i += 4)
    ASSERT_GT(orient3d(topo.point(new_tets[i]), topo.point(new_tets[i + 1]), topo.point(new_tets[i + 2]),
                       topo.point(new_tets[i + 3])),
              0);
  SmoothingScratch scratch;
  ASSERT_TRUE(smooth_new_vertex(topo, v, new_tets, scratch));
  const double placed[3] = {topo.point(v)[0], topo.point(v)[1], topo.point(v)[2]};
  EXPECT_NE(placed[0], off_centre[0]);

  // The same cone put in the mesh first, then smoothed there.
  const uint32_t w = applied.add_vertex(off_centre, 0);
  std::vector<uint32_t> created;
  applied.replace(star, cone_tets(applied, star, w), created);
  SmoothingScratch other;
  ASSERT_TRUE(smooth_vertex(applied, w, other));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(placed[i], applied.point(w)[i], 1e-9) << i;
  // scratch.quality holds the cone's qualities at the placed point, whose
  // worst rose from the start.
  ASSERT_EQ(scratch.quality.size(), new_tets.size() / 4);
  double worst = 1, start = 1;
  for (size_t k = 0; k < scratch.quality.size(); ++k) {
    const uint32_t* q = &new_tets[4 * k];
    const double* p[4];
    const double* s[4];
    for (int i = 0; i < 4; ++i) {
      p[i] = q[i] == v ? placed : m.xyz.data() + 3 * size_t{q[i]};
      s[i] = q[i] == v ? off_centre : m.xyz.data() + 3 * size_t{q[i]};
    }
    EXPECT_EQ(scratch.quality[k], tet_quality(p[0], p[1], p[2], p[3])) << k;
    worst = std::min(worst, scratch.quality[k]);
    start = std::min(start, tet_quality(s[0], s[1], s[2], s[3]));
  }
  EXPECT_GT(worst, start);
  topo.remove_last_vertex();
  EXPECT_EQ(snapshot(topo).tets, before.tets);
  EXPECT_EQ(snapshot(topo).stars, before.stars);
  EXPECT_EQ(topo.changes(), changes);
}

TEST(TetTopology, AFailedInsertionLeavesNoTrace) {
  TetMesh m = lattice();
  TetTopology topo(m);
  SmoothingScratch scratch;
  // Each tet of the lattice in turn, under both rules: where no cavity
  // pays (most tets: the lattice is already good), the topology is as it
  // was, star walk orders and change marks included.
  int failed = 0;
  for (const InsertionRule rule : {InsertionRule::kShortfall, InsertionRule::kWorstFirst})
    for (uint32_t t = 0; t < topo.slots(); ++t) {
      if (!topo.alive(t)) continue;
      const Snapshot before = snapshot(topo);
      const uint32_t changes = topo.changes();
      const size_t vertices = topo.num_vertices();
      if (insert_vertex(topo, t, quality_of_angle(40), scratch, rule)) continue;
      ++failed;
      EXPECT_EQ(snapshot(topo).tets, before.tets) << t;
      EXPECT_EQ(snapshot(topo).stars, before.stars) << t;
      EXPECT_EQ(topo.changes(), changes) << t;
      EXPECT_EQ(topo.num_vertices(), vertices) << t;
    }
  EXPECT_GT(failed, 10);
}

// Per vertex: whether a face through it has no tet behind (from the
// twins, not the topology's flags).
std::vector<uint8_t> open_vertices(const TetTopology& topo) {
  std::vector<uint8_t> open(topo.num_vertices(), 0);
  for (uint32_t t = 0; t < topo.slots(); ++t)
    for (int f = 0; topo.alive(t) && f < 4; ++f)
      if (topo.twin(4 * t + f) == TetTopology::kNone)
        for (int k = 0; k < 4; ++k)
          if (k != f) open[topo.tet(t)[k]] = 1;
  return open;
}

TEST(TetTopology, BoundaryVerticesStayWhatTheyWere) {
  TetMesh m = lattice();
  TetTopology topo(m);
  EXPECT_EQ(topo.boundary_vertices(), open_vertices(topo));
  for (uint32_t v = 0; v < topo.num_vertices(); ++v) EXPECT_EQ(topo.on_boundary(v), topo.boundary_vertices()[v] != 0);
  EXPECT_FALSE(topo.on_boundary(13));  // the lattice's one interior vertex
  EXPECT_TRUE(topo.on_boundary(0));
  // A vertex coned into the centre's star is interior, and the boundary
  // (faces of one tet) is the same after the replace.
  std::vector<uint32_t> star, created;
  topo.vertex_star(13, star);
  const double inside[3] = {1.05, 1.0, 0.97};
  const uint32_t w = topo.add_vertex(inside, 0);
  topo.replace(star, cone_tets(topo, star, w), created);
  EXPECT_FALSE(topo.on_boundary(w));
  EXPECT_EQ(topo.boundary_vertices(), open_vertices(topo));
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

// The incidence gathered in one pass lists each vertex's star (ascending
// slots) and neighbours as the star search and star_neighbours find them,
// dead slots left out.
TEST(TetTopology, VertexIncidenceIsTheStarsAndNeighbours) {
  TetMesh m = lattice();
  TetTopology topo(m);
  std::vector<uint32_t> star, created;
  topo.vertex_star(13, star);
  const double* p = topo.point(13);
  const double inside[3] = {p[0] + 0.01, p[1] - 0.02, p[2] + 0.015};
  const uint32_t w = topo.add_vertex(inside, 0);
  topo.replace(star, cone_tets(topo, star, w), created);
  VertexIncidence incidence(topo);
  std::vector<uint32_t> neighbours;
  for (uint32_t v = 0; v < topo.num_vertices(); ++v) {
    topo.vertex_star(v, star);
    std::sort(star.begin(), star.end());
    EXPECT_TRUE(std::equal(star.begin(), star.end(), incidence.star(v).begin(), incidence.star(v).end())) << v;
    topo.star_neighbours(v, star, neighbours);
    EXPECT_TRUE(std::equal(neighbours.begin(), neighbours.end(), incidence.neighbours(v).begin(),
                           incidence.neighbours(v).end()))
        << v;
  }
  EXPECT_TRUE(incidence.star(13).empty());
  EXPECT_EQ(incidence.neighbours(w).size(), 14u);
}

// The qualities measured in blocks are the ones quality() measures one by
// one, bit for bit.
TEST(TetTopology, QualitiesMeasuredTogetherAreTheLazyOnes) {
  TetMesh m = lattice();
  for (size_t i = 0; i < m.xyz.size(); ++i) m.xyz[i] += 0.01 * static_cast<double>((i * 7919) % 13);
  TetMesh copy = m;
  TetTopology together(m), lazy(copy);
  together.measure_qualities();
  for (uint32_t t = 0; t < together.slots(); ++t)
    EXPECT_EQ(std::bit_cast<uint64_t>(together.quality(t)), std::bit_cast<uint64_t>(lazy.quality(t))) << t;
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

TEST(TetTopology, ChangeMarksFollowMovesAndReplaces) {
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

  std::vector<uint32_t> old_tets;
  topo.tet_vertices(star, old_tets);
  const double inside[3] = {1.05, 1.0, 0.97};

  // A replace kept changes the stars of the cavity's vertices.
  const uint32_t before_replace = topo.changes();
  std::vector<uint32_t> created;
  const uint32_t w = topo.add_vertex(inside, 0);
  topo.replace(star, cone_tets(topo, star, w), created);
  std::vector<uint32_t> cavity_vertices = old_tets;
  cavity_vertices.push_back(w);
  const std::vector<bool> after_replace = unchanged(topo, before_replace);
  EXPECT_EQ(after_replace, untouched(topo, cavity_vertices));
  EXPECT_GT(std::count(after_replace.begin(), after_replace.end(), true), 0);
}

}  // namespace
}  // namespace partet
