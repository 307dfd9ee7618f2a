// recover_input_edges (see edge_recovery.hpp).
#include "delaunay/edge_recovery.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/flat_hash_map.hpp"
#include "core/hash_mix.hpp"
#include "core/predicates.hpp"
#include "core/shape_measure.hpp"
#include "core/vertex_triple.hpp"

namespace partet {
namespace {

uint64_t edge_key(uint32_t u, uint32_t w) { return u < w ? uint64_t{u} << 32 | w : uint64_t{w} << 32 | u; }

struct EdgeKeyTraits {
  static uint64_t empty() { return UINT64_MAX; }
  static uint64_t hash(uint64_t k) { return hash_mix(k); }
};

// The third vertices of the input triangles on an edge.
struct EdgeSides {
  uint32_t opposite[2] = {0, 0};
  uint32_t count = 0;
};

constexpr double kInvalid = -std::numeric_limits<double>::infinity();

// Rounds over the edges left (femur refined once: 3,824 edges in the
// first round, 49 in the second, none in the third; lever refined once:
// 515, 112, 6, 2, none).
constexpr size_t kMaxRecoveryRounds = 8;

// Steps of one edge's recovery (Recovery::recover): each takes a face or
// an edge out of the segment's way.
constexpr int kMaxRecoverySteps = 64;

// The tets around an edge (b, d), its ring vertices ordered so that
// orient3d(b, d, r_k, r_k+1) > 0.
struct Ring {
  uint32_t b = 0, d = 0;
  int n = 0;
  uint32_t vertices[kMaxRecoveryRing] = {};
  uint32_t tets[kMaxRecoveryRing] = {};
};

// Face i of tet q (opposite q[i]), as a key.
VertexTriple face_key(const uint32_t* q, int i) {
  return sorted_triple(q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]);
}

class Recovery {
  struct Outer {
    VertexTriple key;
    uint32_t across;
  };
  struct FaceCode {
    VertexTriple key;
    uint32_t code;
    bool operator<(const FaceCode& o) const {
      return key.a != o.key.a ? key.a < o.key.a : key.b != o.key.b ? key.b < o.key.b : key.c < o.key.c;
    }
  };

 public:
  using EdgeMap = FlatHashMap<uint64_t, EdgeSides, EdgeKeyTraits>;
  using FaceMap = FlatHashMap<VertexTriple, uint32_t, VertexTripleTraits>;
  Recovery(DelaunayTets& d, const EdgeMap& input_edges, const FaceMap& input_faces)
      : d_(d),
        input_edges_(input_edges),
        input_faces_(input_faces),
        vertex_tet_(d.xyz.size() / 3, kNoNeighbour),
        seen_(d.num_tets(), 0),
        flipped_(d.num_tets(), 0) {
    for (size_t t = 0; t < d_.num_tets(); ++t)
      for (int k = 0; k < 4; ++k) vertex_tet_[d_.tets[4 * t + k]] = static_cast<uint32_t>(t);
  }

  // A tet having both u and w, or kNoNeighbour: a search of u's star.
  uint32_t tet_with_edge(uint32_t u, uint32_t w) { return search_star(u, w); }

  // The ring of edge (b, d) from tet t, which has both; false when it
  // meets the enclosing tet's faces or is longer than kMaxRecoveryRing.
  bool edge_ring(uint32_t t, uint32_t b, uint32_t d, Ring& ring) const {
    ring.b = b;
    ring.d = d;
    ring.n = 0;
    uint32_t p = kNoNeighbour, q = kNoNeighbour;
    for (int k = 0; k < 4; ++k) {
      const uint32_t v = tet(t)[k];
      if (v != b && v != d) (p == kNoNeighbour ? p : q) = v;
    }
    // Tet k of the ring is (b, d, r_k, r_k+1): across its face opposite
    // r_k lies the tet on (b, d, r_k+1).
    for (uint32_t current = t;;) {
      if (ring.n == kMaxRecoveryRing) return false;
      ring.vertices[ring.n] = p;
      ring.tets[ring.n] = current;
      ++ring.n;
      const uint32_t across = d_.neighbours[4 * size_t{current} + local(current, p)];
      if (across == kNoNeighbour) return false;
      current = across / 4;
      if (current == t) break;
      uint32_t r = kNoNeighbour;
      for (int k = 0; k < 4; ++k) {
        const uint32_t v = tet(current)[k];
        if (v != b && v != d && v != q) r = v;
      }
      p = q;
      q = r;
    }
    if (orient3d(pt(b), pt(d), pt(ring.vertices[0]), pt(ring.vertices[1])) < 0)
      std::reverse(ring.vertices, ring.vertices + ring.n);
    return true;
  }

