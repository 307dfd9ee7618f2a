// optimize_mesh (see optimize.hpp). A pass has its own target: the
// quality target in the first, lower in the later ones (kLaterPassAngles).
//  1. topology: the tets below it, worst first (ties by slot) in
//     each block of 4096 slots, block after block (tets_below), each
//     offered every flip of its 6 edges and 4 faces; the candidate with the
//     best new worst quality is applied if it beats its cavity's worst. New
//     tets still below it join the end of the work list, whose
//     length is capped.
//  2. insertion: a new interior vertex for each tet still below the
//     insertion bar, in the same order, where it pays (insertion.hpp), else
//     one of its vertices collapsed where that pays (collapse.hpp); not in the
//     last of two or more passes, which leaves the vertices of the earlier
//     ones to the flips and smoothing (docs/decisions.md, "No vertex
//     insertion in the last optimizer pass": 11 % of the optimizer's time
//     for somewhat more slivers on the CAD parts);
//  3. smoothing: the free vertices of the tets still below the pass's
//     target or 30 degrees, whichever is lower, in index order (inserted vertices
//     are free).
// After the passes, one sweep of multi-face removals (multi_face_pass),
// rounds on the mesh's worst tet (worst_tet_rounds, with joint smoothing
// of tied worst tets: joint_smoothing.hpp; more rounds while the worst tet
// is under 1 degree), a sweep of needle splits (needle_split.hpp), then the
// relaxation sweeps (relaxation_sweep, two by default). Each
// change of the passes strictly raises the ascending sequence of tet
// qualities in lexicographic order; with the caps this bounds the work.
#include "optimize/optimize.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numbers>
#include <queue>
#include <utility>

#include "check/quality.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "optimize/collapse.hpp"
#include "optimize/failed_edges.hpp"
#include "optimize/failure_record.hpp"
#include "optimize/flips.hpp"
#include "optimize/insertion.hpp"
#include "optimize/joint_smoothing.hpp"
#include "optimize/needle_split.hpp"
#include "optimize/sheet_lift.hpp"
#include "optimize/smoothing.hpp"
#include "optimize/tet_order.hpp"
#include "optimize/tet_quality.hpp"
#include "optimize/tet_topology.hpp"
#include "optimize/vertex_incidence.hpp"

