// TetTopology (see tet_topology.hpp). Adjacency is built once from the
// tets of each vertex; replace() relinks only the faces of
// the new tets, matching them among themselves and against the cavity's
// outer faces by linear search (a cavity has at most a few dozen faces).
#include "optimize/tet_topology.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

using FaceKey = std::array<uint32_t, 3>;

FaceKey face_key(const uint32_t* tet, int f) {
  FaceKey key;
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != f) key[n++] = tet[k];
  std::sort(key.begin(), key.end());
  return key;
}

// True when (i, j, k, l), a permutation of 0..3, is odd.
bool odd_permutation(int i, int j, int k, int l) {
  const int p[4] = {i, j, k, l};
  int inversions = 0;
  for (int x = 0; x < 4; ++x)
    for (int y = x + 1; y < 4; ++y) inversions += p[x] > p[y];
  return inversions % 2 == 1;
}

}  // namespace

TetTopology::TetTopology(TetMesh& mesh) : mesh_(mesh) {
  const uint32_t n = slots();
  twin_.assign(4 * static_cast<size_t>(n), kNone);
  vertex_tet_.assign(mesh_.num_vertices(), kNone);
  mark_.assign(n, 0);
  quality_.assign(n, std::numeric_limits<double>::quiet_NaN());
  // The tets of every vertex (ascending), then each face's twin among the
  // tets of its smallest vertex: 16 bytes per tet, where sorting the faces
  // took 64.
  std::vector<uint32_t> first(mesh_.num_vertices() + 1, 0);
  for (uint32_t v : mesh_.tets) ++first[v + 1];
  for (size_t v = 0; v < mesh_.num_vertices(); ++v) first[v + 1] += first[v];
  std::vector<uint32_t> tets_of(first.back());
  {
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (uint32_t t = 0; t < n; ++t)
      for (int k = 0; k < 4; ++k) {
        const uint32_t v = tet(t)[k];
        tets_of[fill[v]++] = t;
        vertex_tet_[v] = t;
      }
  }
  for (uint32_t t = 0; t < n; ++t) {
    const uint32_t* vt = tet(t);
    for (int f = 0; f < 4; ++f) {
      if (twin_[4 * t + f] != kNone) continue;
      const FaceKey key = face_key(vt, f);
      uint32_t match = kNone;
      for (uint32_t i = first[key[0]]; i < first[key[0] + 1]; ++i) {
        const uint32_t u = tets_of[i];
        if (u == t) continue;
        const uint32_t* vu = tet(u);
        if (local_index(vu, key[1]) < 0 || local_index(vu, key[2]) < 0) continue;
        PARTET_ASSERT(match == kNone, "a face of the mesh to optimize is shared by more than two tets");
        match = u;
      }
      if (match == kNone) continue;
      const uint32_t* vu = tet(match);
      int g = 0;
      while (vu[g] == key[0] || vu[g] == key[1] || vu[g] == key[2]) ++g;
      PARTET_ASSERT(twin_[4 * match + g] == kNone, "a face of the mesh to optimize is shared by more than two tets");
      link(4 * t + f, 4 * match + g);
    }
  }
}

uint32_t TetTopology::add_vertex(const double* p, uint64_t global_id) {
  const uint32_t v = static_cast<uint32_t>(num_vertices());
  PARTET_ASSERT(v < kNone, "too many vertices");
  mesh_.xyz.insert(mesh_.xyz.end(), p, p + 3);
  if (!mesh_.global_ids.empty()) mesh_.global_ids.push_back(global_id);
  vertex_tet_.push_back(kNone);
  return v;
}

void TetTopology::remove_last_vertex() {
  PARTET_ASSERT(vertex_tet_.back() == kNone, "removing a vertex that tets still have");
  mesh_.xyz.resize(mesh_.xyz.size() - 3);
  if (!mesh_.global_ids.empty()) mesh_.global_ids.pop_back();
  vertex_tet_.pop_back();
}

std::vector<uint8_t> TetTopology::boundary_vertices() const {
  std::vector<uint8_t> boundary(num_vertices(), 0);
  for (uint32_t code = 0; code < twin_.size(); ++code) {
    if (twin_[code] != kNone || !alive(code / 4)) continue;
    for (int k = 0; k < 4; ++k)
      if (k != static_cast<int>(code % 4)) boundary[tet(code / 4)[k]] = 1;
  }
  return boundary;
}

