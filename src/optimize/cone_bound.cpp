// cone_quality_bound, cones_can_beat and cones_can_keep_angle (see
// cone_bound.hpp): per cavity tet its four outward unit face normals, per
// edge the outer faces counted, and at the edges with two the tets'
// dihedral angles there summed (in cavity order).
#include "optimize/cone_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/hash_mix.hpp"
#include "optimize/tet_edges.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

// One (cavity tet, edge) incidence: the tet's index in the cavity, the
// local edge, and the next incidence on the same edge (kNoIncidence last).
constexpr uint32_t kNoIncidence = UINT32_MAX;
struct Incidence {
  uint32_t tet;
  uint32_t next;
  uint8_t edge;
};

// One edge of the cavity: its sorted vertex pair, how many outer faces of
// the cavity meet there (over its incidences), and its incidences' list.
struct CavityEdge {
  uint64_t key;
  uint32_t first, last;
  int outer;
};

// The outward unit normals of the four faces of tet v, face k opposite
// corner k, at n[3k .. 3k + 2] (zero for a face of no area).
void outward_normals(const TetTopology& topo, const uint32_t* v, double* n) {
  const double* p[4] = {topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3])};
  for (int k = 0; k < 4; ++k) {
    const double* a = p[(k + 1) % 4];
    const double* b = p[(k + 2) % 4];
    const double* c = p[(k + 3) % 4];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double* m = &n[3 * k];
    m[0] = u[1] * w[2] - u[2] * w[1];
    m[1] = u[2] * w[0] - u[0] * w[2];
    m[2] = u[0] * w[1] - u[1] * w[0];
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const bool inward = m[0] * (p[k][0] - a[0]) + m[1] * (p[k][1] - a[1]) + m[2] * (p[k][2] - a[2]) > 0;
    const double scale = length > 0 ? (inward ? -1 : 1) / length : 0;
    for (int i = 0; i < 3; ++i) m[i] *= scale;
  }
}

// The cavity's tets' outward normals (12 doubles per tet), its
// (tet, edge) incidences in cavity order, and its edges in the order first
// met, each with its incidences in cavity order (found through an open
// addressing table whose slots are stamped per cavity, so nothing is
// cleared between cavities).
struct CavityEdges {
  std::vector<double> normals;
  std::vector<Incidence> incidences;
  std::vector<CavityEdge> edges;
  std::vector<uint32_t> members;  // the cavity's slots, sorted
  std::vector<uint32_t> table, stamps;  // per table slot: index into edges, and the cavity it was set for
  uint32_t stamp = 0;

  uint32_t edge_index(uint64_t key) {
    const size_t mask = table.size() - 1;
    for (size_t s = hash_mix(key) & mask;; s = (s + 1) & mask) {
      if (stamps[s] != stamp) {
        stamps[s] = stamp;
        table[s] = static_cast<uint32_t>(edges.size());
        edges.push_back({key, kNoIncidence, kNoIncidence, 0});
        return table[s];
      }
      if (edges[table[s]].key == key) return table[s];
    }
  }
};

void cavity_edges(const TetTopology& topo, std::span<const uint32_t> cavity, CavityEdges& out) {
  out.members.assign(cavity.begin(), cavity.end());
  std::sort(out.members.begin(), out.members.end());
  out.normals.resize(12 * cavity.size());
  out.incidences.clear();
  out.edges.clear();
  size_t capacity = 64;
  while (capacity < 12 * cavity.size()) capacity *= 2;
  if (out.table.size() < capacity) {
    out.table.assign(capacity, 0);
    out.stamps.assign(capacity, 0);
    out.stamp = 0;
  }
  if (++out.stamp == 0) {
    std::fill(out.stamps.begin(), out.stamps.end(), 0);
    out.stamp = 1;
  }
  for (uint32_t i = 0; i < cavity.size(); ++i) {
    const uint32_t t = cavity[i];
    const uint32_t* v = topo.tet(t);
    outward_normals(topo, v, &out.normals[12 * size_t{i}]);
    bool outer[4];
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = topo.twin(4 * t + f);
      outer[f] = other == TetTopology::kNone || !std::binary_search(out.members.begin(), out.members.end(), other / 4);
    }
    for (uint8_t e = 0; e < 6; ++e) {
      const uint32_t x = v[kTetEdges[e][0]], y = v[kTetEdges[e][1]];
      CavityEdge& edge = out.edges[out.edge_index((uint64_t{std::min(x, y)} << 32) | std::max(x, y))];
      edge.outer += int{outer[kTetEdgeFaces[e][0]]} + int{outer[kTetEdgeFaces[e][1]]};
      const uint32_t index = static_cast<uint32_t>(out.incidences.size());
      out.incidences.push_back({i, kNoIncidence, e});
      if (edge.first == kNoIncidence)
        edge.first = index;
      else
        out.incidences[edge.last].next = index;
      edge.last = index;
    }
  }
}

