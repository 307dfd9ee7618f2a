// insert_vertex (see insertion.hpp). A trial's new vertex is smoothed in
// its would-be star (smooth_new_vertex) before any tet changes: only an
// insertion that pays replaces the cavity (most trials fail: on handle r1
// 20,000 of 23,000, whose apply-and-undo replace pairs were 8 % of the
// run).
#include "optimize/insertion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "check/quality.hpp"
#include "core/kernel_point.hpp"
#include "core/predicates.hpp"
#include "optimize/cone_bound.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

// The shortfall is measured below min(target, this angle in degrees): with
// the full target, a new vertex never pays off; with none, one bad tet is
// traded for a dozen barely better ones.
constexpr double kShortfallAngle = 20;
// A tet with an angle under this many degrees counts as a sliver: replacing
// one by tets all above it pays even when the shortfall grows.
constexpr double kSliverAngle = 10;
// The mesh's worst tet with an angle under this many degrees is all but
// flat: lifting it pays even when more of the new tets are slivers.
constexpr double kDegenerateAngle = 1;
// The mesh's worst tet with an angle under this many degrees may give way
// to tets with kTradeSlivers more slivers among them when the smallest
// angle rises, kDoublingTradeSlivers when it at least doubles.
constexpr double kTradeAngle = 5;
constexpr int kTradeSlivers = 1;
constexpr int kDoublingTradeSlivers = 3;
// Step 6's cavity grows at most this many times, and no further once it
// has more than this many tets.
constexpr int kGrowRounds = 6;
constexpr size_t kGrowTets = 96;
// Outer faces nearer the kernel's deepest point than this many times its
// depth hold it down: step 6 grows across them.
constexpr double kTight = 2;
// Step 6's cavity toward a point above a face grows at most this many
// times, and no further once it has more than this many tets: under a
// sheet of flat tets on a planar part of the surface (joint r3: 89 tets
// under 1e-6 degrees, all their corners on one plane) it needs 40 to 200
// tets, reached a few at a time.
constexpr int kRiseRounds = 48;
constexpr size_t kRiseTets = 384;
// Step 5's points: these shares of the way from a corner to the deepest
// point of its star's kernel.
constexpr double kCornerShares[] = {1.0 / 4, 1.0 / 16, 1.0 / 64, 1.0 / 256};

// `items` sorted, duplicates dropped: membership by binary search (a
// cavity around a tet's four vertices has about 70 tets).
std::vector<uint32_t> sorted_copy(std::vector<uint32_t> items) {
  std::sort(items.begin(), items.end());
  items.erase(std::unique(items.begin(), items.end()), items.end());
  return items;
}

// Face `code` of a tet of the cavity whose tets are `members` (sorted)
// is an outer face: no tet behind it, or one outside the cavity.
bool outer_face(const TetTopology& topo, const std::vector<uint32_t>& members, uint32_t code) {
  const uint32_t other = topo.twin(code);
  return other == TetTopology::kNone || !std::binary_search(members.begin(), members.end(), other / 4);
}

double quality_of(const TetTopology& topo, const uint32_t* v) {
  return tet_quality(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3]));
}

// min_angle_no_worse for `new_tets` against `old_tets` (vertex
// quadruples); with `trade`, one more sliver may come, three when the
// smallest angle at least doubles.
bool new_angles_no_worse(const TetTopology& topo, const std::vector<uint32_t>& old_tets,
                         const std::vector<uint32_t>& new_tets, bool trade) {
  const AngleSummary before = summarize_angles(topo, old_tets), after = summarize_angles(topo, new_tets);
  const int extra = !trade ? 0 : after.smallest >= 2 * before.smallest ? kDoublingTradeSlivers : kTradeSlivers;
  return after.no_worse_than(before, extra);
}

// The worst tet_quality of the tets of `cavity`.
double worst_quality(const TetTopology& topo, const std::vector<uint32_t>& cavity) {
  double worst = std::numeric_limits<double>::infinity();
  for (uint32_t c : cavity) worst = std::min(worst, topo.quality(c));
  return worst;
}