  // Replaces the ring's tets by the best valid triangulation of its
  // polygon with the chord (a, c) (edge_recovery.hpp); false, and no
  // change, when it has none.
  bool remove_with_chord(const Ring& ring, uint32_t a, uint32_t c) {
    const int n = ring.n;
    const int m = ring_from(ring, a, c);
    if (m < 2 || m > n - 2) return false;  // c next to a: (a, c) is already an edge
    solve_chain(ring, 0, m);
    solve_chain(ring, m, n);
    if (!(best_[0][m] > kInvalid) || !(best_[m][n] > kInvalid))
      return (m == 2 && flip_23(face_between(ring, a, chain_[1]))) ||
             (n - m == 2 && flip_23(face_between(ring, a, chain_[m + 1])));
    made_.clear();
    add_chain(ring, 0, m);
    add_chain(ring, m, n);
    replace({ring.tets, static_cast<size_t>(n)}, made_);
    return true;
  }

  // Replaces the ring's tets by the best valid triangulation of its
  // polygon that has the triangle (a, b, c) (taken in ring order): that
  // triangle coned to the ring's edge ends becomes two tets sharing face
  // abc. False, and no change, when a, b or c is not on the ring or there
  // is no such triangulation.
  bool remove_with_triangle(const Ring& ring, uint32_t a, uint32_t b, uint32_t c) {
    const int n = ring.n;
    int mb = ring_from(ring, a, b);
    int mc = static_cast<int>(std::find(chain_, chain_ + n, c) - chain_);
    if (mb < 0 || mc == n) return false;
    if (mb > mc) {
      std::swap(mb, mc);
      std::swap(b, c);
    }
    if (!cones_positive(ring, a, b, c)) return false;
    for (const auto& [lo, hi] : {std::pair{0, mb}, std::pair{mb, mc}, std::pair{mc, n}}) {
      solve_chain(ring, lo, hi);
      if (!(best_[lo][hi] > kInvalid)) return false;
    }
    made_.clear();
    add_cones(ring, a, b, c);
    add_chain(ring, 0, mb);
    add_chain(ring, mb, mc);
    add_chain(ring, mc, n);
    replace({ring.tets, static_cast<size_t>(n)}, made_);
    return true;
  }

  // chain_: the ring's vertices from a, closed by a again (chain_[n]);
  // returns the position of v in it (-1 when v or a is not on the ring).
  int ring_from(const Ring& ring, uint32_t a, uint32_t v) {
    const int n = ring.n;
    const int start = static_cast<int>(std::find(ring.vertices, ring.vertices + n, a) - ring.vertices);
    if (start == n) return -1;
    int at = -1;
    for (int k = 0; k < n; ++k) {
      chain_[k] = ring.vertices[(start + k) % n];
      if (chain_[k] == v) at = k;
    }
    chain_[n] = a;
    return at;
  }

