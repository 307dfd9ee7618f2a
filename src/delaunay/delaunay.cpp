// Incremental Delaunay tetrahedralization (see delaunay.hpp).
#include "delaunay/delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "core/point_text.hpp"
#include "core/predicates.hpp"
#include "octree/box_morton.hpp"

namespace partet {
namespace {

constexpr uint32_t kDead = UINT32_MAX;

// The insertion order, biased randomized (BRIO, Amenta, Choi and Rote):
// the points shuffled (a fixed xorshift sequence), cut into rounds that
// double in size up to the last half, each round in Morton order of the
// points' cells on a 2^21 grid over their bounding box (ties by index).
// Each round covers the whole body coarsely before the next refines it, so
// a point's cavity stays small; in one Morton sweep each point lands on the
// frontier of what is inserted, whose tets reach to the enclosing corners,
// and femur r1's cavities averaged 30 tets.
std::vector<uint32_t> insertion_order(const std::vector<double>& xyz, const BoxMorton& grid) {
  const size_t n = xyz.size() / 3;
  std::vector<uint32_t> shuffled(n);
  for (size_t i = 0; i < n; ++i) shuffled[i] = static_cast<uint32_t>(i);
  uint64_t state = 0x9e3779b97f4a7c15ULL;
  for (size_t i = n; i > 1; --i) {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    std::swap(shuffled[i - 1], shuffled[state % i]);
  }
  std::vector<std::pair<uint64_t, uint32_t>> keyed(n);
  for (size_t j = 0; j < n; ++j) {
    const size_t i = shuffled[j];
    keyed[j] = {grid.key(&xyz[3 * i]), static_cast<uint32_t>(i)};
  }
  std::vector<size_t> ends;  // round ends, last round first
  for (size_t m = n; m > 0; m /= 2) {
    ends.push_back(m);
    if (m < 64) break;
  }
  size_t begin = 0;
  for (auto e = ends.rbegin(); e != ends.rend(); ++e) {
    std::sort(keyed.begin() + static_cast<std::ptrdiff_t>(begin), keyed.begin() + static_cast<std::ptrdiff_t>(*e));
    begin = *e;
  }
  std::vector<uint32_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

// kEvenRest[i][j]: the k, l that make (i, j, k, l) an even permutation of
// (0, 1, 2, 3), for i != j.
constexpr int kEvenRest[4][4][2] = {
    {{0, 0}, {2, 3}, {3, 1}, {1, 2}},
    {{3, 2}, {0, 0}, {0, 3}, {2, 0}},
    {{1, 3}, {3, 0}, {0, 0}, {0, 1}},
    {{2, 1}, {0, 2}, {1, 0}, {0, 0}},
};

class Builder {
 public:
  explicit Builder(const std::vector<double>& xyz) : n_(xyz.size() / 3) {
    PARTET_ASSERT(n_ + 4 < kDead / 4, "too many points for the Delaunay tetrahedralization");
    const BoxMorton grid(xyz);
    const double *lo = grid.lo(), *hi = grid.hi();
    order_ = insertion_order(xyz, grid);
    out_.num_points = n_;
    // The points in insertion order: the builder's vertex i is input point
    // order_[i], so the points a cavity's tets reach sit close in memory.
    points_.resize(n_ + 4);
    for (size_t i = 0; i < n_; ++i) std::copy_n(&xyz[3 * size_t{order_[i]}], 3, points_[i].xyz);
    // Corners of the tet {x, y, z >= c - K, (x + y + z) - 3c <= 3K} around
    // the box's centre c, K = 4 extent: it holds the cube of half edge K
    // (whose corner c + (K, K, K) lies on its slanted face), so every
    // point, within half an extent of c, lies deep inside.
    double centre[3], extent = 0;
    for (int k = 0; k < 3; ++k) {
      centre[k] = 0.5 * (lo[k] + hi[k]);
      extent = std::max(extent, hi[k] - lo[k]);
    }
    const double big = 4 * std::max(extent, 1.0);
    const double corners[4][3] = {
        {-big, -big, -big}, {5 * big, -big, -big}, {-big, 5 * big, -big}, {-big, -big, 5 * big}};
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) points_[n_ + c].xyz[k] = centre[k] + corners[c][k];
    const uint32_t first = static_cast<uint32_t>(n_);
    new_tet(first, first + 1, first + 2, first + 3);
    for (int i = 0; i < 4; ++i) nb_[i] = kNoNeighbour;
  }

  DelaunayTets run(const std::vector<double>& xyz) {
    uint32_t last = 0;
    for (uint32_t p = 0; p < n_; ++p) last = insert(p, last);
    out_.xyz.reserve(3 * (n_ + 4));
    out_.xyz = xyz;
    for (size_t c = n_; c < n_ + 4; ++c) out_.xyz.insert(out_.xyz.end(), points_[c].xyz, points_[c].xyz + 3);
    std::vector<Point>().swap(points_);
    compact();
    return std::move(out_);
  }

 private:
  const double* pt(uint32_t v) const { return points_[v].xyz; }
  uint32_t& local(uint32_t v) { return points_[v].local; }
  const uint32_t* tet(uint32_t t) const { return &tv_[4 * size_t{t}]; }
  uint32_t& neighbour(uint32_t t, int i) { return nb_[4 * size_t{t} + static_cast<size_t>(i)]; }
  uint32_t& neighbour(uint32_t code) { return nb_[code]; }

  uint32_t new_tet(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
    } else {
      t = static_cast<uint32_t>(tv_.size() / 4);
      tv_.resize(tv_.size() + 4);
      nb_.resize(nb_.size() + 4);
      state_.push_back(kUnseen);
    }
    uint32_t* v = &tv_[4 * size_t{t}];
    v[0] = a, v[1] = b, v[2] = c, v[3] = d;
    return t;
  }

