// face_flip and edge_removal (see flips.hpp). The edge removal table is
// best[i][k] = max over i < j < k of min(Q(i, j, k), best[i][j], best[j][k])
// with best[i][i+1] = +inf, Q the worse of the two tets of triangle (i, j, k),
// or -inf when either is not positive; O(n^3) for n <= 10, run only when the
// ring's half-angle bound (flips.hpp) does not rule out beating the bar.
#include "optimize/flips.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "check/tet_faces.hpp"
#include "core/intersections.hpp"
#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

constexpr double kInvalid = -std::numeric_limits<double>::infinity();

// Quality of tet (v0, v1, v2, v3) of `topo` when it is above `floor` and
// the tet is exactly positive, else kInvalid. The searches only want tets
// above a floor: the exact orientation is then needed for few of them.
double quality_above(const TetTopology& topo, uint32_t v0, uint32_t v1, uint32_t v2, uint32_t v3, double floor) {
  const double *p0 = topo.point(v0), *p1 = topo.point(v1), *p2 = topo.point(v2), *p3 = topo.point(v3);
  const double q = tet_quality(p0, p1, p2, p3);
  if (!(q > floor) || orient3d(p0, p1, p2, p3) <= 0) return kInvalid;
  return q;
}

// kRegularSineScale * sin(theta / 2) for the dihedral angle theta of the
// positive tet (p0, p1, p2, p3) at its edge (p2, p3): |u0 + u1| / 2 for the
// unit inward normals u0, u1 of the faces opposite p0 and p1, which keeps
// its absolute precision at every angle. NaN for a degenerate face.
double half_angle_bound(const double* p0, const double* p1, const double* p2, const double* p3) {
  const double a[3] = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
  const double b[3] = {p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
  const double c[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
  const double d[3] = {p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]};
  const double n0[3] = {b[1] * a[2] - b[2] * a[1], b[2] * a[0] - b[0] * a[2], b[0] * a[1] - b[1] * a[0]};
  const double n1[3] = {c[1] * d[2] - c[2] * d[1], c[2] * d[0] - c[0] * d[2], c[0] * d[1] - c[1] * d[0]};
  const double l0 = std::sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
  const double l1 = std::sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double s = n0[k] / l0 + n1[k] / l1;
    sum += s * s;
  }
  return kRegularSineScale * std::sqrt(sum) / 2;
}

// Bounds below this much under a bar prune (rounding of the bound and of
// tet_quality is far smaller).
constexpr double kBoundMargin = 1e-9;

void add_tet(Flip& flip, uint32_t v0, uint32_t v1, uint32_t v2, uint32_t v3) {
  uint32_t* out = &flip.new_tets[4 * flip.new_count++];
  out[0] = v0, out[1] = v1, out[2] = v2, out[3] = v3;
}

// A sandwiched polygon of multi_face_removal: ring r_0..r_{n-1} (the
// faces' orientation seen from d, so (d, e, r_i, r_{i+1}) is positive when
// de crosses it), and per ring edge the tets on d's and e's side that have
// it; the old tets, two per face.
struct Sandwich {
  int n = 0;
  uint32_t ring[TetTopology::kMaxRing];
  uint32_t d_tet[TetTopology::kMaxRing], e_tet[TetTopology::kMaxRing];
  int old_count = 0;
  uint32_t old_tets[Flip::kMaxOld];
};

bool on_ring(const Sandwich& s, uint32_t v) { return std::find(s.ring, s.ring + s.n, v) != s.ring + s.n; }

// The code of the face of tet t without vertex v.
uint32_t face_without(const TetTopology& topo, uint32_t t, uint32_t v) {
  return 4 * t + static_cast<uint32_t>(local_index(topo.tet(t), v));
}