namespace partet {
namespace {

// Edge removals remembered as failed at a time (FailedEdges): the passes go
// block by block, so the failures asked about again are recent ones, and a
// table of 64 KiB stays in cache where one sized by the mesh missed on
// every lookup.
constexpr size_t kFailedEdges = 2048;

// Work list entries per tet below the target at the start of a pass.
constexpr size_t kWorkPerBadTet = 4;
// Smoothing works on the tets under this angle (or the target if lower):
// raising the worst angle of stars whose tets are all above it cost mean
// radius ratio, which the relaxation sweeps then win back for less.
constexpr double kSmoothingAngle = 30;

// Tets whose flip search last found nothing (failure_record.hpp): the
// search reads only the stars of the tet's vertices, so the meshes are the
// same byte for byte (a slot reused by a new tet has its vertices' marks
// past the count).
using FailedFlips = FailureRecord<&TetTopology::unchanged_since>;

// The passes after the first work on the tets under these angles (the
// last one for every later pass), or under the target if it is lower:
// what the first pass leaves under the target mostly stays there, and
// the second and third passes spent their time offering it the same flips
// and moves (elephant r1: 74,000 flip searches for 4,600 flips). Over the
// 64 inputs (originals and once refined) against three passes at the
// target: the optimizer -17 %, the median tets per second +15 %, share
// under 10 degrees 2.46 -> 2.15 % (mean over inputs), mean radius ratio
// 0.6330 -> 0.6347, mean smallest angle 19.56 -> 19.23 degrees; two passes
// instead cost share under 10 degrees (2.87 %) for about the same time.
constexpr double kLaterPassAngles[] = {25, 10};

double later_pass_angle(int pass) {
  constexpr int last = static_cast<int>(std::size(kLaterPassAngles)) - 1;
  return pass == 0 ? 90 : kLaterPassAngles[std::min(pass - 1, last)];
}

// Tets are taken in blocks of 2^kOrderBlockBits consecutive slots, worst
// first within each block. Slots follow space (optimize_mesh puts the tets
// in Morton order first: tet_order.hpp), so a pass stays in one region of
// the mesh at a time; worst first over the whole mesh sent every
// operation to a random place, and on millions of tets each then waited on
// memory (blobby r3, 2.8 M tets: the topology passes 8.0 -> 5.2 s, same
// quality).
constexpr int kOrderBlockBits = 12;

// Alive tets below `target`, block by block, worst first in each.
std::vector<uint32_t> tets_below(const TetTopology& topo, double target) {
  std::vector<std::pair<double, uint32_t>> bad;
  for (uint32_t t = 0; t < topo.slots(); ++t) {
    if (!topo.alive(t)) continue;
    const double q = topo.quality(t);
    if (q < target) bad.emplace_back(q, t);
  }
  std::sort(bad.begin(), bad.end(), [](const std::pair<double, uint32_t>& x, const std::pair<double, uint32_t>& y) {
    const uint32_t bx = x.second >> kOrderBlockBits, by = y.second >> kOrderBlockBits;
    return bx != by ? bx < by : x < y;
  });
  std::vector<uint32_t> tets(bad.size());
  for (size_t i = 0; i < bad.size(); ++i) tets[i] = bad[i].second;
  return tets;
}

void count(const Flip& flip, OptimizeStats& stats) {
  switch (flip.kind) {
    case FlipKind::k23: ++stats.flips_23; break;
    case FlipKind::k32: ++stats.flips_32; break;
    case FlipKind::k44: ++stats.flips_44; break;
    case FlipKind::kEdgeRemoval: ++stats.edge_removals; break;
    case FlipKind::kMultiFace: ++stats.multi_face_removals; break;
  }
}

// The best improving flip around tet t; false when there is none. With
// `failed_edges`, the edge removals it knows are not searched, and those
// that find nothing against their ring's worst tet are added.
bool best_flip(const TetTopology& topo, uint32_t t, Flip& best, FailedEdges* failed_edges = nullptr) {
  Flip candidate;
  bool found = false;
  auto consider = [&](bool valid) {
    if (valid && candidate.new_quality > candidate.old_quality &&
        (!found || candidate.new_quality > best.new_quality)) {
      best = candidate;
      found = true;
    }
  };
  // Each search looks only for flips beating the best one so far.
  double beat = -std::numeric_limits<double>::infinity();
  for (const auto& e : kTetEdges) {
    const uint32_t a = topo.tet(t)[e[0]], b = topo.tet(t)[e[1]];
    if (failed_edges && failed_edges->known(topo, a, b)) continue;
    const bool removal = edge_removal(topo, t, e[0], e[1], candidate, &beat);
    // Before any candidate the bar is the ring's worst tet: a failure then
    // holds for every later bar.
    if (!removal && !found && failed_edges) failed_edges->add(topo, a, b);
    consider(removal);
    if (found) beat = best.new_quality;
  }
  for (uint32_t f = 0; f < 4; ++f) {
    consider(face_flip(topo, 4 * t + f, candidate, &beat));
    if (found) beat = best.new_quality;
  }
  return found;
}

// Applies the best improving flip around tet t; the new tets go to `created`.
bool improve_topology(TetTopology& topo, uint32_t t, OptimizeStats& stats, std::vector<uint32_t>& created,
                      FailedEdges& failed_edges) {
  Flip best;
  if (!best_flip(topo, t, best, &failed_edges)) return false;
  topo.replace(best.cavity(), best.replacement(), created);
  count(best, stats);
  return true;
}

// Step 1 of a pass; the number of flips applied.
size_t topology_pass(TetTopology& topo, double target, OptimizeStats& stats, FailedFlips& failed,
                     FailedEdges& failed_edges) {
  std::vector<uint32_t> work = tets_below(topo, target);
  const size_t cap = kWorkPerBadTet * work.size();
  std::vector<uint32_t> created;
  size_t applied = 0;
  for (size_t i = 0; i < work.size() && i < cap; ++i) {
    const uint32_t t = work[i];
    if (!topo.alive(t) || topo.quality(t) >= target || failed.known(topo, t)) continue;
    created.clear();
    if (!improve_topology(topo, t, stats, created, failed_edges)) {
      failed.add(topo, t);
      continue;
    }
    ++applied;
    for (uint32_t c : created)
      if (topo.quality(c) < target) work.push_back(c);
  }
  return applied;
}

// After the passes: each tet still below the target, in that order, is
// offered its best multi-face removal, applied when it lifts the cavity's
// worst tet, adds no tet under 10 degrees and gains radius ratio at least
// the mesh's mean per tet it adds (a removal takes tets away: it may lose
// that much per tet). None of the three measures can get worse, and the
// passes' path is left as it was (multi-face removals inside the passes
// changed which tets insertion and smoothing saw, and cost the smallest
// angle on refined inputs). The number applied.
size_t multi_face_pass(TetTopology& topo, double target, OptimizeStats& stats) {
  const std::vector<uint32_t> work = tets_below(topo, target);
  if (work.empty()) return 0;
  double sum = 0;
  size_t tets = 0;
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t)) {
      sum += topo.radius_ratio(t);
      ++tets;
    }
  const double mean = sum / static_cast<double>(tets);
  const double ten = quality_of_angle(10);
  std::vector<uint32_t> created;
  size_t applied = 0;
  for (uint32_t t : work) {
    if (!topo.alive(t) || topo.quality(t) >= target) continue;
    Flip best, candidate;
    bool found = false;
    double beat = -std::numeric_limits<double>::infinity();
    for (uint32_t f = 0; f < 4; ++f) {
      if (!multi_face_removal(topo, 4 * t + f, candidate, &beat)) continue;
      double gain = 0;
      int old_slivers = 0, new_slivers = 0;
      for (int i = 0; i < candidate.old_count; ++i) {
        gain -= topo.radius_ratio(candidate.old_tets[i]);
        old_slivers += topo.quality(candidate.old_tets[i]) < ten;
      }
      for (int i = 0; i < candidate.new_count; ++i) {
        const uint32_t* v = &candidate.new_tets[4 * i];
        gain += radius_ratio_of(topo, v);
        new_slivers += tet_quality(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3])) < ten;
      }
      if (new_slivers > old_slivers || gain < mean * (candidate.new_count - candidate.old_count)) continue;
      best = candidate;
      found = true;
      beat = best.new_quality;
    }
    if (!found) continue;
    created.clear();
    topo.replace(best.cavity(), best.replacement(), created);
    count(best, stats);
    ++applied;
  }
  return applied;
}