void TetTopology::replace(std::span<const uint32_t> old_tets, std::span<const uint32_t> new_tets,
                          std::vector<uint32_t>& created) {
  struct Outer {
    FaceKey key;
    uint32_t twin;
    bool matched;
  };
  std::vector<Outer> outer;
  auto in_cavity = [&](uint32_t t) { return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end(); };
  for (uint32_t t : old_tets) {
    PARTET_ASSERT(alive(t), "replacing a dead tet");
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = twin_[4 * t + f];
      if (other == kNone || !in_cavity(other / 4)) outer.push_back({face_key(tet(t), f), other, false});
    }
  }
  // Freed in reverse, so that new tet i takes the slot of old tet i.
  for (size_t i = old_tets.size(); i-- > 0;) {
    const uint32_t t = old_tets[i];
    for (int k = 0; k < 4; ++k) vertex_tet_[tet(t)[k]] = kNone;
    for (int f = 0; f < 4; ++f) twin_[4 * t + f] = kNone;
    mesh_.tets[4 * t] = kNone;
    free_slots_.push_back(t);
  }

  std::vector<std::pair<FaceKey, uint32_t>> pending;  // new faces not matched yet, with their codes
  for (size_t i = 0; i < new_tets.size() / 4; ++i) {
    uint32_t t;
    if (free_slots_.empty()) {
      t = slots();
      mesh_.tets.resize(mesh_.tets.size() + 4);
      twin_.resize(twin_.size() + 4, kNone);
      mark_.push_back(0);
      quality_.push_back(0);
    } else {
      t = free_slots_.back();
      free_slots_.pop_back();
    }
    created.push_back(t);
    quality_[t] = std::numeric_limits<double>::quiet_NaN();
    std::copy_n(&new_tets[4 * i], 4, &mesh_.tets[4 * t]);
    for (int k = 0; k < 4; ++k) vertex_tet_[tet(t)[k]] = t;
    for (int f = 0; f < 4; ++f) {
      const uint32_t code = 4 * t + f;
      const FaceKey key = face_key(tet(t), f);
      auto inner = std::find_if(pending.begin(), pending.end(), [&](const auto& p) { return p.first == key; });
      if (inner != pending.end()) {
        link(code, inner->second);
        pending.erase(inner);
        continue;
      }
      auto out = std::find_if(outer.begin(), outer.end(), [&](const Outer& o) { return !o.matched && o.key == key; });
      if (out != outer.end()) {
        out->matched = true;
        link(code, out->twin);
        continue;
      }
      pending.emplace_back(key, code);
    }
  }
  PARTET_ASSERT(pending.empty(), "the new tets of a cavity leave faces unmatched");
  PARTET_ASSERT(std::all_of(outer.begin(), outer.end(), [](const Outer& o) { return o.matched; }),
                "the new tets of a cavity do not cover its outer faces");
}

bool TetTopology::edge_ring(uint32_t t, int i, int j, Ring& ring) const {
  int k = -1, l = -1;
  for (int m = 0; m < 4; ++m) {
    if (m == i || m == j) continue;
    (k < 0 ? k : l) = m;
  }
  if (odd_permutation(i, j, k, l)) std::swap(k, l);
  const uint32_t* v = tet(t);
  ring.a = v[i];
  ring.b = v[j];
  ring.n = 0;
  uint32_t current = t, c = v[k], d = v[l];  // (a, b, c, d) is positive
  do {
    if (ring.n == kMaxRing) return false;
    ring.tets[ring.n] = current;
    ring.vertices[ring.n++] = c;
    // The next tet shares the face (a, b, d): (a, b, d, e) is positive.
    const uint32_t across = twin_[4 * current + local_index(tet(current), c)];
    if (across == kNone) return false;
    current = across / 4;
    c = d;
    d = tet(current)[across % 4];
  } while (current != t);
  return true;
}

double TetTopology::measure(uint32_t t) const {
  const uint32_t* v = tet(t);
  return tet_quality(point(v[0]), point(v[1]), point(v[2]), point(v[3]));
}

void TetTopology::move_vertex(uint32_t v, const double* x) {
  std::copy_n(x, 3, &mesh_.xyz[3 * v]);
  std::vector<uint32_t> star;
  vertex_star(v, star);
  for (uint32_t t : star) quality_[t] = std::numeric_limits<double>::quiet_NaN();
}

void TetTopology::vertex_star(uint32_t v, std::vector<uint32_t>& star) const {
  star.clear();
  const uint32_t first = vertex_tet_[v];
  if (first == kNone) return;
  if (++stamp_ == 0) {
    std::fill(mark_.begin(), mark_.end(), 0);
    stamp_ = 1;
  }
  mark_[first] = stamp_;
  star.push_back(first);
  for (size_t s = 0; s < star.size(); ++s) {
    const uint32_t t = star[s];
    const int lv = local_index(tet(t), v);
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = twin_[4 * t + f];
      if (f == lv || other == kNone || mark_[other / 4] == stamp_) continue;
      mark_[other / 4] = stamp_;
      star.push_back(other / 4);
    }
  }
}

void TetTopology::compact() {
  size_t kept = 0;
  for (uint32_t t = 0; t < slots(); ++t) {
    if (!alive(t)) continue;
    std::copy_n(&mesh_.tets[4 * t], 4, &mesh_.tets[4 * kept]);
    ++kept;
  }
  mesh_.tets.resize(4 * kept);
  twin_.clear();
  vertex_tet_.clear();
  free_slots_.clear();
  mark_.clear();
  quality_.clear();
}

}  // namespace partet