// Inserts a vertex at p into `cavity` if that pays (see insertion.hpp).
// With `settled` (p is already a good place, e.g. a kernel's deepest
// point), a cone no better than the cavity before smoothing is not tried.
bool try_cavity(TetTopology& topo, const std::vector<uint32_t>& cavity, const double* p, double bar,
                SmoothingScratch& scratch, InsertionRule rule, bool settled = false,
                CavityGrowth* growth = nullptr) {
  std::vector<uint32_t> old_tets, new_tets;
  const std::vector<uint32_t> members = sorted_copy(cavity);
  double old_quality = std::numeric_limits<double>::infinity();
  double old_deficit = 0, new_deficit = 0;  // sum of max(0, bar - quality)
  for (uint32_t t : cavity) {
    old_tets.insert(old_tets.end(), topo.tet(t), topo.tet(t) + 4);
    const double q = topo.quality(t);
    old_quality = std::min(old_quality, q);
    old_deficit += std::max(0.0, bar - q);
  }
  const uint32_t v = topo.add_vertex(p, kOptimizerVertexId | topo.num_vertices());
  // Each outer face is coned to v: its tet with the opposite vertex replaced.
  for (uint32_t t : cavity) {
    for (int f = 0; f < 4; ++f) {
      if (!outer_face(topo, members, 4 * t + f)) continue;
      uint32_t tet[4];
      std::copy_n(topo.tet(t), 4, tet);
      tet[f] = v;
      if (orient3d(topo.point(tet[0]), topo.point(tet[1]), topo.point(tet[2]), topo.point(tet[3])) <= 0) {
        topo.remove_last_vertex();
        return false;
      }
      new_tets.insert(new_tets.end(), tet, tet + 4);
    }
  }
  // A vertex inside the cavity (on no outer face) would vanish: only a free
  // one, and only with `growth` (whose flags say which are free).
  const std::vector<uint32_t> kept = sorted_copy(new_tets);
  std::vector<uint32_t> vanished;
  for (uint32_t u : old_tets) {
    if (std::binary_search(kept.begin(), kept.end(), u)) continue;
    if (!growth || (u < growth->frozen.size() && growth->frozen[u])) {
      topo.remove_last_vertex();
      return false;
    }
    vanished.push_back(u);
  }
  if (settled) {
    double start = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < new_tets.size(); i += 4) start = std::min(start, quality_of(topo, &new_tets[i]));
    if (!(start > old_quality)) {
      topo.remove_last_vertex();
      return false;
    }
  }
  smooth_new_vertex(topo, v, new_tets, scratch);
  double new_quality = std::numeric_limits<double>::infinity();
  for (const double q : scratch.quality) {
    new_quality = std::min(new_quality, q);
    new_deficit += std::max(0.0, bar - q);
  }
  // Kept when the worst tet improves and either the shortfall does not grow
  // or a tet under 10 degrees gives way to tets all above (kShortfall), or
  // the smallest dihedral angle does not drop and the tets with one under
  // 10 degrees do not grow in number, or the worst tet was under
  // kDegenerateAngle, or under kTradeAngle with one more sliver at most
  // (kWorstFirst).
  const double ten = quality_of_angle(kSliverAngle);
  const bool pays = rule == InsertionRule::kShortfall
                        ? new_deficit <= old_deficit || (old_quality < ten && new_quality >= ten)
                        : old_quality < quality_of_angle(kDegenerateAngle) ||
                              new_angles_no_worse(topo, old_tets, new_tets,
                                                  old_quality < quality_of_angle(kTradeAngle));
  if (new_quality > old_quality && pays) {
    std::vector<uint32_t> created;
    topo.replace(cavity, new_tets, created);
    if (growth) growth->vertices_removed += sorted_copy(vanished).size();
    return true;
  }
  topo.remove_last_vertex();
  return false;
}