// Tets below this radius ratio have their free vertices relaxed (the
// templated core's tets are at 0.64 to 0.95 and gain nothing).
constexpr double kRelaxBelow = 0.75;

// The vertices of `tets` that are not frozen (inserted ones, beyond
// `frozen`, are free), ascending, each once.
std::vector<uint32_t> free_vertices_of(const TetTopology& topo, const std::vector<uint32_t>& tets,
                                       const std::vector<uint8_t>& frozen) {
  // Marks take each vertex once (a vertex is in many of the tets), so only
  // the distinct ones are sorted.
  std::vector<uint8_t> taken(topo.num_vertices(), 0);
  std::vector<uint32_t> vertices;
  for (uint32_t t : tets)
    for (int k = 0; k < 4; ++k) {
      const uint32_t v = topo.tet(t)[k];
      if ((v < frozen.size() && frozen[v]) || taken[v]) continue;
      taken[v] = 1;
      vertices.push_back(v);
    }
  std::sort(vertices.begin(), vertices.end());
  return vertices;
}

// The relaxation may lower a star's worst tet down to this angle (degrees),
// never below the mesh's smallest angle: the tets under it are the ones
// the insertion counts as bad (its shortfall bar). Keeping each star's
// worst tet, the relaxation left the passes' good tets where the smoothing
// had put them; with this room the mean radius ratio over the 64 r0 and r1
// inputs rose 0.6342 -> 0.6414 (femur r1 0.785 -> 0.795, eight r1 0.687 ->
// 0.706, sphere966 r0 0.738 -> 0.752), the smallest angle and the share
// under 10 degrees at or past the best peer's on all 64 as before, the
// share under 20 degrees the same (femur r1 0.56 %), for 5.6 % more
// optimizer time (more moves, and the second sweep tries every vertex that
// moved), which the measures the trials hand back to the topology then
// won back (smoothing.cpp). With one sweep the mean radius ratio stays where it was (0.6338)
// and the optimizer takes 9 % less; 10 degrees gave a little more (femur r1
// 0.798) for twice as many tets under 20.
constexpr double kRelaxFloorAngle = 20;