// Grows `s` across ring edge i: the tet beyond d's tet there, (u, w, d, x),
// whose face (u, w, x) has e's tet behind it, with x a new vertex. False
// when there is none.
bool grow(const TetTopology& topo, uint32_t d, uint32_t e, const Sandwich& s, int i, Sandwich& out) {
  const uint32_t u = s.ring[i], w = s.ring[(i + 1) % s.n];
  const uint32_t* dt = topo.tet(s.d_tet[i]);
  uint32_t third = TetTopology::kNone;  // the disk face's vertex off this edge
  for (int k = 0; k < 4; ++k)
    if (dt[k] != u && dt[k] != w && dt[k] != d) third = dt[k];
  const uint32_t across = topo.twin(face_without(topo, s.d_tet[i], third));
  if (across == TetTopology::kNone) return false;
  const uint32_t beyond = across / 4, x = topo.tet(beyond)[across % 4];
  if (x == e || on_ring(s, x)) return false;
  const uint32_t below = topo.twin(face_without(topo, beyond, d));
  if (below == TetTopology::kNone || topo.tet(below / 4)[below % 4] != e) return false;
  out = s;
  for (int k = s.n; k > i + 1; --k) {
    out.ring[k] = s.ring[k - 1];
    out.d_tet[k] = s.d_tet[k - 1];
    out.e_tet[k] = s.e_tet[k - 1];
  }
  out.ring[i + 1] = x;
  out.d_tet[i] = out.d_tet[i + 1] = beyond;
  out.e_tet[i] = out.e_tet[i + 1] = below / 4;
  ++out.n;
  out.old_tets[out.old_count++] = beyond;
  out.old_tets[out.old_count++] = below / 4;
  return true;
}

// The new tets (d, e, a, b) of one multi_face_removal, by ring edge (a, b):
// each growth keeps all but one of the ring's edges, so each tet's quality
// is computed once and its exact orientation at most once.
class NewTets {
 public:
  NewTets(const TetTopology& topo, uint32_t d, uint32_t e) : topo_(topo), d_(d), e_(e) {}

  // quality_above(d, e, a, b, floor).
  double quality_above(uint32_t a, uint32_t b, double floor) {
    Entry& x = entry(a, b);
    if (!(x.quality > floor)) return kInvalid;
    if (x.orientation == kUnknown) {
      const bool positive = orient3d(topo_.point(d_), topo_.point(e_), topo_.point(a), topo_.point(b)) > 0;
      x.orientation = positive ? kPositive : kNotPositive;
    }
    return x.orientation == kPositive ? x.quality : kInvalid;
  }

 private:
  static constexpr int kUnknown = 0, kPositive = 1, kNotPositive = 2;
  struct Entry {
    uint64_t key;
    double quality;
    int orientation;
  };
  // The entry of tet (d, e, a, b); past kMaxEntries (more than the growth
  // of a ring to kMaxRing can make) the last slot is reused.
  Entry& entry(uint32_t a, uint32_t b) {
    const uint64_t key = uint64_t{a} << 32 | b;
    for (int i = 0; i < count_; ++i)
      if (entries_[i].key == key) return entries_[i];
    if (count_ < kMaxEntries) ++count_;
    Entry& x = entries_[count_ - 1];
    x = {key, tet_quality(topo_.point(d_), topo_.point(e_), topo_.point(a), topo_.point(b)), kUnknown};
    return x;
  }

  static constexpr int kMaxEntries = 4 * TetTopology::kMaxRing * TetTopology::kMaxRing;
  const TetTopology& topo_;
  uint32_t d_, e_;
  int count_ = 0;
  Entry entries_[kMaxEntries];
};

// Worst new tet (d, e, r_i, r_{i+1}) of `s`, or kInvalid unless all are
// positive; once it is at or below `floor` the search stops there (the
// value returned is then at most `floor`).
double sandwich_quality(NewTets& tets, const Sandwich& s, double floor) {
  double worst = std::numeric_limits<double>::infinity();
  for (int i = 0; i < s.n && worst > floor; ++i)
    worst = std::min(worst, tets.quality_above(s.ring[i], s.ring[(i + 1) % s.n], floor));
  return worst;
}