// The outer faces of `cavity`, each as 3 points looking into the cavity
// (orient3d(a, b, c, q) > 0 for q inside near the face): for face f of tet
// t, the tet with vertex f replaced by q is (a, b, c, q) up to an even
// permutation.
std::vector<double> outer_faces(const TetTopology& topo, const std::vector<uint32_t>& cavity) {
  std::vector<double> faces;
  const std::vector<uint32_t> members = sorted_copy(cavity);
  for (uint32_t t : cavity)
    for (int f = 0; f < 4; ++f) {
      if (!outer_face(topo, members, 4 * t + f)) continue;
      uint32_t tri[3];
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != f) tri[n++] = topo.tet(t)[k];
      if ((3 - f) % 2 == 1) std::swap(tri[0], tri[1]);  // moving q from slot f to slot 3 is 3 - f swaps
      for (uint32_t v : tri) faces.insert(faces.end(), topo.point(v), topo.point(v) + 3);
    }
  return faces;
}

// try_cavity at p, else at the deepest point of the cavity's kernel: a
// point near a flat tet's plane (its centroid, the rounded midpoint of an
// edge of a flat ring) may see some of the cavity's outer faces from
// behind, the kernel's deepest point sees them all. With `ring`, the
// cavity is that ring's tets, and the cone bound reads it from the ring.
bool try_point_then_kernel(TetTopology& topo, const std::vector<uint32_t>& cavity, const double* p, double bar,
                           SmoothingScratch& scratch, InsertionRule rule, const TetTopology::Ring* ring = nullptr) {
  const double worst = worst_quality(topo, cavity);
  if (!(ring ? cones_can_beat(topo, *ring, worst) : cones_can_beat(topo, cavity, worst))) return false;
  if (try_cavity(topo, cavity, p, bar, scratch, rule)) return true;
  const KernelPoint kernel = deepest_kernel_point(outer_faces(topo, cavity));
  return kernel.found && kernel.depth > 0 && try_cavity(topo, cavity, kernel.point, bar, scratch, rule, true);
}

// Inserts a vertex at the midpoint of the edge whose closed ring is `ring`,
// or at the ring's kernel point, into the ring's tets, if that pays.
// A split `failed` knows is not tried; one refused is added to it.
bool split_edge(TetTopology& topo, const TetTopology::Ring& ring, double bar, SmoothingScratch& scratch,
                InsertionRule rule, FailedSplits* failed) {
  if (failed && failed->known(topo, ring)) return false;
  const double* a = topo.point(ring.a);
  const double* b = topo.point(ring.b);
  const double middle[3] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  if (try_point_then_kernel(topo, std::vector<uint32_t>(ring.tets, ring.tets + ring.n), middle, bar, scratch, rule,
                            &ring))
    return true;
  if (failed) failed->add(topo, ring);
  return false;
}

// Face f of tet t: its three corners and its normal (the cross product of
// two of its edges, as long as twice its area).
struct FaceFrame {
  const double* corner[3];
  double normal[3];
  double twice_area;
};

FaceFrame face_frame(const TetTopology& topo, uint32_t t, int f) {
  FaceFrame out;
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != f) out.corner[n++] = topo.point(topo.tet(t)[k]);
  double u[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = out.corner[1][i] - out.corner[0][i];
    w[i] = out.corner[2][i] - out.corner[0][i];
  }
  out.normal[0] = u[1] * w[2] - u[2] * w[1];
  out.normal[1] = u[2] * w[0] - u[0] * w[2];
  out.normal[2] = u[0] * w[1] - u[1] * w[0];
  out.twice_area = std::sqrt(out.normal[0] * out.normal[0] + out.normal[1] * out.normal[1] +
                             out.normal[2] * out.normal[2]);
  return out;
}