// The relaxation's floor: the quality of kRelaxFloorAngle or of the mesh's
// smallest dihedral angle, whichever is larger (a hair above it). A tet of
// quality q has no dihedral angle under asin(q / kRegularSineScale) (nor
// over 180 minus it), so only the tets of lower quality than the worst
// tet's smallest angle gives need their angles.
double relaxation_floor(const TetTopology& topo) {
  uint32_t worst = TetTopology::kNone;
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t) && (worst == TetTopology::kNone || topo.quality(t) < topo.quality(worst))) worst = t;
  if (worst == TetTopology::kNone) return quality_of_angle(kRelaxFloorAngle);
  auto smallest_angle = [&](uint32_t t) { return summarize_angles(topo, {topo.tet(t), 4}).smallest; };
  auto degrees = [](double radians) { return radians * 180 / std::numbers::pi; };
  double smallest = smallest_angle(worst);
  const double below = quality_of_angle(degrees(smallest));
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t) && topo.quality(t) < below) smallest = std::min(smallest, smallest_angle(t));
  // A relative margin over the rounding between the angles and the
  // qualities: the mesh's smallest angle must not drop by an ulp either.
  return quality_of_angle(std::max(kRelaxFloorAngle, degrees(smallest))) * (1 + 1e-9);
}

// After the passes: relax_vertex (with `floor`, relaxation_floor) on the
// free vertices of the tets below kRelaxBelow, in index order, skipping
// those with `settled` set; the number moved. relax_vertex depends only on
// the star's points, so a vertex that stays where it is gets `settled`
// until it or a neighbour moves: a later sweep would try the same points
// and refuse them again.
size_t relaxation_sweep(TetTopology& topo, VertexIncidence& incidence, const std::vector<uint8_t>& frozen,
                        std::vector<uint8_t>& settled, SmoothingScratch& scratch, double floor) {
  std::vector<uint32_t> low;
  for (uint32_t t = 0; t < topo.slots(); ++t)
    if (topo.alive(t) && topo.radius_ratio(t) < kRelaxBelow) low.push_back(t);
  const std::vector<uint32_t> vertices = free_vertices_of(topo, low, frozen);
  settled.resize(topo.num_vertices(), 0);
  size_t moved = 0;
  for (uint32_t v : vertices) {
    if (settled[v]) continue;
    const bool move = relax_vertex(topo, v, incidence.star(v), incidence.neighbours(v), scratch, floor);
    settled[v] = !move;
    if (!move) continue;
    ++moved;
    for (uint32_t u : incidence.neighbours(v)) settled[u] = 0;
  }
  return moved;
}