  // The best triangulations (the largest worst shape measure of their
  // cones) of the sub-chains of chain_[first..last], closed by their end
  // chord, into best_ and split_ (kInvalid: none whose cones are all
  // positive; a chain of one edge needs no triangle).
  void solve_chain(const Ring& ring, int first, int last) {
    auto triangle_quality = [&](int lo, int mid, int hi) {
      if (!cones_positive(ring, chain_[lo], chain_[mid], chain_[hi])) return kInvalid;
      const double *x = pt(chain_[lo]), *y = pt(chain_[mid]), *z = pt(chain_[hi]);
      return std::min(shape_measure(x, y, z, pt(ring.d)), shape_measure(y, x, z, pt(ring.b)));
    };
    for (int len = 1; len <= last - first; ++len)
      for (int lo = first; lo + len <= last; ++lo) {
        const int hi = lo + len;
        best_[lo][hi] = len == 1 ? std::numeric_limits<double>::infinity() : kInvalid;
        split_[lo][hi] = -1;
        for (int mid = lo + 1; mid < hi; ++mid) {
          const double q = std::min({best_[lo][mid], best_[mid][hi], triangle_quality(lo, mid, hi)});
          if (q > best_[lo][hi]) {
            best_[lo][hi] = q;
            split_[lo][hi] = mid;
          }
        }
      }
  }

  // Appends to made_ the cones of solve_chain's triangulation of
  // chain_[first..last].
  void add_chain(const Ring& ring, int first, int last) {
    int stack[2 * kChain], top = 0;
    stack[top++] = first;
    stack[top++] = last;
    while (top > 0) {
      const int hi = stack[--top], lo = stack[--top];
      if (hi - lo < 2) continue;
      const int mid = split_[lo][hi];
      add_cones(ring, chain_[lo], chain_[mid], chain_[hi]);
      stack[top++] = lo;
      stack[top++] = mid;
      stack[top++] = mid;
      stack[top++] = hi;
    }
  }

  // Whether triangle (x, y, z) of the ring's polygon, in ring order, coned
  // to d and to b gives two positive tets.
  bool cones_positive(const Ring& ring, uint32_t x, uint32_t y, uint32_t z) const {
    return orient3d(pt(x), pt(y), pt(z), pt(ring.d)) > 0 && orient3d(pt(y), pt(x), pt(z), pt(ring.b)) > 0;
  }

  // Appends those two tets to made_.
  void add_cones(const Ring& ring, uint32_t x, uint32_t y, uint32_t z) {
    made_.insert(made_.end(), {x, y, z, ring.d, y, x, z, ring.b});
  }

  // The 2-3 flip of the two tets on face `code` (4 t + i): with apexes u
  // (of t) and w (across), face (x, y, z), the tets (u, w, x, y), (u, w,
  // y, z) and (u, w, z, x) when uw crosses the face (all three positive, or
  // all three negative and then taken with w first) and the face is not an
  // input triangle (no input edge crosses one on a valid surface); false,
  // and no change, otherwise.
  bool flip_23(uint32_t code) {
    const uint32_t t = code / 4, across = d_.neighbours[code];
    const uint32_t* q = tet(t);
    if (across == kNoNeighbour || input_faces_.find(face_key(q, static_cast<int>(code % 4)))) return false;
    uint32_t u = q[code % 4], w = tet(across / 4)[across % 4];
    const uint32_t x = q[(code + 1) % 4], y = q[(code + 2) % 4], z = q[(code + 3) % 4];
    const int s1 = orient3d(pt(u), pt(w), pt(x), pt(y)), s2 = orient3d(pt(u), pt(w), pt(y), pt(z)),
              s3 = orient3d(pt(u), pt(w), pt(z), pt(x));
    if (s1 == 0 || s1 != s2 || s1 != s3) return false;
    if (s1 < 0) std::swap(u, w);
    made_.assign({u, w, x, y, u, w, y, z, u, w, z, x});
    const uint32_t old[2] = {t, across / 4};
    replace({old, 2}, made_);
    return true;
  }

  std::vector<uint8_t> take_flipped() { return std::move(flipped_); }