  // orient3d of tet t with vertex i replaced by p: negative when p lies
  // strictly beyond face i.
  int side(uint32_t t, int i, const double* p) const {
    const double* q[4];
    for (int k = 0; k < 4; ++k) q[k] = k == i ? p : pt(tet(t)[k]);
    return orient3d(q[0], q[1], q[2], q[3]);
  }

  bool contains(uint32_t t, const double* p) const {
    for (int i = 0; i < 4; ++i)
      if (side(t, i, p) < 0) return false;
    return true;
  }

  uint32_t locate(uint32_t p, uint32_t start) {
    const double* x = pt(p);
    uint32_t t = start;
    int entered = -1;  // the face of t the walk came in through: x lies strictly on t's side of it
    const size_t budget = 64 + 4 * (tv_.size() / 4);
    for (size_t step = 0; step < budget; ++step) {
      ++out_.walk_steps;
      rotate_ = (rotate_ + 1) & 3;
      int beyond = -1;
      for (int k = 0; k < 4 && beyond < 0; ++k) {
        const int i = (rotate_ + k) & 3;
        if (i != entered && side(t, i, x) < 0) beyond = i;
      }
      if (beyond < 0) return t;
      const uint32_t across = neighbour(t, beyond);
      PARTET_ASSERT(across != kNoNeighbour, "a point lies outside the enclosing tet");
      t = across / 4;
      entered = static_cast<int>(across % 4);
    }
    for (uint32_t u = 0; u < tv_.size() / 4; ++u)
      if (tv_[4 * size_t{u}] != kDead && contains(u, x)) return u;
    throw InternalError("Delaunay tetrahedralization: no tet holds point " + std::to_string(order_[p]));
  }