// Step 2 of a pass: each tet below the insertion bar, block by block and
// worst first in each, gets a vertex where that pays, else loses one
// (collapse_vertex) where that pays; the number of vertices inserted or
// collapsed.
size_t insertion_pass(TetTopology& topo, double target, const std::vector<uint8_t>& frozen, bool collapse,
                      OptimizeStats& stats, SmoothingScratch& scratch, FailedSplits& failed_splits,
                      RefusedCollapses& refused_collapses) {
  const size_t before = stats.vertices_inserted + stats.vertices_collapsed;
  const double bar = insertion_bar(target);
  for (uint32_t t : tets_below(topo, bar)) {
    if (!topo.alive(t) || topo.quality(t) >= bar) continue;
    if (insert_vertex(topo, t, target, scratch, InsertionRule::kShortfall, nullptr, false, &failed_splits))
      ++stats.vertices_inserted;
    else if (collapse && collapse_vertex(topo, t, frozen, bar, InsertionRule::kShortfall, &refused_collapses))
      ++stats.vertices_collapsed;
  }
  return stats.vertices_inserted + stats.vertices_collapsed - before;
}

struct JointScratch {
  std::vector<uint32_t> vertices, region, tets;
  std::vector<double> old_positions;
};

// Past options.worst_tet_rounds, the rounds go on (options.flat_tet_rounds
// more at most) only while the worst tet has an angle under this many
// degrees: more rounds on a mesh whose worst tet is fair trade radius ratio
// for a degree (star r1 31.9 -> 35.2 degrees, 0.735 -> 0.688).
constexpr double kFlatAngle = 1;

// The worst-tet rounds seek the worst tet among about this many of the
// worst and the tets changed since (worst_tet_rounds), not over every slot.
constexpr size_t kLowTets = 1024;

// Tets within this quality of the worst one lend their free corners to a
// joint move (kJointVertices at most).
constexpr double kJointBand = 0.05;
constexpr size_t kJointVertices = 32;

// The tied_vertices of tet `worst` moved together (smooth_jointly); kept
// when the worst tet gains, the smallest dihedral angle of the tets around
// them does not drop and no more of them are under 10 degrees. True if
// kept.
bool smooth_worst_jointly(TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen, JointScratch& s) {
  tied_vertices(topo, worst, frozen, kJointBand, kJointVertices, s.vertices);
  if (s.vertices.size() < 2) return false;
  joint_region(topo, s.vertices, s.region);
  topo.tet_vertices(s.region, s.tets);
  const AngleSummary old_angles = summarize_angles(topo, s.tets);
  s.old_positions.clear();
  for (uint32_t v : s.vertices) s.old_positions.insert(s.old_positions.end(), topo.point(v), topo.point(v) + 3);
  const double stuck = topo.quality(worst);
  if (!smooth_jointly(topo, s.vertices, s.region)) return false;
  topo.tet_vertices(s.region, s.tets);
  if (summarize_angles(topo, s.tets).no_worse_than(old_angles) && topo.quality(worst) > stuck) return true;
  for (size_t i = 0; i < s.vertices.size(); ++i) topo.move_vertex(s.vertices[i], &s.old_positions[3 * i]);
  return false;
}

