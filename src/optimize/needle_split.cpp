// split_needles (see needle_split.hpp).
#include "optimize/needle_split.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "core/predicates.hpp"
#include "optimize/cone_bound.hpp"
#include "optimize/failed_splits.hpp"
#include "optimize/insertion.hpp"
#include "optimize/smoothing.hpp"

namespace partet {
namespace {

// Rounds of a sweep: the first over every needle, each later one over the
// needles the previous round's splits made (a split halves the longest
// edge; a needle of edge ratio 6 wants two or three). One round: r1 mean
// radius ratio 0.637, two 0.641, four 0.644 (handle r1 0.401 / 0.416 /
// 0.430) for 2 % more CPU than one.
constexpr int kNeedleRounds = 4;

double squared_length(const double* p, const double* q) {
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

// Scratch of one sweep.
struct Split {
  std::vector<uint32_t> cavity, old_tets, new_tets, created;
};

// Splits the edge of closed ring `ring` at its midpoint if that pays (see
// needle_split.hpp); true when kept.
bool try_split(TetTopology& topo, const TetTopology::Ring& ring, double mean, SmoothingScratch& scratch, Split& s) {
  const double* a = topo.point(ring.a);
  const double* b = topo.point(ring.b);
  const double middle[3] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  s.cavity.assign(ring.tets, ring.tets + ring.n);
  s.old_tets.clear();
  s.new_tets.clear();
  double old_sum = 0;
  for (uint32_t c : s.cavity) {
    s.old_tets.insert(s.old_tets.end(), topo.tet(c), topo.tet(c) + 4);
    old_sum += topo.radius_ratio(c);
  }
  const AngleSummary before = summarize_angles(topo, s.old_tets);
  // Where the ring's angle at an outer edge is under twice its smallest, no
  // position of m keeps that smallest angle (cone_bound.hpp): refused
  // before m is made (a third of handle r1's trials, same meshes).
  if (!cones_can_keep_angle(topo, ring, before.smallest)) return false;
  const uint32_t m = topo.add_vertex(middle, kOptimizerVertexId | topo.num_vertices());
  for (uint32_t c : s.cavity)
    for (uint32_t end : {ring.a, ring.b}) {
      uint32_t tet[4];
      std::copy_n(topo.tet(c), 4, tet);
      tet[local_index(tet, end)] = m;
      if (orient3d(topo.point(tet[0]), topo.point(tet[1]), topo.point(tet[2]), topo.point(tet[3])) <= 0) {
        topo.remove_last_vertex();
        return false;
      }
      s.new_tets.insert(s.new_tets.end(), tet, tet + 4);
    }
  smooth_new_vertex(topo, m, s.new_tets, scratch);
  double new_sum = 0;
  for (size_t i = 0; i < s.new_tets.size(); i += 4) new_sum += radius_ratio_of(topo, &s.new_tets[i]);
  const double added = static_cast<double>(s.new_tets.size() / 4 - s.cavity.size());
  // The radius ratios first: most splits are refused for them (femur r1:
  // 2,132 of 2,645), and the angles cost an atan2 per tet.
  if (new_sum - old_sum >= mean * added && summarize_angles(topo, s.new_tets).no_worse_than(before)) {
    s.created.clear();
    topo.replace(s.cavity, s.new_tets, s.created);
    return true;
  }
  topo.remove_last_vertex();
  return false;
}

}  // namespace

size_t split_needles(TetTopology& topo, double bar, SmoothingScratch& scratch) {
  std::vector<std::pair<double, uint32_t>> needles;
  double sum = 0;
  size_t tets = 0;
  for (uint32_t t = 0; t < topo.slots(); ++t) {
    if (!topo.alive(t)) continue;
    const double r = topo.radius_ratio(t);
    sum += r;
    ++tets;
    if (r < bar) needles.emplace_back(r, t);
  }
  if (needles.empty()) return 0;
  const double mean = sum / static_cast<double>(tets);
  Split s;
  FailedSplits refused(needles.size());  // the needles around one long edge share it
  size_t split = 0;
  std::vector<uint32_t> made;
  for (int round = 0; round < kNeedleRounds && !needles.empty(); ++round) {
    std::sort(needles.begin(), needles.end());
    made.clear();
    for (const auto& [ratio, t] : needles) {
      // A slot may have been refilled by a split since the list was made.
      if (!topo.alive(t) || topo.radius_ratio(t) >= bar) continue;
      const uint32_t* v = topo.tet(t);
      int longest = 0;
      double length = -1;
      for (int e = 0; e < 6; ++e) {
        const double l = squared_length(topo.point(v[kTetEdges[e][0]]), topo.point(v[kTetEdges[e][1]]));
        if (l > length) length = l, longest = e;
      }
      TetTopology::Ring ring;
      if (!topo.edge_ring(t, kTetEdges[longest][0], kTetEdges[longest][1], ring) || refused.known(topo, ring))
        continue;
      if (!try_split(topo, ring, mean, scratch, s)) {
        refused.add(topo, ring);
        continue;
      }
      ++split;
      made.insert(made.end(), s.created.begin(), s.created.end());
    }
    // The next round: the tets the splits made that are still needles
    // (a refused split would be refused again: its ring has not changed).
    std::sort(made.begin(), made.end());
    made.erase(std::unique(made.begin(), made.end()), made.end());
    needles.clear();
    for (uint32_t t : made) {
      if (!topo.alive(t)) continue;
      const double r = topo.radius_ratio(t);
      if (r < bar) needles.emplace_back(r, t);
    }
  }
  return split;
}

}  // namespace partet