// The interior dihedral angle of the incidence's tet at its edge as the
// complex number (cos, sin), of length 1 up to rounding since the normals
// are unit vectors (no normalisation per incidence: hypot was 3 % of
// handle r1's run): between the faces opposite the edge's other two
// corners, pi minus the angle of their outward normals.
void unit_angle(const CavityEdges& edges, const Incidence& in, double& c, double& s) {
  const double* nk = &edges.normals[12 * size_t{in.tet} + 3 * kTetEdgeFaces[in.edge][0]];
  const double* nl = &edges.normals[12 * size_t{in.tet} + 3 * kTetEdgeFaces[in.edge][1]];
  const double x[3] = {nk[1] * nl[2] - nk[2] * nl[1], nk[2] * nl[0] - nk[0] * nl[2], nk[0] * nl[1] - nk[1] * nl[0]};
  c = -(nk[0] * nl[0] + nk[1] * nl[1] + nk[2] * nl[2]);
  s = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

// Calls edge(c, s) with the cavity's interior angle, as a complex number
// of length 1 up to rounding, at each edge where exactly two outer faces
// meet; stops when it returns false.
template <class Edge>
void for_each_two_face_edge(const CavityEdges& edges, Edge&& edge) {
  for (const CavityEdge& e : edges.edges) {
    if (e.outer != 2) continue;
    double c = 1, s = 0;
    for (uint32_t k = e.first; k != kNoIncidence; k = edges.incidences[k].next) {
      double ck, sk;
      unit_angle(edges, edges.incidences[k], ck, sk);
      const double nc = c * ck - s * sk, ns = c * sk + s * ck;
      c = nc;
      s = ns;
    }
    if (!edge(c, s)) return;
  }
}

// True when `below(c, s)` holds at none of the cavity's edges where two
// outer faces meet (stopping at the first where it does).
template <class Below>
bool no_two_face_edge(const TetTopology& topo, std::span<const uint32_t> cavity, Below&& below) {
  thread_local CavityEdges edges;  // scratch: no allocation per cavity
  cavity_edges(topo, cavity, edges);
  bool none = true;
  for_each_two_face_edge(edges, [&](double c, double s) {
    none = !below(c, s);
    return none;
  });
  return none;
}

// The same over the cavity of a closed ring of tets around an edge (a, b),
// from the ring's structure instead of an edge table: tet k = (a, b, r_k,
// r_{k+1}) has its two outer faces (opposite a and b) at edge (r_k,
// r_{k+1}), and edges (a, r_k) and (b, r_k) have the outer faces of tets k
// - 1 and k, whose angles there sum. The angles and their products are
// those of for_each_two_face_edge, bit for bit (a product of two unit
// complex numbers is the same in either order; the faces of an angle may
// come in either order).
template <class Edge>
void for_each_ring_edge(const TetTopology& topo, const TetTopology::Ring& ring, Edge&& edge) {
  const auto angle = [](const double* nk, const double* nl, double& c, double& s) {
    const double x[3] = {nk[1] * nl[2] - nk[2] * nl[1], nk[2] * nl[0] - nk[0] * nl[2], nk[0] * nl[1] - nk[1] * nl[0]};
    c = -(nk[0] * nl[0] + nk[1] * nl[1] + nk[2] * nl[2]);
    s = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  };
  const auto times = [](double c1, double s1, double c2, double s2, double& c, double& s) {
    c = c1 * c2 - s1 * s2;
    s = c1 * s2 + s1 * c2;
  };
  // Per tet: its angles at (a, r_k), (a, r_{k+1}), (b, r_k), (b, r_{k+1}).
  double at[TetTopology::kMaxRing][4][2];
  for (int k = 0; k < ring.n; ++k) {
    const uint32_t* v = topo.tet(ring.tets[k]);
    double n[12];
    outward_normals(topo, v, n);
    const double* na = &n[3 * local_index(v, ring.a)];
    const double* nb = &n[3 * local_index(v, ring.b)];
    const double* n0 = &n[3 * local_index(v, ring.vertices[k])];
    const double* n1 = &n[3 * local_index(v, ring.vertices[(k + 1) % ring.n])];
    double c, s;
    angle(na, nb, c, s);
    if (!edge(c, s)) return;
    angle(nb, n1, at[k][0][0], at[k][0][1]);
    angle(nb, n0, at[k][1][0], at[k][1][1]);
    angle(na, n1, at[k][2][0], at[k][2][1]);
    angle(na, n0, at[k][3][0], at[k][3][1]);
  }
  for (int k = 0; k < ring.n; ++k) {
    const int before = (k + ring.n - 1) % ring.n;
    for (int side = 0; side < 2; ++side) {
      const double* mine = at[k][2 * side];
      const double* theirs = at[before][2 * side + 1];
      double c, s;
      times(mine[0], mine[1], theirs[0], theirs[1], c, s);
      if (!edge(c, s)) return;
    }
  }
}

// no_two_face_edge over a ring's cavity (for_each_ring_edge).
template <class Below>
bool no_two_face_ring_edge(const TetTopology& topo, const TetTopology::Ring& ring, Below&& below) {
  bool none = true;
  for_each_ring_edge(topo, ring, [&](double c, double s) {
    none = !below(c, s);
    return none;
  });
  return none;
}

}  // namespace