// After the passes: the mesh's worst tet, while it is below the target,
// gets the topology step, then an insertion, then a collapse, then its free
// vertices smoothed, then (when none moves) the free vertices around them
// smoothed before them again, which counts only when the worst tet gains,
// then (when that fails too) the free vertices of the near-worst tets
// around it moved together (smooth_worst_jointly), then, for a tet under
// kSheetAngle, the sheet of nearly flat tets around it lifted (lift_sheet);
// each change is kept only when the smallest dihedral angle of the tets it
// changes does not drop and no more of them have one under 10 degrees
// (min_angle_no_worse), until none of them changes anything (see
// OptimizeOptions::set_aside_stuck_on_frozen for the exception) or after `rounds`
// (the passes leave alone a tet above the insertion bar, so a small mesh's
// smallest angle could stay where a vertex would lift it: the cube's six
// tets of 35.3 degrees become twelve of 45 around a centre vertex).
void worst_tet_rounds(TetTopology& topo, double target, const OptimizeOptions& options,
                      const std::vector<uint8_t>& frozen, const std::vector<uint8_t>* caller_frozen,
                      OptimizeStats& stats, SmoothingScratch& scratch) {
  std::vector<uint32_t> created, before, star, neighbours;
  JointScratch joint;
  CavityGrowth growth{frozen};
  const auto free_vertex = [&](uint32_t v) { return !(v < frozen.size() && frozen[v]); };
  // Smooths free vertex v, kept only when its star's angles get no worse.
  const auto guarded_smooth = [&](uint32_t v) {
    const double old_position[3] = {topo.point(v)[0], topo.point(v)[1], topo.point(v)[2]};
    topo.vertex_star(v, scratch.star);
    topo.tet_vertices(scratch.star, star);
    const AngleSummary old_angles = summarize_angles(topo, star);
    if (!smooth_vertex(topo, v, scratch)) return false;
    if (summarize_angles(topo, star).no_worse_than(old_angles)) {
      ++stats.vertices_moved;
      return true;
    }
    topo.move_vertex(v, old_position);
    return false;
  };
  const double flat = quality_of_angle(kFlatAngle);
  const int rounds = options.worst_tet_rounds > 0 ? options.worst_tet_rounds + options.flat_tet_rounds : 0;
  // Past options.worst_tet_rounds only a tet under `flat` matters: the
  // worst is sought among those (ascending slots, as the whole scan) and
  // the tets changed since, not over the whole mesh every round (femur r3:
  // 5.4 M tets, hundreds of rounds).
  std::vector<uint32_t> flat_tets, changed_tets;
  // Tets set aside (options.set_aside_stuck_on_frozen): slot and corners,
  // so a slot reused by a new tet counts again.
  std::vector<std::array<uint32_t, 5>> aside;
  const auto set_aside = [&](uint32_t t) {
    for (const auto& a : aside)
      if (a[0] == t && std::equal(a.begin() + 1, a.end(), topo.tet(t))) return true;
    return false;
  };
  const auto on_caller_frozen = [&](uint32_t t) {
    for (int k = 0; k < 4; ++k) {
      const uint32_t v = topo.tet(t)[k];
      if (caller_frozen && v < caller_frozen->size() && (*caller_frozen)[v]) return true;
    }
    return false;
  };
  const auto worse = [&](uint32_t t, uint32_t than) {
    return (than == TetTopology::kNone || topo.quality(t) < topo.quality(than)) && (aside.empty() || !set_aside(t));
  };
  // The first rounds' worst tet is the one a scan of every slot finds (the
  // lowest quality, then the lowest slot), sought among `low`: the
  // kLowTets worst at the last scan, whose qualities lie under `cut` but
  // for ties at it, and the tets changed since (every other tet is at `cut`
  // or above). When none of them is under `cut`, a scan refills `low`.
  std::vector<uint32_t> low;
  double cut = -std::numeric_limits<double>::infinity();
  const auto scan_low = [&] {
    std::priority_queue<std::pair<double, uint32_t>> worst_seen;  // the kLowTets smallest (quality, slot)
    for (uint32_t t = 0; t < topo.slots(); ++t) {
      if (!topo.alive(t) || (!aside.empty() && set_aside(t))) continue;
      const std::pair<double, uint32_t> key{topo.quality(t), t};
      if (worst_seen.size() < kLowTets) {
        worst_seen.push(key);
      } else if (key < worst_seen.top()) {
        worst_seen.pop();
        worst_seen.push(key);
      }
    }
    cut = worst_seen.size() < kLowTets ? std::numeric_limits<double>::infinity() : worst_seen.top().first;
    low.clear();
    for (; !worst_seen.empty(); worst_seen.pop()) low.push_back(worst_seen.top().second);
    changed_tets.clear();
  };
  // Adds the tets changed since the last call to `tets` (kept ascending,
  // each once), drops the dead ones and those not under `below`, and
  // returns the worst of the rest, ties to the lowest slot (kNone if none).
  const auto merge_changed_worst = [&](std::vector<uint32_t>& tets, double below) {
    tets.insert(tets.end(), changed_tets.begin(), changed_tets.end());
    changed_tets.clear();
    std::sort(tets.begin(), tets.end());
    tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
    std::erase_if(tets, [&](uint32_t t) { return !topo.alive(t) || !(topo.quality(t) < below); });
    uint32_t worst = TetTopology::kNone;
    for (uint32_t t : tets)
      if (worse(t, worst)) worst = t;
    return worst;
  };
  const double everything = std::numeric_limits<double>::infinity();
  topo.log_changes(&changed_tets);
  for (int round = 0; round < rounds; ++round) {
    uint32_t worst = TetTopology::kNone;
    if (round < options.worst_tet_rounds) {
      worst = merge_changed_worst(low, everything);
      if (worst == TetTopology::kNone || !(topo.quality(worst) < cut)) {
        scan_low();
        worst = merge_changed_worst(low, everything);
      }
    } else {
      if (round == options.worst_tet_rounds)
        for (uint32_t t = 0; t < topo.slots(); ++t)
          if (topo.alive(t) && topo.quality(t) < flat) flat_tets.push_back(t);
      worst = merge_changed_worst(flat_tets, flat);
    }
    if (worst == TetTopology::kNone || !(topo.quality(worst) < target)) break;
    bool changed = false;
    Flip flip;
    if (best_flip(topo, worst, flip)) {
      topo.tet_vertices(flip.cavity(), before);
      if (min_angle_no_worse(topo, before, flip.replacement())) {
        created.clear();
        topo.replace(flip.cavity(), flip.replacement(), created);
        count(flip, stats);
        changed = true;
      }
    }
    if (!changed && options.insert_vertices &&
        insert_vertex(topo, worst, target, scratch, InsertionRule::kWorstFirst,
                      options.grow_cavities ? &growth : nullptr, options.corner_vertices)) {
      ++stats.vertices_inserted;
      changed = true;
    }
    if (!changed && options.collapse_vertices &&
        collapse_vertex(topo, worst, frozen, insertion_bar(target), InsertionRule::kWorstFirst)) {
      ++stats.vertices_collapsed;
      changed = true;
    }
    if (!changed) {
      uint32_t corners[4];
      std::copy_n(topo.tet(worst), 4, corners);
      for (uint32_t v : corners)
        if (free_vertex(v) && guarded_smooth(v)) changed = true;
      if (!changed && options.smooth_around_worst) {
        // The free corners sit where their stars' worst tets balance:
        // their free neighbours, moved first, may give them room.
        const double stuck = topo.quality(worst);
        neighbours.clear();
        for (uint32_t v : corners) {
          if (!free_vertex(v)) continue;
          topo.vertex_star(v, scratch.star);
          for (uint32_t s : scratch.star)
            for (int k = 0; k < 4; ++k) neighbours.push_back(topo.tet(s)[k]);
        }
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        bool moved = false;
        for (uint32_t u : neighbours)
          if (std::find(corners, corners + 4, u) == corners + 4 && free_vertex(u)) moved = guarded_smooth(u) || moved;
        if (moved)
          for (uint32_t v : corners)
            if (free_vertex(v)) guarded_smooth(v);
        changed = topo.quality(worst) > stuck;
      }
      if (!changed && options.smooth_jointly) changed = smooth_worst_jointly(topo, worst, frozen, joint);
      if (!changed && options.lift_sheets && lift_sheet(topo, worst, frozen)) {
        ++stats.sheets_lifted;
        changed = true;
      }
    }
    if (!changed &&
        !(options.set_aside_stuck_on_frozen && round < options.worst_tet_rounds && on_caller_frozen(worst)))
      break;
    if (!changed) {
      std::array<uint32_t, 5> a{worst};
      std::copy_n(topo.tet(worst), 4, a.begin() + 1);
      aside.push_back(a);
    }
  }
  topo.log_changes(nullptr);
  stats.vertices_removed += growth.vertices_removed;
}

