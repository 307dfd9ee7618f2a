// The live front: construction from the initial front, the hashes and the
// leaf index kept in step with every applied tet (see front.hpp).
#include "front/front.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "octree/box_triangle.hpp"

namespace partet {

namespace {

uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t{a} << 32) | b;
}

// The largest float not above x, the smallest not below it.
float float_below(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -HUGE_VALF) : f;
}

float float_above(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, HUGE_VALF) : f;
}

}  // namespace

uint64_t Front::EdgeTraits::hash(uint64_t k) { return hash_mix(k); }

Front::Front(const InitialFront& initial, const LinearOctree& tree, const RootCube& root)
    : tree_(&tree),
      root_(root),
      query_(tree),
      xyz_(initial.xyz),
      global_ids_(initial.global_ids),
      vertex_leaf_(initial.vertex_leaf),
      vertex_uses_(initial.vertex_leaf.size(), 0),
      free_(initial.vertex_leaf.size(), 0),
      vertex_prev_(initial.vertex_leaf.size(), kNoIndex),
      vertex_next_(initial.vertex_leaf.size(), kNoIndex),
      leaf_vertex_head_(tree.size(), kNoIndex),
      listed_(tree.size()),
      leaf_entry_head_(tree.size(), kNoIndex),
      leaf_changed_(tree.size(), 0) {
  PARTET_ASSERT(initial.xyz.size() == 3 * initial.vertex_leaf.size(), "initial front vertex arrays disagree");
  PARTET_ASSERT(initial.vertex_leaf.size() < kNoIndex, "too many front vertices");
  for (uint32_t leaf : vertex_leaf_) PARTET_ASSERT(leaf < tree.size(), "front vertex leaf out of range");
  const size_t n = initial.num_faces();
  faces_.reserve(3 * n);
  alive_.reserve(n);
  // A closed front has 3/2 edges per face; both tables shrink from here.
  face_of_triple_.reserve(n);
  edge_faces_.reserve(n + n / 2);
  for (size_t f = 0; f < n; ++f) {
    const uint32_t* t = &initial.faces[3 * f];
    PARTET_ASSERT(find_face(t[0], t[1], t[2]) == kNoIndex, "initial front has two faces on one vertex triple");
    add_face(t[0], t[1], t[2]);
  }
  // Free vertices: listed with one use that the first face using them takes.
  PARTET_ASSERT(initial.free_vertices <= vertex_leaf_.size(), "more free vertices than vertices");
  for (size_t v = vertex_leaf_.size() - initial.free_vertices; v < vertex_leaf_.size(); ++v) {
    PARTET_ASSERT(vertex_uses_[v] == 0, "a free vertex is used by a face of the initial front");
    use_vertex(static_cast<uint32_t>(v));
    free_[v] = 1;
  }
  free_count_ = initial.free_vertices;
}

uint32_t Front::find_face(uint32_t a, uint32_t b, uint32_t c) const {
  const uint32_t* f = face_of_triple_.find(sorted_triple(a, b, c));
  return f ? *f : kNoIndex;
}

const Front::EdgeFaces* Front::find_edge(uint32_t a, uint32_t b) const { return edge_faces_.find(edge_key(a, b)); }

uint32_t Front::edge_uses(uint32_t a, uint32_t b) const {
  const EdgeFaces* edge = find_edge(a, b);
  return edge ? edge->uses : 0;
}

void Front::change_edge(uint32_t a, uint32_t b, uint32_t f, int delta) {
  const uint64_t key = edge_key(a, b);
  if (delta > 0) {
    EdgeFaces& edge = edge_faces_.get_or_insert(key, EdgeFaces{});
    ++edge.uses;
    edge.faces_xor ^= f;
    return;
  }
  EdgeFaces* edge = edge_faces_.find(key);
  PARTET_ASSERT(edge && edge->uses > 0, "front edge count underflow");
  edge->faces_xor ^= f;
  if (--edge->uses == 0) edge_faces_.erase(key);
}

void Front::use_vertex(uint32_t v) {
  if (free_[v]) {  // its first face takes over the free vertex's use
    free_[v] = 0;
    --free_count_;
    return;
  }
  if (vertex_uses_[v]++ > 0) return;
  const uint32_t leaf = vertex_leaf_[v];
  vertex_prev_[v] = kNoIndex;
  vertex_next_[v] = leaf_vertex_head_[leaf];
  if (vertex_next_[v] != kNoIndex) vertex_prev_[vertex_next_[v]] = v;
  leaf_vertex_head_[leaf] = v;
  listed_.insert(leaf);
  leaf_changed_[leaf] = changes_;
}