  // Makes input edge ac, missing, an edge if one of the flips of
  // edge_recovery.hpp can; b and d are the third vertices of its input
  // triangles. False, and no change, otherwise.
  bool recover(uint32_t a, uint32_t c, uint32_t b, uint32_t d) {
    if (chord_removal(b, d, a, c)) return true;
    uint32_t through[2];
    const int k = crossings(a, c, crossed_, through);
    if (k >= 2) {
      // Faces crossed one after the other share an edge (they are two
      // faces of one tet); when all share one, a and c lie on its ring.
      uint32_t common[3];
      std::copy_n(face_vertices(crossed_[0]).data(), 3, common);
      int n = 3;
      for (const uint32_t code : crossed_) {
        const std::array<uint32_t, 3> f = face_vertices(code);
        n = static_cast<int>(
            std::remove_if(common, common + n, [&](uint32_t v) { return std::find(f.begin(), f.end(), v) == f.end(); }) -
            common);
      }
      if (n == 2 && chord_removal(common[0], common[1], a, c)) return true;
    }
    // Steps from either end, a first: each takes away what the segment
    // meets first from that end (step_from), leaving less between a and c.
    for (int step = 0; step < kMaxRecoverySteps; ++step) {
      if (!step_from(a, c) && !step_from(c, a)) return false;
      if (tet_with_edge(a, c) != kNoNeighbour) return true;
    }
    return false;
  }

  // Makes input triangle abc a face when its three edges are edges and it
  // is not one yet: an edge pq opposite one of its edges uv in a tet of
  // uv's ring, not an input edge, whose ring holds a, b and c, is removed
  // by the best valid triangulation of its ring with the triangle
  // (remove_with_triangle). False, and no change, otherwise.
  bool recover_face(uint32_t a, uint32_t b, uint32_t c) {
    const uint32_t corners[3] = {a, b, c};
    Ring around[3];
    bool closed[3];
    for (int e = 0; e < 3; ++e) {
      const uint32_t u = corners[e], v = corners[(e + 1) % 3], w = corners[(e + 2) % 3];
      const uint32_t t = tet_with_edge(u, v);
      if (t == kNoNeighbour) return false;
      closed[e] = edge_ring(t, u, v, around[e]);
      if (closed[e] && std::find(around[e].vertices, around[e].vertices + around[e].n, w) !=
                           around[e].vertices + around[e].n)
        return false;  // abc is a face already
    }
    for (int e = 0; e < 3; ++e) {
      if (!closed[e]) continue;
      for (int k = 0; k < around[e].n; ++k) {
        const uint32_t p = around[e].vertices[k], q = around[e].vertices[(k + 1) % around[e].n];
        if (input_edges_.find(edge_key(p, q))) continue;
        const uint32_t with_pq = tet_with_edge(p, q);
        if (with_pq != kNoNeighbour && edge_ring(with_pq, p, q, ring_) && remove_with_triangle(ring_, a, b, c))
          return true;
      }
    }
    return false;
  }

  // One step of segment (from, to)'s recovery: where it leaves `from`
  // through an edge of from's star, that edge's removal with the chord, or
  // by the fan of its ring from `from`; where it crosses a face first,
  // advance. False, and no change, when none applies (or the walk meets an
  // edge or a vertex further on).
  bool step_from(uint32_t from, uint32_t to) {
    uint32_t through[2];
    const int k = crossings(from, to, crossed_, through);
    if (k > 0) return advance(crossed_[0], from);
    if (through[0] == kNoNeighbour) return false;
    return chord_removal(through[0], through[1], from, to) ||
           fan_removal(through[0], through[1], from, tet_with_edge(through[0], through[1]));
  }

  // Takes face `code` (4 t + i), crossed by a segment from t's vertex
  // `from` = t[i], out of the segment's way: its 2-3 flip when valid, else
  // the removal of an edge of it (not an input edge) by the fan of its ring
  // from `from` (remove_with_fan), where the apex across lies beyond that
  // edge as seen from `from`. Every new tet then has `from`, so the
  // segment leaves `from` past the tets taken away. False, and no change,
  // when neither applies.
  bool advance(uint32_t code, uint32_t from) {
    if (flip_23(code)) return true;
    const uint32_t t = code / 4, across = d_.neighbours[code];
    if (across == kNoNeighbour) return false;
    const uint32_t w = tet(across / 4)[across % 4];
    const std::array<uint32_t, 3> f = face_vertices(code);
    for (int e = 0; e < 3; ++e) {
      const uint32_t x = f[e], y = f[(e + 1) % 3], z = f[(e + 2) % 3];
      // w beyond edge xy: not on z's side of plane (from, x, y).
      if (orient3d(pt(from), pt(x), pt(y), pt(w)) == orient3d(pt(from), pt(x), pt(y), pt(z))) continue;
      if (fan_removal(x, y, from, t)) return true;
    }
    return false;
  }