double cone_quality_bound(const TetTopology& topo, std::span<const uint32_t> cavity) {
  CavityEdges edges;
  cavity_edges(topo, cavity, edges);
  double bound = std::numeric_limits<double>::infinity();
  for_each_two_face_edge(edges, [&](double c, double s) {
    double phi = std::atan2(s, c);
    if (phi < 0) phi += 2 * std::numbers::pi;
    bound = std::min(bound, kRegularSineScale * std::sin(phi / 2));
    return true;
  });
  return bound;
}

namespace {

// cones_can_beat with `none(below)` telling whether below(c, s) holds at
// none of the cavity's two-face edges.
template <class None>
bool can_beat(double worst, None&& none) {
  // worst = K sin(alpha); the bound is below it where phi lies within
  // 2 alpha of 0 (or of 2 pi): c > 0 and |s| < sin(2 alpha) |(c, s)|,
  // for 2 alpha up to 90 degrees.
  if (!(worst >= 1e-4) || !(worst <= quality_of_angle(45))) return true;
  const double sine = worst * (1 - 1e-6) / kRegularSineScale;
  const double reach = 2 * sine * std::sqrt(1 - sine * sine);  // sin(2 alpha)
  return none([&](double c, double s) { return c > 0 && std::abs(s) < reach * std::sqrt(c * c + s * s); });
}

// cones_can_keep_angle the same way.
template <class None>
bool can_keep_angle(double angle, None&& none) {
  if (!(angle >= 1e-6) || !(angle <= std::numbers::pi / 2)) return true;
  // phi < beta for phi, beta in [0, pi] exactly when s >= 0 and the cross
  // product of (cos beta, sin beta) and (c, s), |(c, s)| sin(phi - beta),
  // is negative.
  const double beta = 2 * angle * (1 - 1e-6);
  const double cb = std::cos(beta), sb = std::sin(beta);
  return none([&](double c, double s) { return s >= 0 && s * cb - c * sb < 0; });
}

}  // namespace

bool cones_can_beat(const TetTopology& topo, std::span<const uint32_t> cavity, double worst) {
  return can_beat(worst, [&](auto&& below) { return no_two_face_edge(topo, cavity, below); });
}

bool cones_can_beat(const TetTopology& topo, const TetTopology::Ring& ring, double worst) {
  return can_beat(worst, [&](auto&& below) { return no_two_face_ring_edge(topo, ring, below); });
}

bool cones_can_keep_angle(const TetTopology& topo, std::span<const uint32_t> cavity, double angle) {
  return can_keep_angle(angle, [&](auto&& below) { return no_two_face_edge(topo, cavity, below); });
}

bool cones_can_keep_angle(const TetTopology& topo, const TetTopology::Ring& ring, double angle) {
  return can_keep_angle(angle, [&](auto&& below) { return no_two_face_ring_edge(topo, ring, below); });
}

}  // namespace partet
