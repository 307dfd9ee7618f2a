// TetTopology (see tet_topology.hpp). Adjacency is built once, the faces
// matched in slot order through a table of the unmatched ones; replace()
// relinks only the faces of the new tets, matching them among themselves
// and against the cavity's outer faces in a small hash table (a linear search over the faces cost an insertion trial
// as much as smoothing its vertex: 10 % of handle's optimizer).
#include "optimize/tet_topology.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "optimize/tet_kernels.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

using FaceKey = TetTopology::FaceKey;

FaceKey face_key(const uint32_t* tet, int f) {
  FaceKey key;
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != f) key[n++] = tet[k];
  // Three compare-exchanges (std::sort's set-up cost more than the faces).
  if (key[0] > key[1]) std::swap(key[0], key[1]);
  if (key[1] > key[2]) std::swap(key[1], key[2]);
  if (key[0] > key[1]) std::swap(key[0], key[1]);
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
  changed_at_.assign(mesh_.num_vertices(), 0);
  mark_.assign(n, 0);
  measures_.assign(n, {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()});
  for (uint32_t t = 0; t < n; ++t)
    if (alive(t))
      for (int k = 0; k < 4; ++k) vertex_tet_[tet(t)[k]] = t;
  link_faces();
  on_boundary_.assign(mesh_.num_vertices(), 0);
  for (uint32_t code = 0; code < twin_.size(); ++code) {
    if (twin_[code] != kNone || !alive(code / 4)) continue;
    for (int k = 0; k < 4; ++k)
      if (k != static_cast<int>(code % 4)) on_boundary_[tet(code / 4)[k]] = 1;
  }
}

void TetTopology::link_faces() {
  // The faces not yet matched, in an open-addressing table (linear
  // probing, at most half full) that a face leaves when its twin comes:
  // the tets go in slot order, which follows space (tet_order.hpp), so
  // the table holds the frontier of that order and its lookups stay nearer
  // in cache than the tets of every vertex, gathered and sorted (16 bytes
  // per tet), which missed it on every vertex's star. The faces on three
  // surface vertices are set aside and matched after, sorted: the surface
  // triangles among them never find a twin and only grew the table
  // (femur r2: 124,768 triangles; link_faces 0.43 -> 0.34 s, 0.28 s with
  // the prefetches below).
  std::vector<uint8_t> on_surface(mesh_.num_vertices(), 0);
  for (uint32_t v : mesh_.tris) on_surface[v] = 1;
  struct Aside {
    FaceKey key;
    uint32_t code;
  };
  std::vector<Aside> aside;
  struct Open {
    FaceKey key;
    uint32_t code;
  };
  size_t capacity = 1024;
  std::vector<Open> table(capacity, Open{{kNone, 0, 0}, 0});
  size_t used = 0;
  const auto home = [&](const FaceKey& key) { return hash_triple(key[0], key[1], key[2]) & (capacity - 1); };
  // Whether tet code / 4 lies on the positive side of face code % 4 taken
  // in ascending vertex order (its corners in ascending local order have
  // the tet's own orientation with corner f last for odd f, the opposite
  // one for even f; sorting them by vertex flips it per inversion). Twins
  // of a valid mesh lie on opposite sides.
  const auto outward_sorted = [&](uint32_t code) {
    const uint32_t* v = tet(code / 4);
    const int f = static_cast<int>(code % 4);
    int order[3], m = 0;
    for (int k = 0; k < 4; ++k)
      if (k != f) order[m++] = k;
    const int inversions = (v[order[0]] > v[order[1]]) + (v[order[1]] > v[order[2]]) + (v[order[0]] > v[order[2]]);
    return (inversions % 2 == 1) == (f % 2 == 0);
  };
  // The faces go in chunks of kChunk tets: their keys and hashes first,
  // each home slot prefetched, then matched in order, so that the chunk's
  // table misses overlap instead of coming one after the other.
  constexpr uint32_t kChunk = 16;
  FaceKey keys[4 * kChunk];
  uint64_t hashes[4 * kChunk];
  uint32_t codes[4 * kChunk];
  for (uint32_t first = 0; first < slots(); first += kChunk) {
    const uint32_t last = std::min(slots(), first + kChunk);
    uint32_t m = 0;
    for (uint32_t t = first; t < last; ++t) {
      if (!alive(t)) continue;
      for (int f = 0; f < 4; ++f) {
        const uint32_t code = 4 * t + static_cast<uint32_t>(f);
        const FaceKey key = face_key(tet(t), f);
        if (on_surface[key[0]] && on_surface[key[1]] && on_surface[key[2]]) {
          aside.push_back({key, code});
          continue;
        }
        keys[m] = key;
        hashes[m] = hash_triple(key[0], key[1], key[2]);
        codes[m] = code;
        __builtin_prefetch(&table[hashes[m] & (capacity - 1)]);
        ++m;
      }
    }
    for (uint32_t i = 0; i < m; ++i) {
      const FaceKey& key = keys[i];
      const uint32_t code = codes[i];
      size_t s = hashes[i] & (capacity - 1);
      const auto same = [&](const FaceKey& other) {
        return other[0] == key[0] && other[1] == key[1] && other[2] == key[2];
      };
      while (table[s].key[0] != kNone && !same(table[s].key)) s = (s + 1) & (capacity - 1);
      if (table[s].key[0] == kNone) {
        table[s] = {key, code};
        if (2 * ++used > capacity) {
          std::vector<Open> old(2 * capacity, Open{{kNone, 0, 0}, 0});
          old.swap(table);
          capacity *= 2;
          for (const Open& e : old) {
            if (e.key[0] == kNone) continue;
            size_t j = home(e.key);
            while (table[j].key[0] != kNone) j = (j + 1) & (capacity - 1);
            table[j] = e;
          }
        }
        continue;
      }
      PARTET_ASSERT(outward_sorted(code) != outward_sorted(table[s].code),
                    "two tets of the mesh to optimize lie on the same side of a face");
      link(code, table[s].code);
      // Backward-shift deletion: the entries after s that probed past it
      // move back, so no lookup needs a tombstone.
      size_t hole = s;
      for (size_t j = (s + 1) & (capacity - 1); table[j].key[0] != kNone; j = (j + 1) & (capacity - 1))
        if (((j - home(table[j].key)) & (capacity - 1)) >= ((j - hole) & (capacity - 1))) {
          table[hole] = table[j];
          hole = j;
        }
      table[hole].key[0] = kNone;
      --used;
    }
  }
  std::sort(aside.begin(), aside.end(), [](const Aside& x, const Aside& y) { return x.key < y.key; });
  for (size_t i = 0; i + 1 < aside.size(); ++i) {
    if (aside[i].key != aside[i + 1].key) continue;
    PARTET_ASSERT(outward_sorted(aside[i].code) != outward_sorted(aside[i + 1].code),
                  "two tets of the mesh to optimize lie on the same side of a face");
    link(aside[i].code, aside[i + 1].code);
    ++i;
  }
}