  // Replaces the ring's tets by the fan of its polygon from ring vertex a
  // (triangles (a, r_k, r_k+1)), each triangle coned to b and to d, when
  // every new tet is positive; false, and no change, otherwise.
  bool remove_with_fan(const Ring& ring, uint32_t a) {
    const int n = ring.n;
    const int start = static_cast<int>(std::find(ring.vertices, ring.vertices + n, a) - ring.vertices);
    if (start == n || n < 3) return false;
    made_.clear();
    for (int k = 1; k + 1 < n; ++k) {
      const uint32_t y = ring.vertices[(start + k) % n], z = ring.vertices[(start + k + 1) % n];
      if (!cones_positive(ring, a, y, z)) return false;
      add_cones(ring, a, y, z);
    }
    replace({ring.tets, static_cast<size_t>(n)}, made_);
    return true;
  }

  // The faces segment ac crosses, from a, as codes 4 t + i of the tet
  // before each: their number, or -1 when the segment meets an edge or a
  // vertex on its way (or a has no tet), which this walk does not follow.
  // `through` gets the edge of a's star the segment leaves a through,
  // when it does (both ends, else kNoNeighbour).
  int crossings(uint32_t a, uint32_t c, std::vector<uint32_t>& crossed, uint32_t through[2]) {
    crossed.clear();
    through[0] = through[1] = kNoNeighbour;
    star_of(a);
    uint32_t p = 0, q = 0, r = 0, current = kNoNeighbour;
    for (const uint32_t t : queue_) {
      const uint32_t* v = tet(t);
      const int i = local(t, a);
      int zeros = 0, zero = -1;
      bool inside = true;
      for (int j = 0; j < 4 && inside; ++j) {
        if (j == i) continue;
        const double* x[4] = {pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3])};
        x[j] = pt(c);
        const int o = orient3d(x[0], x[1], x[2], x[3]);
        inside = o >= 0;
        if (o == 0) ++zeros, zero = j;
      }
      if (!inside) continue;
      if (zeros == 1) {  // through the edge of the face opposite a that lies opposite v[zero]
        int k = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i && j != zero) through[k++] = v[j];
        return -1;
      }
      if (zeros > 0) continue;
      current = t;
      p = v[(i + 1) % 4];
      q = v[(i + 2) % 4];
      r = v[(i + 3) % 4];
      break;
    }
    if (current == kNoNeighbour) return -1;
    const int sigma = orient3d(pt(a), pt(c), pt(p), pt(q));
    if (sigma == 0 || orient3d(pt(a), pt(c), pt(q), pt(r)) != sigma || orient3d(pt(a), pt(c), pt(r), pt(p)) != sigma)
      return -1;
    for (int steps = 0; steps < 64; ++steps) {
      const uint32_t code = 4 * current + static_cast<uint32_t>(local_face(current, p, q, r));
      crossed.push_back(code);
      const uint32_t across = d_.neighbours[code];
      if (across == kNoNeighbour) return -1;
      current = across / 4;
      const uint32_t w = tet(current)[across % 4];
      if (w == c) return static_cast<int>(crossed.size());
      const int tp = orient3d(pt(a), pt(c), pt(p), pt(w)), tq = orient3d(pt(a), pt(c), pt(q), pt(w)),
                tr = orient3d(pt(a), pt(c), pt(r), pt(w));
      if (tp == 0 || tq == 0 || tr == 0) return -1;
      if (tr == sigma && tq == -sigma) {  // out through (q, r, w)
        p = q;
        q = r;
        r = w;
      } else if (tp == sigma && tr == -sigma) {  // through (r, p, w)
        const uint32_t old_p = p;
        p = r;
        q = old_p;
        r = w;
      } else if (tq == sigma && tp == -sigma) {  // through (p, q, w)
        r = w;
      } else {
        return -1;
      }
    }
    return -1;
  }

 private:
  // Removes edge uv with the chord ac (remove_with_chord) when uv is an
  // edge, not an input edge, and its ring closes and holds a and c.
  bool chord_removal(uint32_t u, uint32_t v, uint32_t a, uint32_t c) {
    if (input_edges_.find(edge_key(u, v))) return false;
    const uint32_t t = tet_with_edge(u, v);
    if (t == kNoNeighbour || !edge_ring(t, u, v, ring_)) return false;
    const uint32_t* const begin = ring_.vertices;
    const uint32_t* const end = begin + ring_.n;
    if (std::find(begin, end, a) == end || std::find(begin, end, c) == end) return false;
    return remove_with_chord(ring_, a, c);
  }

  // Removes edge uv, which tet t has, by the fan of its ring from `from`
  // (remove_with_fan) when uv is not an input edge and its ring closes.
  bool fan_removal(uint32_t u, uint32_t v, uint32_t from, uint32_t t) {
    if (input_edges_.find(edge_key(u, v)) || t == kNoNeighbour || !edge_ring(t, u, v, ring_)) return false;
    return remove_with_fan(ring_, from);
  }

  std::array<uint32_t, 3> face_vertices(uint32_t code) const {
    const uint32_t* q = tet(code / 4);
    return {q[(code + 1) % 4], q[(code + 2) % 4], q[(code + 3) % 4]};
  }

  // The face (b, d, x) of the ring's tet on (b, d, a, x), as its code.
  uint32_t face_between(const Ring& ring, uint32_t a, uint32_t x) const {
    for (int k = 0; k < ring.n; ++k) {
      const uint32_t* q = tet(ring.tets[k]);
      if (std::find(q, q + 4, a) != q + 4 && std::find(q, q + 4, x) != q + 4) return 4 * ring.tets[k] + local(ring.tets[k], a);
    }
    PARTET_ASSERT(false, "a ring vertex next to a shares a ring tet with it");
    return 0;
  }

  // The tets having v, in queue_.
  void star_of(uint32_t v) { search_star(v, kNoNeighbour); }

  // Breadth first over v's star (across the faces having v) into queue_,
  // from its recorded tet: the first tet met that also has w, or
  // kNoNeighbour after the whole star.
  uint32_t search_star(uint32_t v, uint32_t w) {
    queue_.clear();
    const uint32_t start = vertex_tet_[v];
    if (start == kNoNeighbour) return kNoNeighbour;
    if (++stamp_ == 0) {
      std::fill(seen_.begin(), seen_.end(), 0);
      stamp_ = 1;
    }
    queue_.push_back(start);
    seen_[start] = stamp_;
    for (size_t k = 0; k < queue_.size(); ++k) {
      const uint32_t t = queue_[k];
      const uint32_t* q = tet(t);
      if (w != kNoNeighbour && (q[0] == w || q[1] == w || q[2] == w || q[3] == w)) return t;
      for (int i = 0; i < 4; ++i) {
        if (q[i] == v) continue;  // the face opposite v does not have it
        const uint32_t across = d_.neighbours[4 * size_t{t} + i];
        if (across == kNoNeighbour || seen_[across / 4] == stamp_) continue;
        seen_[across / 4] = stamp_;
        queue_.push_back(across / 4);
      }
    }
    return kNoNeighbour;
  }

  // The local index of the vertex of tet t that is none of x, y, z.
  int local_face(uint32_t t, uint32_t x, uint32_t y, uint32_t z) const {
    const uint32_t* q = tet(t);
    for (int i = 0; i < 4; ++i)
      if (q[i] != x && q[i] != y && q[i] != z) return i;
    return 0;
  }
  const uint32_t* tet(uint32_t t) const { return &d_.tets[4 * size_t{t}]; }
  const double* pt(uint32_t v) const { return &d_.xyz[3 * size_t{v}]; }
  int local(uint32_t t, uint32_t v) const {
    const uint32_t* q = tet(t);
    return q[0] == v ? 0 : q[1] == v ? 1 : q[2] == v ? 2 : 3;
  }

  // The tets `old` give way to `made` (4 vertices per tet): their slots
  // first, then new ones; faces matched among the new tets, and the others
  // to the neighbours of the old tets' outer faces.
  void replace(std::span<const uint32_t> old, const std::vector<uint32_t>& made) {
    outer_.clear();
    for (const uint32_t t : old)
      for (int i = 0; i < 4; ++i) {
        const uint32_t across = d_.neighbours[4 * size_t{t} + i];
        if (across != kNoNeighbour && std::find(old.begin(), old.end(), across / 4) != old.end()) continue;
        outer_.push_back({face_key(tet(t), i), across});
      }
    const size_t count = made.size() / 4;
    slots_.assign(old.begin(), old.end());
    surplus_.clear();
    while (slots_.size() > count) {
      surplus_.push_back(slots_.back());
      slots_.pop_back();
    }
    while (slots_.size() < count) {
      slots_.push_back(static_cast<uint32_t>(d_.num_tets()));
      d_.tets.insert(d_.tets.end(), 4, 0);
      d_.neighbours.insert(d_.neighbours.end(), 4, kNoNeighbour);
      seen_.push_back(0);
      flipped_.push_back(0);
    }
    faces_.clear();
    for (size_t k = 0; k < count; ++k) {
      const uint32_t t = slots_[k];
      flipped_[t] = 1;
      std::copy_n(&made[4 * k], 4, &d_.tets[4 * size_t{t}]);
      for (int i = 0; i < 4; ++i) {
        vertex_tet_[made[4 * k + i]] = t;
        faces_.push_back({face_key(&made[4 * k], i), 4 * t + i});
      }
    }
    std::sort(faces_.begin(), faces_.end());
    for (size_t i = 0; i < faces_.size(); ++i) {
      if (i + 1 < faces_.size() && faces_[i].key == faces_[i + 1].key) {
        d_.neighbours[faces_[i].code] = faces_[i + 1].code;
        d_.neighbours[faces_[i + 1].code] = faces_[i].code;
        ++i;
        continue;
      }
      const auto o =
          std::find_if(outer_.begin(), outer_.end(), [&](const Outer& x) { return x.key == faces_[i].key; });
      PARTET_ASSERT(o != outer_.end(), "a recovery's new face is neither shared nor on the old tets' boundary");
      d_.neighbours[faces_[i].code] = o->across;
      if (o->across != kNoNeighbour) d_.neighbours[o->across] = faces_[i].code;
    }
    // The slots a flip to fewer tets leaves, highest first: each gets the
    // last tet (so a later, lower one never is the last one moved).
    std::sort(surplus_.begin(), surplus_.end(), std::greater<>());
    for (const uint32_t t : surplus_) drop_slot(t);
  }

  // Removes the unused slot t: the last tet moves into it, its
  // neighbours' links, its vertices' tets and its flags with it.
  void drop_slot(uint32_t t) {
    const uint32_t last = static_cast<uint32_t>(d_.num_tets() - 1);
    if (t != last) {
      for (int i = 0; i < 4; ++i) {
        const uint32_t v = d_.tets[4 * size_t{last} + i];
        d_.tets[4 * size_t{t} + i] = v;
        if (vertex_tet_[v] == last) vertex_tet_[v] = t;
        const uint32_t across = d_.neighbours[4 * size_t{last} + i];
        d_.neighbours[4 * size_t{t} + i] = across;
        if (across != kNoNeighbour) d_.neighbours[across] = 4 * t + static_cast<uint32_t>(i);
      }
      seen_[t] = seen_[last];
      flipped_[t] = flipped_[last];
    }
    d_.tets.resize(4 * size_t{last});
    d_.neighbours.resize(4 * size_t{last});
    seen_.pop_back();
    flipped_.pop_back();
  }

  static constexpr int kChain = kMaxRecoveryRing + 1;

  DelaunayTets& d_;
  const EdgeMap& input_edges_;
  const FaceMap& input_faces_;
  Ring ring_;
  std::vector<uint32_t> crossed_;
  std::vector<uint32_t> vertex_tet_;  // per vertex, a tet having it
  std::vector<uint32_t> seen_;        // per tet, the stamp of the last search that met it
  uint32_t stamp_ = 0;
  std::vector<uint32_t> queue_, made_, slots_, surplus_;
  std::vector<uint8_t> flipped_;  // per tet, whether a flip made it
  std::vector<Outer> outer_;
  std::vector<FaceCode> faces_;
  uint32_t chain_[kChain] = {};
  double best_[kChain][kChain] = {};
  int split_[kChain][kChain] = {};
};

}  // namespace