// Step 3 of a pass; the number of vertices moved.
size_t smoothing_pass(TetTopology& topo, double target, const std::vector<uint8_t>& frozen,
                      SmoothingScratch& scratch) {
  size_t moved = 0;
  for (uint32_t v : free_vertices_of(topo, tets_below(topo, target), frozen)) moved += smooth_vertex(topo, v, scratch);
  return moved;
}

}  // namespace

OptimizeStats optimize_mesh(TetMesh& mesh, const OptimizeOptions& options, const std::vector<uint8_t>* frozen) {
  Stopwatch clock;
  OptimizeStats stats;
  Stopwatch part;
  stats.before = measure_quality(mesh);
  stats.measure_seconds += part.wall();
  if (options.passes > 0 && mesh.num_tets() > 0) {
    PARTET_ASSERT(!frozen || frozen->size() == mesh.num_vertices(), "one frozen flag per vertex");
    sort_tets_by_space(mesh);
    TetTopology topo(mesh);
    topo.measure_qualities();
    std::vector<uint8_t> fixed = topo.boundary_vertices();
    for (uint32_t v : mesh.tris) fixed[v] = 1;
    if (frozen)
      for (size_t v = 0; v < fixed.size(); ++v) fixed[v] |= (*frozen)[v] != 0;
    const double target = quality_of_angle(options.quality_target_deg);
    SmoothingScratch scratch;
    FailedFlips failed_flips;
    FailedEdges failed_edges(kFailedEdges);
    FailedSplits failed_splits(topo.slots() / 4);
    RefusedCollapses refused_collapses;
    for (int pass = 0; pass < options.passes; ++pass) {
      ++stats.passes;
      part = Stopwatch();
      const double pass_target =
          options.lower_later_targets ? std::min(target, quality_of_angle(later_pass_angle(pass))) : target;
      const size_t flips = topology_pass(topo, pass_target, stats, failed_flips, failed_edges);
      stats.topology_seconds += part.wall();
      part = Stopwatch();
      const bool last_of_several = options.passes > 1 && pass + 1 == options.passes;
      const size_t inserted = options.insert_vertices && !last_of_several
                                  ? insertion_pass(topo, target, fixed, options.collapse_vertices, stats, scratch,
                                                   failed_splits, refused_collapses)
                                  : 0;
      stats.insertion_seconds += part.wall();
      part = Stopwatch();
      const size_t moved =
          smoothing_pass(topo, std::min(pass_target, quality_of_angle(kSmoothingAngle)), fixed, scratch);
      stats.smoothing_seconds += part.wall();
      stats.vertices_moved += moved;
      if (flips == 0 && inserted == 0 && moved == 0) break;
    }
    if (options.multi_face_sweep) {
      part = Stopwatch();
      multi_face_pass(topo, target, stats);
      stats.topology_seconds += part.wall();
    }
    part = Stopwatch();
    worst_tet_rounds(topo, target, options, fixed, frozen, stats, scratch);
    if (options.needle_radius_ratio > 0 && options.insert_vertices)
      stats.needles_split += split_needles(topo, options.needle_radius_ratio, scratch);
    stats.insertion_seconds += part.wall();
    part = Stopwatch();
    if (options.relaxation_sweeps > 0) {
      std::vector<uint8_t> settled;
      const double floor = relaxation_floor(topo);
      VertexIncidence incidence(topo);
      for (int sweep = 0; sweep < options.relaxation_sweeps; ++sweep)
        stats.vertices_relaxed += relaxation_sweep(topo, incidence, fixed, settled, scratch, floor);
    }
    stats.relaxation_seconds += part.wall();
    topo.compact();
  }
  part = Stopwatch();
  stats.after = options.passes > 0 ? measure_quality(mesh) : stats.before;
  stats.measure_seconds += part.wall();
  stats.seconds = clock.wall();
  return stats;
}

}  // namespace partet