// Distance from p to the plane of face f of tet t (doubles: it only
// steers which tets a cavity takes in).
double plane_distance(const TetTopology& topo, uint32_t t, int f, const double* p) {
  const FaceFrame face = face_frame(topo, t, f);
  double dot = 0;
  for (int i = 0; i < 3; ++i) dot += face.normal[i] * (p[i] - face.corner[0][i]);
  return face.twice_area > 0 ? std::abs(dot) / face.twice_area : 0;
}

// The outer faces of `cavity` whose cone to p is not positive or no
// better than `worst`: the tets behind them go to `join`; false when one of
// them is a boundary face (no tet behind it). `bad` tells whether any was.
// Also the tets behind the outer faces whose plane is within `tight` of p.
bool blocking_faces(const TetTopology& topo, const std::vector<uint32_t>& members, const double* p, double worst,
                    double tight, std::vector<uint32_t>& join, bool& bad) {
  join.clear();
  bad = false;
  for (uint32_t c : members)
    for (int f = 0; f < 4; ++f) {
      const uint32_t code = 4 * c + f;
      if (!outer_face(topo, members, code)) continue;
      const double* q[4];
      for (int k = 0; k < 4; ++k) q[k] = k == f ? p : topo.point(topo.tet(c)[k]);
      if (orient3d(q[0], q[1], q[2], q[3]) > 0 && tet_quality(q[0], q[1], q[2], q[3]) > worst) {
        if (topo.twin(code) != TetTopology::kNone && plane_distance(topo, c, f, p) <= tight)
          join.push_back(topo.twin(code) / 4);
        continue;
      }
      bad = true;
      if (topo.twin(code) == TetTopology::kNone) return false;
      join.push_back(topo.twin(code) / 4);
    }
  join = sorted_copy(join);
  return true;
}

// The point `scale` times a regular tet's height (0.816 times the edge of
// an equilateral triangle of the same area) above the middle of face f of
// tet t, on the side of t's corner f; false for a face of no area.
bool point_above_face(const TetTopology& topo, uint32_t t, int f, double scale, double* p) {
  const FaceFrame face = face_frame(topo, t, f);
  if (!(face.twice_area > 0)) return false;
  double middle[3];
  for (int i = 0; i < 3; ++i) middle[i] = (face.corner[0][i] + face.corner[1][i] + face.corner[2][i]) / 3;
  const double* corner = topo.point(topo.tet(t)[f]);
  double side = 0;
  for (int i = 0; i < 3; ++i) side += face.normal[i] * (corner[i] - middle[i]);
  const double edge = std::sqrt(2 * face.twice_area / std::sqrt(3.0));
  const double step = scale * 0.816 * edge * (side < 0 ? -1 : 1) / face.twice_area;
  for (int i = 0; i < 3; ++i) p[i] = middle[i] + step * face.normal[i];
  return true;
}