uint32_t TetTopology::add_vertex(const double* p, uint64_t global_id) {
  const uint32_t v = static_cast<uint32_t>(num_vertices());
  PARTET_ASSERT(v < kNone, "too many vertices");
  mesh_.xyz.insert(mesh_.xyz.end(), p, p + 3);
  if (!mesh_.global_ids.empty()) mesh_.global_ids.push_back(global_id);
  vertex_tet_.push_back(kNone);
  on_boundary_.push_back(0);
  changed_at_.push_back(0);
  return v;
}

void TetTopology::remove_last_vertex() {
  PARTET_ASSERT(vertex_tet_.back() == kNone, "removing a vertex that tets still have");
  mesh_.xyz.resize(mesh_.xyz.size() - 3);
  if (!mesh_.global_ids.empty()) mesh_.global_ids.pop_back();
  vertex_tet_.pop_back();
  on_boundary_.pop_back();
  changed_at_.pop_back();
}

void TetTopology::place_vertex(uint32_t v, const double* x) {
  PARTET_ASSERT(vertex_tet_[v] == kNone, "placing a vertex that tets have");
  std::copy_n(x, 3, &mesh_.xyz[3 * size_t{v}]);
}

uint32_t TetTopology::FaceMatch::hash(const FaceKey& key) {
  return static_cast<uint32_t>(hash_triple(key[0], key[1], key[2]));
}

TetTopology::FaceMatch* TetTopology::find_match(const FaceKey& key) {
  const size_t mask = matches_.size() - 1;
  for (size_t i = FaceMatch::hash(key) & mask;; i = (i + 1) & mask) {
    FaceMatch& m = matches_[i];
    if (m.state == FaceMatch::kFree) {
      m.key = key;
      return &m;
    }
    if (m.key == key) return &m;
  }
}