EdgeRecoveryCounts recover_input_edges(DelaunayTets& d, std::span<const uint32_t> triangles,
                                       std::vector<uint8_t>& flipped) {
  EdgeRecoveryCounts counts;
  const size_t num_triangles = triangles.size() / 3;
  const size_t num_vertices = d.xyz.size() / 3;
  FlatHashMap<VertexTriple, uint32_t, VertexTripleTraits> input;
  FlatHashMap<uint64_t, EdgeSides, EdgeKeyTraits> sides;
  input.reserve(num_triangles);
  sides.reserve(num_triangles * 3 / 2 + 1);
  std::vector<uint8_t> on_input(num_vertices, 0);
  for (size_t s = 0; s < num_triangles; ++s) {
    const uint32_t* f = &triangles[3 * s];
    input.get_or_insert(sorted_triple(f[0], f[1], f[2]), static_cast<uint32_t>(s));
    for (int k = 0; k < 3; ++k) {
      on_input[f[k]] = 1;
      EdgeSides& e = sides.get_or_insert(edge_key(f[k], f[(k + 1) % 3]), EdgeSides{});
      if (e.count < 2) e.opposite[e.count] = f[(k + 2) % 3];
      ++e.count;
    }
  }
  std::vector<uint8_t> present(num_triangles, 0);
  for (size_t t = 0; t < d.num_tets(); ++t) {
    const uint32_t* v = &d.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      if (!on_input[v[(i + 1) % 4]] || !on_input[v[(i + 2) % 4]] || !on_input[v[(i + 3) % 4]]) continue;
      if (const uint32_t* s = input.find(face_key(v, i))) present[*s] = 1;
    }
  }
  std::vector<uint64_t> candidates;
  for (size_t s = 0; s < num_triangles; ++s) {
    if (present[s]) continue;
    ++counts.missing_triangles;
    const uint32_t* f = &triangles[3 * s];
    for (int k = 0; k < 3; ++k) candidates.push_back(edge_key(f[k], f[(k + 1) % 3]));
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  Recovery recovery(d, sides, input);
  std::vector<uint64_t> later;
  // Each round that continues recovered an edge, which stays (no flip
  // destroys an input edge) and leaves the candidates: the rounds end, and
  // at most kMaxRecoveryRounds run.
  for (bool progress = true; progress && !candidates.empty() && counts.rounds < kMaxRecoveryRounds;) {
    progress = false;
    ++counts.rounds;
    later.clear();
    for (const uint64_t key : candidates) {
      const uint32_t a = static_cast<uint32_t>(key >> 32), c = static_cast<uint32_t>(key);
      const EdgeSides& e = *sides.find(key);
      if (e.count != 2 || e.opposite[0] == e.opposite[1]) continue;
      if (recovery.tet_with_edge(a, c) != kNoNeighbour) continue;
      if (recovery.recover(a, c, e.opposite[0], e.opposite[1])) {
        ++counts.recovered_edges;
        progress = true;
      } else {
        later.push_back(key);
      }
    }
    candidates.swap(later);
  }
  // Then the triangles still missing whose three edges are there.
  for (size_t s = 0; s < num_triangles; ++s) {
    const uint32_t* f = &triangles[3 * s];
    if (!present[s]) counts.recovered_faces += recovery.recover_face(f[0], f[1], f[2]);
  }
  flipped = recovery.take_flipped();
  return counts;
}

}  // namespace partet