// Step 6 (for the mesh's worst tet, with the frozen flags): a cavity grown
// from the tet toward a point p with room, until every outer face's cone to
// p is positive and beats the cavity's worst tet; then p is tried
// (try_cavity, which lets free vertices the cavity swallows vanish). First
// p is the deepest point of the kernel of the tet and its face neighbours,
// the cavity growing across the faces that hold it down (bad cones, and
// faces about as near as the deepest) and the point found again; then, for
// a tet on the boundary, p is fixed above the middle of its boundary face
// (a flat tet over nearly coplanar surface triangles, whose kernel stays
// thin as it grows along the surface).
bool grow_cavity(TetTopology& topo, uint32_t t, double bar, SmoothingScratch& scratch, InsertionRule rule,
                 CavityGrowth& growth) {
  std::vector<uint32_t> start = {t}, join;
  for (int f = 0; f < 4; ++f)
    if (topo.twin(4 * t + f) != TetTopology::kNone) start.push_back(topo.twin(4 * t + f) / 4);
  std::vector<uint32_t> cavity = start;
  bool bad = false;
  for (int round = 0; round < kGrowRounds && cavity.size() <= kGrowTets; ++round) {
    const KernelPoint deep = deepest_kernel_point(outer_faces(topo, cavity));
    if (!deep.found) break;
    const double tight = kTight * std::max(deep.depth, 0.0);
    if (!blocking_faces(topo, sorted_copy(cavity), deep.point, worst_quality(topo, cavity), tight, join, bad)) break;
    if (!bad) {
      if (try_cavity(topo, cavity, deep.point, bar, scratch, rule, false, &growth)) return true;
      break;
    }
    cavity.insert(cavity.end(), join.begin(), join.end());
  }
  // A flat tet off the boundary (its corners on one plane, as surface
  // vertices of a planar face can be after the removals) has no boundary
  // face to rise from: its largest face, on either side, takes that part.
  bool off_boundary = true;
  for (int f = 0; f < 4; ++f) off_boundary = off_boundary && topo.twin(4 * t + f) != TetTopology::kNone;
  int lifted_face = -1;
  if (off_boundary && topo.quality(t) < quality_of_angle(kDegenerateAngle)) {
    double largest = 0;
    for (int f = 0; f < 4; ++f) {
      const double area = face_frame(topo, t, f).twice_area;
      if (area > largest) {
        largest = area;
        lifted_face = f;
      }
    }
  }
  for (int f = 0; f < 4; ++f) {
    const bool boundary = topo.twin(4 * t + f) == TetTopology::kNone;
    if (!boundary && f != lifted_face) continue;
    double p[3];
    // A boundary face rises on its tet's side only; the lifted face on both.
    for (double scale : {1.0, 0.5, -1.0, -0.5}) {
      if ((boundary && scale < 0) || !point_above_face(topo, t, f, scale, p)) break;
      cavity = start;
      for (int round = 0; round < kRiseRounds && cavity.size() <= kRiseTets; ++round) {
        if (!blocking_faces(topo, sorted_copy(cavity), p, worst_quality(topo, cavity), -1, join, bad)) break;
        if (!bad) {
          if (try_cavity(topo, cavity, p, bar, scratch, rule, false, &growth)) return true;
          break;
        }
        cavity.insert(cavity.end(), join.begin(), join.end());
      }
    }
  }
  return false;
}

// Step 5 (for the mesh's worst tet): each corner of t on an open face, its
// star as the cavity, the point a share of the way from the corner to the
// deepest point of the star's kernel (the kernel is convex and the corner
// bounds it, so every point between them sees the star's outer faces). A
// cap, an input triangle with an angle near 180 degrees, leaves its obtuse
// corner a tiny height h above its long edge: every tet on the cap with an
// apex far from that corner has an angle of about h over the long edge's
// half length (u r1: 0.0675 degrees, on two caps, in every peer's mesh
// too); a new vertex a few h from the corner gives the cap's tet moderate
// angles and the tets on the corner's other surface triangles angles of
// its distance over their size, and smoothing then places it.
bool near_boundary_corner(TetTopology& topo, uint32_t t, double bar, SmoothingScratch& scratch, InsertionRule rule) {
  uint32_t corners[4];
  std::copy_n(topo.tet(t), 4, corners);
  std::vector<uint32_t> star;
  for (uint32_t corner : corners) {
    if (!topo.on_boundary(corner)) continue;
    topo.vertex_star(corner, star);
    const KernelPoint deep = deepest_kernel_point(outer_faces(topo, star));
    if (!deep.found || !(deep.depth > 0)) continue;
    const double* at = topo.point(corner);
    const double c[3] = {at[0], at[1], at[2]};  // a trial's new vertex may move the points
    for (double share : kCornerShares) {
      double p[3];
      for (int i = 0; i < 3; ++i) p[i] = c[i] + share * (deep.point[i] - c[i]);
      if (try_cavity(topo, star, p, bar, scratch, rule)) return true;
    }
  }
  return false;
}

}  // namespace