// True when segment de meets one of the sandwich's faces (the polygon).
bool crosses(const TetTopology& topo, uint32_t d, uint32_t e, const Sandwich& s) {
  for (int k = 0; k < s.old_count; k += 2) {
    const uint32_t* t = topo.tet(s.old_tets[k]);
    uint32_t face[3];
    int m = 0;
    for (int j = 0; j < 4; ++j)
      if (t[j] != d) face[m++] = t[j];
    if (segment_triangle_intersect(topo.point(d), topo.point(e), topo.point(face[0]), topo.point(face[1]),
                                   topo.point(face[2])))
      return true;
  }
  return false;
}

}  // namespace

bool multi_face_removal(const TetTopology& topo, uint32_t code, Flip& flip, const double* beat) {
  const uint32_t other = topo.twin(code);
  if (other == TetTopology::kNone) return false;
  const uint32_t t1 = code / 4, t2 = other / 4;
  const uint32_t d = topo.tet(t1)[code % 4], e = topo.tet(t2)[other % 4];
  Sandwich s;
  s.n = 3;
  for (int k = 0; k < 3; ++k) {
    s.ring[k] = topo.tet(t1)[kOutwardFace[code % 4][k]];
    s.d_tet[k] = t1;
    s.e_tet[k] = t2;
  }
  s.old_tets[0] = t1;
  s.old_tets[1] = t2;
  s.old_count = 2;
  double old_quality = std::min(topo.quality(t1), topo.quality(t2));
  bool found = false;
  NewTets new_tets(topo, d, e);
  while (s.n < TetTopology::kMaxRing) {
    // The growth giving the best new tets (the first on ties).
    Sandwich best_growth, candidate;
    double best_growth_quality = kInvalid;
    bool grown = false;
    for (int i = 0; i < s.n; ++i) {
      if (!grow(topo, d, e, s, i, candidate)) continue;
      const double q = sandwich_quality(new_tets, candidate, grown ? best_growth_quality : kInvalid);
      if (!grown || q > best_growth_quality) {
        best_growth = candidate;
        best_growth_quality = q;
        grown = true;
      }
    }
    if (!grown) break;
    s = best_growth;
    for (int k = s.old_count - 2; k < s.old_count; ++k)
      old_quality = std::min(old_quality, topo.quality(s.old_tets[k]));
    // Wanted: positive new tets, better than the polygon found so far and,
    // with `beat`, than *beat and the old tets.
    const double bar = std::max(beat ? std::max(*beat, old_quality) : kInvalid, found ? flip.new_quality : kInvalid);
    if (!(best_growth_quality > bar)) continue;
    if (!crosses(topo, d, e, s)) continue;
    flip = Flip{};
    flip.kind = FlipKind::kMultiFace;
    flip.new_quality = best_growth_quality;
    flip.old_quality = old_quality;
    flip.old_count = s.old_count;
    std::copy_n(s.old_tets, s.old_count, flip.old_tets);
    for (int i = 0; i < s.n; ++i) add_tet(flip, d, e, s.ring[i], s.ring[(i + 1) % s.n]);
    found = true;
  }
  return found;
}