void Front::release_vertex(uint32_t v, std::vector<uint32_t>& shrunk) {
  PARTET_ASSERT(vertex_uses_[v] > 0, "front vertex use count underflow");
  if (--vertex_uses_[v] > 0) return;
  const uint32_t leaf = vertex_leaf_[v];
  if (vertex_prev_[v] != kNoIndex)
    vertex_next_[vertex_prev_[v]] = vertex_next_[v];
  else
    leaf_vertex_head_[leaf] = vertex_next_[v];
  if (vertex_next_[v] != kNoIndex) vertex_prev_[vertex_next_[v]] = vertex_prev_[v];
  vertex_prev_[v] = vertex_next_[v] = kNoIndex;
  leaf_changed_[leaf] = changes_;
  shrunk.push_back(leaf);
}

uint32_t Front::add_face(uint32_t a, uint32_t b, uint32_t c, const LeafCover* cover) {
  PARTET_ASSERT(faces_.size() / 3 < kNoIndex - 1, "too many front faces");
  const uint32_t f = static_cast<uint32_t>(alive_.size());
  faces_.insert(faces_.end(), {a, b, c});
  alive_.push_back(1);
  face_first_entry_.push_back(kNoIndex);
  ++alive_count_;
  face_of_triple_.get_or_insert(sorted_triple(a, b, c), f);
  change_edge(a, b, f, 1);
  change_edge(b, c, f, 1);
  change_edge(c, a, f, 1);
  use_vertex(a);
  use_vertex(b);
  use_vertex(c);
  list_face(f, true, cover);
  return f;
}

void Front::list_face(uint32_t f, bool stamp, const LeafCover* cover) {
  const uint32_t a = faces_[3 * size_t{f}], b = faces_[3 * size_t{f} + 1], c = faces_[3 * size_t{f} + 2];
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({point(a)[k], point(b)[k], point(c)[k]});
    hi[k] = std::max({point(a)[k], point(b)[k], point(c)[k]});
  }
  if (face_box_.size() < 6 * (size_t{f} + 1)) face_box_.resize(6 * (size_t{f} + 1));
  for (int k = 0; k < 3; ++k) {
    face_box_[6 * size_t{f} + k] = float_below(lo[k]);
    face_box_[6 * size_t{f} + 3 + k] = float_above(hi[k]);
  }
  uint32_t glo[3], ghi[3];
  grid_range(root_, lo, hi, glo, ghi);
  if (cover)
    leaves_in_cover(*cover, glo, ghi, leaves_scratch_);
  else
    query_.leaves_in_range(glo, ghi, leaves_scratch_);
  double root_hi[3];
  for (int k = 0; k < 3; ++k) root_hi[k] = root_.origin[k] + root_.edge();
  const TriangleBoxTest triangle(point(a), point(b), point(c));
  for (size_t leaf : leaves_scratch_) {
    const bool vertex_leaf = leaf == vertex_leaf_[a] || leaf == vertex_leaf_[b] || leaf == vertex_leaf_[c];
    if (!vertex_leaf) {
      double leaf_lo[3], leaf_hi[3];
      query_.leaf_box(root_, leaf, leaf_lo, leaf_hi);
      const bool open[3] = {!closed_lists_ && leaf_hi[0] < root_hi[0], !closed_lists_ && leaf_hi[1] < root_hi[1],
                            !closed_lists_ && leaf_hi[2] < root_hi[2]};
      if (!triangle.meets_half_open(leaf_lo, leaf_hi, open)) continue;
    }
    uint32_t e;
    if (free_entry_ != kNoIndex) {
      e = free_entry_;
      free_entry_ = entry_next_[e];
    } else {
      PARTET_ASSERT(entry_face_.size() < kNoIndex - 1, "too many front face entries");
      e = static_cast<uint32_t>(entry_face_.size());
      entry_face_.push_back(0);
      entry_leaf_.push_back(0);
      entry_prev_.push_back(0);
      entry_next_.push_back(0);
      entry_chain_.push_back(0);
    }
    entry_face_[e] = f;
    entry_leaf_[e] = static_cast<uint32_t>(leaf);
    entry_prev_[e] = kNoIndex;
    entry_next_[e] = leaf_entry_head_[leaf];
    if (entry_next_[e] != kNoIndex) entry_prev_[entry_next_[e]] = e;
    leaf_entry_head_[leaf] = e;
    listed_.insert(leaf);
    entry_chain_[e] = face_first_entry_[f];
    face_first_entry_[f] = e;
    if (stamp) leaf_changed_[leaf] = changes_;
  }
}