AngleSummary summarize_angles(const TetTopology& topo, std::span<const uint32_t> tets) {
  const double sliver = kSliverAngle * std::numbers::pi / 180;
  AngleSummary out;
  for (size_t i = 0; i < tets.size(); i += 4) {
    const uint32_t* v = &tets[i];
    const double a = tet_min_dihedral(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3]));
    out.smallest = std::min(out.smallest, a);
    out.slivers += a < sliver;
  }
  return out;
}

bool min_angle_no_worse(const TetTopology& topo, std::span<const uint32_t> old_tets,
                        std::span<const uint32_t> new_tets) {
  return summarize_angles(topo, new_tets).no_worse_than(summarize_angles(topo, old_tets));
}

double insertion_bar(double target) { return std::min(target, quality_of_angle(kShortfallAngle)); }

bool insert_vertex(TetTopology& topo, uint32_t t, double target, SmoothingScratch& scratch, InsertionRule rule,
                   CavityGrowth* growth, bool near_corners, FailedSplits* failed_splits) {
  const uint32_t* v = topo.tet(t);
  double centroid[3];
  for (int i = 0; i < 3; ++i)
    centroid[i] = (topo.point(v[0])[i] + topo.point(v[1])[i] + topo.point(v[2])[i] + topo.point(v[3])[i]) / 4;
  const double bar = insertion_bar(target);
  std::vector<uint32_t> cavity = {t};
  for (int f = 0; f < 4; ++f)
    if (topo.twin(4 * t + f) != TetTopology::kNone) cavity.push_back(topo.twin(4 * t + f) / 4);
  if (cavity.size() > 1) {
    // The edge split first (step 1 of insertion.hpp).
    const uint32_t* u = topo.tet(t);
    int k = 0, l = 1;
    TetTopology::Ring ring;
    const bool widest_closes =
        widest_dihedral_faces(topo.point(u[0]), topo.point(u[1]), topo.point(u[2]), topo.point(u[3]), k, l) &&
        topo.edge_ring(t, k, l, ring);
    if (widest_closes && split_edge(topo, ring, bar, scratch, rule, failed_splits)) return true;
    if (try_point_then_kernel(topo, cavity, centroid, bar, scratch, rule)) return true;
    // For the mesh's worst tet, or a sliver whose widest angle sits on a
    // surface edge (a flat ear), the tet's other edges whose rings close.
    if (rule == InsertionRule::kWorstFirst || (!widest_closes && topo.quality(t) < quality_of_angle(kSliverAngle))) {
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          if ((i == k && j == l) || (i == l && j == k)) continue;
          if (topo.edge_ring(t, i, j, ring) && split_edge(topo, ring, bar, scratch, rule, failed_splits)) return true;
        }
    }
    // The tets around t's vertices: a kernel with room for a good vertex.
    // A vertex of t off the boundary has its whole star in that cavity, on
    // none of its outer faces: it would vanish, and the cavity is not used.
    bool open = true;
    for (int k = 0; k < 4; ++k) open = open && topo.on_boundary(topo.tet(t)[k]);
    std::vector<uint32_t> wider = cavity, star;
    for (int k = 0; k < 4 && open; ++k) {
      topo.vertex_star(topo.tet(t)[k], star);
      for (uint32_t s : star)
        if (std::find(wider.begin(), wider.end(), s) == wider.end()) wider.push_back(s);
    }
    if (open && cones_can_beat(topo, wider, worst_quality(topo, wider))) {
      const KernelPoint deep = deepest_kernel_point(outer_faces(topo, wider));
      if (deep.found && deep.depth > 0 && try_cavity(topo, wider, deep.point, bar, scratch, rule, true)) return true;
    }
    if (growth && grow_cavity(topo, t, bar, scratch, rule, *growth)) return true;
    return near_corners && rule == InsertionRule::kWorstFirst && near_boundary_corner(topo, t, bar, scratch, rule);
  }
  return try_cavity(topo, {t}, centroid, bar, scratch, rule);
}

}  // namespace partet