  bool in_conflict(uint32_t t, const double* x) const {
    const uint32_t* v = tet(t);
    return insphere(pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3]), x) > 0;
  }

  // A face of the cavity's boundary: the cavity tet's vertices with the
  // index of the face (the vertex the point replaces), and the tet outside.
  struct BoundaryFace {
    uint32_t v[4];
    int i;
    uint32_t outside;  // 4 u + j, or kNoNeighbour
  };

  uint32_t insert(uint32_t p, uint32_t start) {
    const double* x = pt(p);
    const uint32_t t0 = locate(p, start);
    if (!in_conflict(t0, x)) {
      const uint32_t* v = tet(t0);
      for (int k = 0; k < 4; ++k)
        if (std::equal(pt(v[k]), pt(v[k]) + 3, x))
          throw InternalError("Delaunay tetrahedralization: points " + std::to_string(order_[v[k]]) + " and " +
                              std::to_string(order_[p]) + " coincide at " + point_text(x));
      throw InternalError("Delaunay tetrahedralization: the tet holding point " + std::to_string(order_[p]) +
                          " is not in conflict with it");
    }
    ++epoch_;
    cavity_.assign(1, t0);
    state_[t0] = kInCavity;
    boundary_.clear();
    for (size_t c = 0; c < cavity_.size(); ++c) {
      const uint32_t u = cavity_[c];
      for (int i = 0; i < 4; ++i) {
        const uint32_t across = neighbour(u, i);
        if (across != kNoNeighbour) {
          const uint32_t w = across / 4;
          if (state_[w] == kUnseen) {
            const bool conflict = in_conflict(w, x);
            state_[w] = conflict ? kInCavity : kOutside;
            if (conflict) cavity_.push_back(w);
          }
          if (state_[w] == kInCavity) continue;
        }
        BoundaryFace f;
        std::copy(tet(u), tet(u) + 4, f.v);
        f.i = i;
        f.outside = across;
        boundary_.push_back(f);
      }
    }
    out_.cavity_tets += cavity_.size();
    for (uint32_t u : cavity_) {
      tv_[4 * size_t{u}] = kDead;
      state_[u] = kUnseen;
      free_.push_back(u);
    }
    for (const BoundaryFace& f : boundary_)
      if (f.outside != kNoNeighbour) state_[f.outside / 4] = kUnseen;
    return make_tets(p);
  }

  // The cavity's new tets, the point coned to each boundary face, linked to
  // the tets outside and to each other. New tet T (p at index i) meets the
  // new tet across its face j at the edge (v[k], v[l]), (i, j, k, l) an
  // even permutation: T's positive orientation gives that edge one
  // direction and the other tet's the opposite one, so each side face is
  // found as its directed edge's reverse in a table over the boundary's
  // vertices numbered locally (a hash of the edges when they are many).
  uint32_t make_tets(uint32_t p) {
    uint32_t nv = 0;
    for (const BoundaryFace& f : boundary_)
      for (int k = 0; k < 4; ++k)
        if (k != f.i && local(f.v[k]) == kNoLocal) {
          local(f.v[k]) = nv++;
          touched_.push_back(f.v[k]);
        }
    out_.largest_boundary = std::max<size_t>(out_.largest_boundary, nv);
    const bool direct = nv <= kDirectVertices;
    if (direct) {
      if (table_.size() < size_t{nv} * nv) table_.resize(size_t{nv} * nv);
    } else {
      prepare_edges(boundary_.size() * 3 / 2);
    }
    made_.clear();
    for (const BoundaryFace& f : boundary_) {
      uint32_t v[4] = {f.v[0], f.v[1], f.v[2], f.v[3]};
      v[f.i] = p;
      const uint32_t made = new_tet(v[0], v[1], v[2], v[3]);
      made_.push_back(made);
      neighbour(made, f.i) = f.outside;
      if (f.outside != kNoNeighbour) neighbour(f.outside) = 4 * made + f.i;
      for (int j = 0; j < 4; ++j) {
        if (j == f.i) continue;
        const uint32_t a = f.v[kEvenRest[f.i][j][0]], b = f.v[kEvenRest[f.i][j][1]];
        if (direct)
          table_[size_t{local(a)} * nv + local(b)] = 4 * made + j;
        else
          link_edge(std::min(a, b), std::max(a, b), 4 * made + j);
      }
    }
    if (direct) {
      for (size_t b = 0; b < boundary_.size(); ++b) {
        const BoundaryFace& f = boundary_[b];
        for (int j = 0; j < 4; ++j) {
          if (j == f.i) continue;
          const uint32_t u = f.v[kEvenRest[f.i][j][0]], w = f.v[kEvenRest[f.i][j][1]];
          neighbour(4 * made_[b] + j) = table_[size_t{local(w)} * nv + local(u)];
        }
      }
    }
    for (uint32_t v : touched_) local(v) = kNoLocal;
    touched_.clear();
    return made_.back();
  }

  void link_edge(uint32_t a, uint32_t b, uint32_t face) {
    const uint64_t key = uint64_t{a} << 32 | b;
    for (size_t s = hash_mix(key) & edge_mask_;; s = (s + 1) & edge_mask_) {
      if (edge_epoch_[s] != epoch_) {
        edge_epoch_[s] = epoch_;
        edge_key_[s] = key;
        edge_face_[s] = face;
        return;
      }
      if (edge_key_[s] == key) {
        neighbour(face) = edge_face_[s];
        neighbour(edge_face_[s]) = face;
        return;
      }
    }
  }
  void prepare_edges(size_t edges) {
    size_t capacity = 64;
    while (capacity < 2 * edges) capacity *= 2;
    if (capacity > edge_key_.size()) {
      edge_key_.assign(capacity, 0);
      edge_face_.assign(capacity, 0);
      edge_epoch_.assign(capacity, 0);
    }
    edge_mask_ = capacity - 1;
  }

  // The alive slots moved down in place (a slot only ever moves to a lower
  // one) and handed over: no second copy of the tets at the peak (the
  // capacity left is the few slots freed last).
  void compact() {
    const size_t slots = tv_.size() / 4;
    std::vector<uint32_t> index(slots, kDead);
    uint32_t count = 0;
    for (size_t t = 0; t < slots; ++t)
      if (tv_[4 * t] != kDead) index[t] = count++;
    std::vector<uint8_t>().swap(state_);
    std::vector<uint32_t>().swap(free_);
    for (size_t t = 0; t < slots; ++t) {
      if (index[t] == kDead) continue;
      for (int k = 0; k < 4; ++k) {
        const uint32_t v = tv_[4 * t + k];
        tv_[4 * size_t{index[t]} + k] = v < n_ ? order_[v] : v;
        const uint32_t across = nb_[4 * t + k];
        nb_[4 * size_t{index[t]} + k] = across == kNoNeighbour ? kNoNeighbour : 4 * index[across / 4] + across % 4;
      }
    }
    tv_.resize(4 * size_t{count});
    nb_.resize(4 * size_t{count});
    out_.tets = std::move(tv_);
    out_.neighbours = std::move(nb_);
  }

  size_t n_;
  std::vector<uint32_t> order_;
  // A point in insertion order (then the enclosing tet's corners), with its
  // number on the current cavity's boundary (kNoLocal when not on it) in the
  // same cache line as its coordinates, which the cavity's tests have read.
  struct alignas(32) Point {
    double xyz[3];
    uint32_t local = UINT32_MAX;
  };
  std::vector<Point> points_;
  DelaunayTets out_;
  std::vector<uint32_t> tv_, nb_, free_;
  // Per tet during an insertion: not yet tested, in the cavity, or tested
  // and outside it; back to kUnseen when the insertion ends.
  enum : uint8_t { kUnseen, kInCavity, kOutside };
  std::vector<uint8_t> state_;
  uint32_t epoch_ = 0;
  int rotate_ = 0;
  std::vector<uint32_t> cavity_;
  std::vector<BoundaryFace> boundary_;
  static constexpr uint32_t kNoLocal = UINT32_MAX;
  static constexpr uint32_t kDirectVertices = 256;
  std::vector<uint32_t> touched_;  // the vertices numbered
  std::vector<uint32_t> table_;    // directed edge (local a, local b) -> the new tet's face on it
  std::vector<uint32_t> made_;     // the new tet on each boundary face
  std::vector<uint64_t> edge_key_;
  std::vector<uint32_t> edge_face_, edge_epoch_;
  size_t edge_mask_ = 0;
};

}  // namespace

DelaunayTets delaunay_tetrahedralize(const std::vector<double>& xyz) { return Builder(xyz).run(xyz); }

}  // namespace partet