bool face_flip(const TetTopology& topo, uint32_t code, Flip& flip, const double* beat) {
  const uint32_t other = topo.twin(code);
  if (other == TetTopology::kNone) return false;
  const uint32_t t1 = code / 4, t2 = other / 4;
  const uint32_t d = topo.tet(t1)[code % 4], e = topo.tet(t2)[other % 4];
  // The face as seen from t1's outside, so (x, y, z, e) is positive.
  uint32_t face[3];
  for (int k = 0; k < 3; ++k) face[k] = topo.tet(t1)[kOutwardFace[code % 4][k]];
  flip = Flip{};
  flip.kind = FlipKind::k23;
  flip.old_tets[0] = t1;
  flip.old_tets[1] = t2;
  flip.old_count = 2;
  flip.old_quality = std::min(topo.quality(t1), topo.quality(t2));
  const double bar = beat ? std::max(*beat, flip.old_quality) : kInvalid;
  flip.new_quality = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const uint32_t r0 = face[k], r1 = face[(k + 1) % 3];
    const double q = quality_above(topo, d, e, r0, r1, bar);
    if (q == kInvalid) return false;
    flip.new_quality = std::min(flip.new_quality, q);
    add_tet(flip, d, e, r0, r1);
  }
  return true;
}

bool edge_removal(const TetTopology& topo, uint32_t t, int i, int j, Flip& flip, const double* beat) {
  TetTopology::Ring ring;
  if (!topo.edge_ring(t, i, j, ring)) return false;
  const int n = ring.n;
  const uint32_t* r = ring.vertices;
  double old_quality = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) old_quality = std::min(old_quality, topo.quality(ring.tets[k]));
  // A sub-polygon whose best is not above `bar` cannot be part of a wanted
  // triangulation: starting every entry at the bar prunes it.
  const double bar = beat ? std::max(*beat, old_quality) : kInvalid;
  // The ring's half-angle bound (flips.hpp): ring tet (a, b, r_k, r_{k+1})
  // gives way to (r_k, r_{k+1}, x, a) and (.., b), which split its angle
  // at edge (r_k, r_{k+1}).
  if (beat)
    for (int k = 0; k < n; ++k)
      if (half_angle_bound(topo.point(ring.a), topo.point(ring.b), topo.point(r[k]), topo.point(r[(k + 1) % n])) <
          bar - kBoundMargin)
        return false;
  constexpr int N = TetTopology::kMaxRing;
  double best[N][N];
  int split[N][N] = {};
  for (int len = 1; len < n; ++len) {
    for (int lo = 0; lo + len < n; ++lo) {
      const int hi = lo + len;
      best[lo][hi] = len == 1 ? std::numeric_limits<double>::infinity() : bar;
      split[lo][hi] = -1;
      for (int mid = lo + 1; mid < hi; ++mid) {
        double q = std::min(best[lo][mid], best[mid][hi]);
        if (q <= best[lo][hi]) continue;
        q = std::min(q, quality_above(topo, r[lo], r[mid], r[hi], ring.b, best[lo][hi]));
        if (q <= best[lo][hi]) continue;
        q = std::min(q, quality_above(topo, r[lo], r[hi], r[mid], ring.a, best[lo][hi]));
        if (q <= best[lo][hi]) continue;
        best[lo][hi] = q;
        split[lo][hi] = mid;
      }
    }
  }
  if (split[0][n - 1] < 0) return false;

  flip = Flip{};
  flip.kind = n == 3 ? FlipKind::k32 : n == 4 ? FlipKind::k44 : FlipKind::kEdgeRemoval;
  flip.new_quality = best[0][n - 1];
  // Unfold the chosen triangulation: a stack of (lo, hi) sub-polygons.
  int stack[2 * N], top = 0;
  stack[top++] = 0;
  stack[top++] = n - 1;
  while (top > 0) {
    const int hi = stack[--top], lo = stack[--top];
    if (hi - lo < 2) continue;
    const int mid = split[lo][hi];
    add_tet(flip, r[lo], r[mid], r[hi], ring.b);
    add_tet(flip, r[lo], r[hi], r[mid], ring.a);
    stack[top++] = lo;
    stack[top++] = mid;
    stack[top++] = mid;
    stack[top++] = hi;
  }
  flip.old_quality = old_quality;
  for (int k = 0; k < n; ++k) flip.old_tets[k] = ring.tets[k];
  flip.old_count = n;
  return true;
}

}  // namespace partet