void TetTopology::replace(std::span<const uint32_t> old_tets, std::span<const uint32_t> new_tets,
                          std::vector<uint32_t>& created) {
  // Every face to match goes into a small open-addressing table keyed by
  // its sorted vertices: first the cavity's outer faces (with the face
  // behind each), then the new tets' faces, each closing an outer face or
  // waiting for its partner among the new tets.
  size_t capacity = 32;
  while (capacity < 2 * (4 * old_tets.size() + new_tets.size())) capacity *= 2;  // at most half full
  matches_.assign(capacity, FaceMatch{});
  const uint32_t stamp = next_stamp();
  const uint32_t change = next_change();
  for (uint32_t t : old_tets) {
    PARTET_ASSERT(alive(t), "replacing a dead tet");
    mark_[t] = stamp;
    for (int k = 0; k < 4; ++k) changed_at_[tet(t)[k]] = change;
  }
  for (uint32_t v : new_tets) changed_at_[v] = change;
  size_t open = 0;  // faces waiting: outer ones not closed, new ones without a partner
  for (uint32_t t : old_tets) {
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = twin_[4 * t + f];
      if (other != kNone && mark_[other / 4] == stamp) continue;
      FaceMatch* m = find_match(face_key(tet(t), f));
      PARTET_ASSERT(m->state == FaceMatch::kFree, "a cavity's outer face appears twice");
      m->state = FaceMatch::kOuter;
      m->code = other;
      ++open;
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

  for (size_t i = 0; i < new_tets.size() / 4; ++i) {
    uint32_t t;
    if (free_slots_.empty()) {
      t = slots();
      mesh_.tets.resize(mesh_.tets.size() + 4);
      twin_.resize(twin_.size() + 4, kNone);
      mark_.push_back(0);
      measures_.push_back({0, 0});
    } else {
      t = free_slots_.back();
      free_slots_.pop_back();
    }
    created.push_back(t);
    if (change_log_) change_log_->push_back(t);
    forget_measures(t);
    std::copy_n(&new_tets[4 * i], 4, &mesh_.tets[4 * t]);
    for (int k = 0; k < 4; ++k) vertex_tet_[tet(t)[k]] = t;
    for (int f = 0; f < 4; ++f) {
      const uint32_t code = 4 * t + f;
      FaceMatch* m = find_match(face_key(tet(t), f));
      PARTET_ASSERT(m->state != FaceMatch::kClosed, "the new tets of a cavity have a face three times");
      if (m->state == FaceMatch::kFree) {
        m->state = FaceMatch::kWaiting;
        m->code = code;
        ++open;
        continue;
      }
      link(code, m->code);
      m->state = FaceMatch::kClosed;
      --open;
    }
  }
  PARTET_ASSERT(open == 0, "the new tets of a cavity leave faces unmatched or do not cover its outer faces");
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

void TetTopology::forget_measures(uint32_t t) {
  measures_[t] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
}

double TetTopology::measure_radius_ratio(uint32_t t) const { return radius_ratio_of(*this, tet(t)); }

double TetTopology::measure(uint32_t t) const {
  const uint32_t* v = tet(t);
  return tet_quality(point(v[0]), point(v[1]), point(v[2]), point(v[3]));
}

void TetTopology::measure_qualities() {
  constexpr size_t kBlock = 256;
  std::vector<double> columns(12 * kBlock), out(kBlock);
  std::vector<uint32_t> block;
  block.reserve(kBlock);
  const auto flush = [&] {
    tet_qualities(column_view(columns.data(), kBlock), block.size(), out.data());
    for (size_t k = 0; k < block.size(); ++k) measures_[block[k]].quality = out[k];
    block.clear();
  };
  for (uint32_t t = 0; t < slots(); ++t) {
    if (!alive(t) || !std::isnan(measures_[t].quality)) continue;
    const size_t k = block.size();
    for (int j = 0; j < 4; ++j) {
      const double* x = point(tet(t)[j]);
      for (int i = 0; i < 3; ++i) columns[static_cast<size_t>(3 * j + i) * kBlock + k] = x[i];
    }
    block.push_back(t);
    if (block.size() == kBlock) flush();
  }
  flush();
}

void TetTopology::move_vertex(uint32_t v, const double* x) {
  vertex_star(v, moved_star_);
  move_vertex(v, x, moved_star_);
}

void TetTopology::move_vertex(uint32_t v, const double* x, std::span<const uint32_t> star) {
  std::copy_n(x, 3, &mesh_.xyz[3 * v]);
  const uint32_t change = next_change();
  for (uint32_t t : star) {
    forget_measures(t);
    for (int k = 0; k < 4; ++k) changed_at_[tet(t)[k]] = change;
  }
  if (change_log_) change_log_->insert(change_log_->end(), star.begin(), star.end());
}

uint32_t TetTopology::next_stamp() const {
  if (++stamp_ == 0) {
    std::fill(mark_.begin(), mark_.end(), 0);
    stamp_ = 1;
  }
  return stamp_;
}

void TetTopology::vertex_star(uint32_t v, std::vector<uint32_t>& star) const {
  star.clear();
  const uint32_t first = vertex_tet_[v];
  if (first == kNone) return;
  const uint32_t stamp = next_stamp();
  mark_[first] = stamp;
  star.push_back(first);
  for (size_t s = 0; s < star.size(); ++s) {
    const uint32_t t = star[s];
    const int lv = local_index(tet(t), v);
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = twin_[4 * t + f];
      if (f == lv || other == kNone || mark_[other / 4] == stamp) continue;
      mark_[other / 4] = stamp;
      star.push_back(other / 4);
    }
  }
}

void TetTopology::star_neighbours(uint32_t v, std::span<const uint32_t> star, std::vector<uint32_t>& out) const {
  out.clear();
  if (vertex_mark_.size() < num_vertices()) vertex_mark_.resize(num_vertices(), 0);
  if (++vertex_stamp_ == 0) {
    std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
    vertex_stamp_ = 1;
  }
  for (uint32_t t : star)
    for (int k = 0; k < 4; ++k) {
      const uint32_t u = tet(t)[k];
      if (u == v || vertex_mark_[u] == vertex_stamp_) continue;
      vertex_mark_[u] = vertex_stamp_;
      out.push_back(u);
    }
  std::sort(out.begin(), out.end());
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
  measures_.clear();
}

}  // namespace partet