void Front::close_face(uint32_t f, std::vector<uint32_t>& shrunk) {
  PARTET_ASSERT(alive_[f], "closing a closed front face");
  const uint32_t a = faces_[3 * size_t{f}], b = faces_[3 * size_t{f} + 1], c = faces_[3 * size_t{f} + 2];
  alive_[f] = 0;
  --alive_count_;
  face_of_triple_.erase(sorted_triple(a, b, c));
  change_edge(a, b, f, -1);
  change_edge(b, c, f, -1);
  change_edge(c, a, f, -1);
  uint32_t e = face_first_entry_[f];
  while (e != kNoIndex) {
    const uint32_t leaf = entry_leaf_[e];
    if (entry_prev_[e] != kNoIndex)
      entry_next_[entry_prev_[e]] = entry_next_[e];
    else
      leaf_entry_head_[leaf] = entry_next_[e];
    if (entry_next_[e] != kNoIndex) entry_prev_[entry_next_[e]] = entry_prev_[e];
    leaf_changed_[leaf] = changes_;
    shrunk.push_back(leaf);
    const uint32_t next = entry_chain_[e];
    entry_next_[e] = free_entry_;
    free_entry_ = e;
    e = next;
  }
  face_first_entry_[f] = kNoIndex;
  release_vertex(a, shrunk);
  release_vertex(b, shrunk);
  release_vertex(c, shrunk);
}

uint32_t Front::add_vertex(const double* p, uint64_t global_id) {
  PARTET_ASSERT(vertex_leaf_.size() < kNoIndex - 1, "too many front vertices");
  const uint32_t v = static_cast<uint32_t>(vertex_leaf_.size());
  xyz_.insert(xyz_.end(), p, p + 3);
  global_ids_.push_back(global_id);
  vertex_leaf_.push_back(leaf_of_point(*tree_, root_, p));
  vertex_uses_.push_back(0);
  free_.push_back(0);
  vertex_prev_.push_back(kNoIndex);
  vertex_next_.push_back(kNoIndex);
  return v;
}

size_t Front::drop_free_vertices(std::vector<uint32_t>& shrunk) {
  const size_t dropped = free_count_;
  for (uint32_t v = 0; v < free_.size() && free_count_ > 0; ++v) {
    if (!free_[v]) continue;
    free_[v] = 0;
    --free_count_;
    release_vertex(v, shrunk);
  }
  return dropped;
}

void Front::remove_last_vertex() {
  PARTET_ASSERT(!vertex_leaf_.empty() && vertex_uses_.back() == 0, "removing a used front vertex");
  xyz_.resize(xyz_.size() - 3);
  global_ids_.pop_back();
  vertex_leaf_.pop_back();
  vertex_uses_.pop_back();
  free_.pop_back();
  vertex_prev_.pop_back();
  vertex_next_.pop_back();
}

int Front::apply_tet(uint32_t f, uint32_t p, std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk,
                     const LeafCover* cover) {
  PARTET_ASSERT(f < alive_.size() && alive_[f], "tet on a closed front face");
  ++changes_;
  const uint32_t a = faces_[3 * size_t{f}], b = faces_[3 * size_t{f} + 1], c = faces_[3 * size_t{f} + 2];
  // Add before closing, so that vertices kept by the new faces never leave
  // their leaf's list.
  const uint32_t sides[3][3] = {{b, c, p}, {a, p, c}, {a, b, p}};
  uint32_t twins[3];
  int closed = 0;
  for (int s = 0; s < 3; ++s) {
    twins[s] = find_face(sides[s][0], sides[s][1], sides[s][2]);
    if (twins[s] == kNoIndex) added.push_back(add_face(sides[s][0], sides[s][1], sides[s][2], cover));
  }
  close_face(f, shrunk);
  for (int s = 0; s < 3; ++s)
    if (twins[s] != kNoIndex) {
      close_face(twins[s], shrunk);
      ++closed;
    }
  return closed;
}

void Front::remove_tet(const uint32_t tet[4], std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk) {
  ++changes_;
  const uint32_t a = tet[0], b = tet[1], c = tet[2], d = tet[3];
  // Into the tet: (a, b, c) faces d; the others are the reverses of the
  // outward faces (b, c, d), (a, d, c), (a, b, d).
  const uint32_t sides[4][3] = {{a, b, c}, {b, d, c}, {a, c, d}, {a, d, b}};
  uint32_t twins[4];
  for (int s = 0; s < 4; ++s) {
    twins[s] = find_face(sides[s][0], sides[s][1], sides[s][2]);
    if (twins[s] == kNoIndex) added.push_back(add_face(sides[s][0], sides[s][1], sides[s][2]));
  }
  for (uint32_t twin : twins)
    if (twin != kNoIndex) close_face(twin, shrunk);
}

Front::Snapshot Front::snapshot() const {
  Snapshot s;
  s.slots = alive_.size();
  for (uint32_t f = 0; f < alive_.size(); ++f)
    if (alive_[f]) s.alive_faces.push_back(f);
  for (uint32_t v = 0; v < free_.size(); ++v)
    if (free_[v]) s.free_vertices.push_back(v);
  return s;
}

Front::Changes Front::changes_since(const Snapshot& then) const {
  PARTET_ASSERT(then.slots <= alive_.size(), "changes since more face slots than the front has");
  Changes c;
  for (uint32_t f : then.alive_faces)
    if (!alive_[f]) c.closed.insert(c.closed.end(), &faces_[3 * size_t{f}], &faces_[3 * size_t{f}] + 3);
  for (size_t f = then.slots; f < alive_.size(); ++f)
    if (alive_[f]) c.added.insert(c.added.end(), &faces_[3 * f], &faces_[3 * f] + 3);
  for (uint32_t v : then.free_vertices)
    if (!free_[v]) c.taken.push_back(v);
  return c;
}

void Front::merge(const Changes& changes, std::vector<uint32_t>& shrunk) {
  ++changes_;
  for (size_t i = 0; i + 3 <= changes.closed.size(); i += 3) {
    const uint32_t f = find_face(changes.closed[i], changes.closed[i + 1], changes.closed[i + 2]);
    PARTET_ASSERT(f != kNoIndex, "a merged front closes a face not alive here");
    close_face(f, shrunk);
  }
  for (size_t i = 0; i + 3 <= changes.added.size(); i += 3) {
    const uint32_t* t = &changes.added[i];
    PARTET_ASSERT(find_face(t[0], t[1], t[2]) == kNoIndex, "a merged front adds a face alive here");
    add_face(t[0], t[1], t[2]);
  }
  for (uint32_t v : changes.taken) {
    PARTET_ASSERT(v < free_.size(), "a merged front takes a vertex this front lacks");
    if (!free_[v]) continue;  // a face added above took it over
    free_[v] = 0;
    --free_count_;
    release_vertex(v, shrunk);
  }
}

std::vector<uint32_t> Front::compact() {
  std::vector<uint32_t> new_face(alive_.size(), kNoIndex);
  uint32_t n = 0;
  for (uint32_t f = 0; f < alive_.size(); ++f)
    if (alive_[f]) new_face[f] = n++;
  std::vector<uint32_t> faces(3 * size_t{n});
  for (uint32_t f = 0; f < alive_.size(); ++f)
    if (new_face[f] != kNoIndex) std::copy_n(&faces_[3 * size_t{f}], 3, &faces[3 * size_t{new_face[f]}]);
  faces_.swap(faces);
  face_box_.assign(6 * size_t{n}, 0.0f);
  face_box_.shrink_to_fit();
  alive_.assign(n, 1);
  alive_.shrink_to_fit();
  // The leaf lists again, closed from now on, in face order: a list holds
  // the newest face first, as it did.
  for (std::vector<uint32_t>* v : {&entry_face_, &entry_leaf_, &entry_prev_, &entry_next_, &entry_chain_}) *v = {};
  std::fill(leaf_entry_head_.begin(), leaf_entry_head_.end(), kNoIndex);
  free_entry_ = kNoIndex;
  face_first_entry_.assign(n, kNoIndex);
  face_first_entry_.shrink_to_fit();
  closed_lists_ = true;
  for (uint32_t f = 0; f < n; ++f) list_face(f, false);

  face_of_triple_ = {};
  edge_faces_ = {};
  face_of_triple_.reserve(n);
  edge_faces_.reserve(n + n / 2);
  for (uint32_t f = 0; f < n; ++f) {
    const uint32_t* t = &faces_[3 * size_t{f}];
    face_of_triple_.get_or_insert(sorted_triple(t[0], t[1], t[2]), f);
    change_edge(t[0], t[1], f, 1);
    change_edge(t[1], t[2], f, 1);
    change_edge(t[2], t[0], f, 1);
  }
  return new_face;
}

}  // namespace partet

