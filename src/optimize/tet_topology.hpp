// A tet mesh opened for local changes: the tets of a TetMesh with free
// slots, face adjacency and one incident tet per vertex. Face code 4*t + f
// names the face of tet t opposite its local vertex f; twin(code) is the code
// of the same face in the neighbouring tet, or kNone on the boundary (a face
// of exactly one tet).
//
// The only change is replace(): a set of tets (a cavity) is swapped for new
// tets whose outer faces are exactly the cavity's outer faces, so the
// boundary, and the faces shared with the rest of the mesh, never change.
// Callers check orientation (exactly) before replacing; replace() checks the
// face matching and throws InternalError when it does not close.
//
// Contract: the mesh is valid (positive tets, each face in at most two tets).
// Vertex coordinates stay in the TetMesh (smoothing moves them there);
// compact() writes the tets back without free slots, in slot order, and
// leaves the topology empty.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/tet_edges.hpp"

namespace partet {

class TetTopology {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;
  using FaceKey = std::array<uint32_t, 3>;  // a face's vertices, ascending
  // Longest edge ring edge_ring() walks (and the largest polygon of a
  // multi-face removal). 10, not 7: a flat tet on two coplanar input
  // triangles can have its only interior edge in a ring of 8 or more, and
  // with no flip or insertion left it stayed at 1e-15 degrees (helmet r1,
  // --quality-target 32 or 35).
  static constexpr int kMaxRing = 10;

  explicit TetTopology(TetMesh& mesh);

  uint32_t slots() const { return static_cast<uint32_t>(mesh_.tets.size() / 4); }
  bool alive(uint32_t t) const { return mesh_.tets[4 * t] != kNone; }
  const uint32_t* tet(uint32_t t) const { return &mesh_.tets[4 * t]; }
  uint32_t twin(uint32_t code) const { return twin_[code]; }
  const double* point(uint32_t v) const { return &mesh_.xyz[3 * v]; }
  // Moves vertex v to x (the caller checks its tets stay positive).
  void move_vertex(uint32_t v, const double* x);
  // The same with v's star as vertex_star gives it, which the caller holds
  // (smoothing has just walked it): the walk is not done again.
  void move_vertex(uint32_t v, const double* x, std::span<const uint32_t> star);
  // tet_quality of alive tet t, kept per slot until the tet is replaced or
  // one of its vertices moves (half the optimizer's quality evaluations
  // were of tets it had measured before).
  double quality(uint32_t t) const {
    if (std::isnan(measures_[t].quality)) measures_[t].quality = measure(t);
    return measures_[t].quality;
  }
  // tet_radius_ratio of alive tet t, kept the same way (the mean, the
  // needles and the relaxation's tets are sought over the whole mesh four
  // times, 3 % of a run computed afresh each time).
  double radius_ratio(uint32_t t) const {
    if (std::isnan(measures_[t].radius_ratio)) measures_[t].radius_ratio = measure_radius_ratio(t);
    return measures_[t].radius_ratio;
  }
  // Set the kept measures of alive tet t to values the caller computed
  // from t's current points, in t's vertex order, with tet_quality and
  // tet_radius_ratio (so they are what quality and radius_ratio would
  // compute): after a move_vertex whose trial already measured the star.
  void keep_measures(uint32_t t, double quality, double radius_ratio) { measures_[t] = {quality, radius_ratio}; }
  void keep_quality(uint32_t t, double quality) { measures_[t].quality = quality; }
  // Measures the quality of every alive tet not yet measured, in blocks
  // (tet_kernels.hpp): what quality(t) would compute, for a caller about
  // to read them all (the first topology pass reads every slot's).
  void measure_qualities();
  size_t num_vertices() const { return mesh_.num_vertices(); }

  // Appends a vertex at p (no tet has it yet; with global ids, `global_id`
  // is its id); remove_last_vertex() drops it again once no tet has it,
  // and place_vertex() puts it at x while no tet has it.
  uint32_t add_vertex(const double* p, uint64_t global_id);
  void remove_last_vertex();
  void place_vertex(uint32_t v, const double* x);

  // Per vertex: 1 when on a boundary face (a face of exactly one tet, so
  // its link is not closed), else 0. Fixed for the topology's life:
  // replace() keeps a cavity's outer faces, so the boundary faces never
  // change, and added vertices are interior.
  const std::vector<uint8_t>& boundary_vertices() const { return on_boundary_; }
  bool on_boundary(uint32_t v) const { return on_boundary_[v] != 0; }

  // Replaces the alive, distinct tets `old_tets` by `new_tets` (4 vertex
  // indices each); the slots of the new tets are appended to `created`.
  // New tet i takes the slot of old tet i (then free slots, last freed
  // first, then new ones), so replacing m >= n tets by n and then the
  // created tets by the n old ones puts every old tet back in its slot.
  void replace(std::span<const uint32_t> old_tets, std::span<const uint32_t> new_tets,
               std::vector<uint32_t>& created);

  // The tets around the edge (v[i], v[j]) of tet t, when they close a ring
  // of at most kMaxRing tets: a = v[i], b = v[j], ring vertices r_0..r_{n-1}
  // and tets[k] = (a, b, r_k, r_{k+1 mod n}) as a positive tet. False for a
  // boundary edge or a longer ring.
  struct Ring {
    uint32_t a = 0, b = 0;
    int n = 0;
    uint32_t vertices[kMaxRing];
    uint32_t tets[kMaxRing];
  };
  bool edge_ring(uint32_t t, int i, int j, Ring& ring) const;

  // The tets having vertex v, appended to `star` (cleared first) in a
  // deterministic breadth-first order from v's incident tet.
  void vertex_star(uint32_t v, std::vector<uint32_t>& star) const;
  // The vertices other than v of the tets in `star` (v's star), each once,
  // ascending, in `out` (cleared first).
  void star_neighbours(uint32_t v, std::span<const uint32_t> star, std::vector<uint32_t>& out) const;
  // The vertex quadruples of the tets in `slots`, in order (cleared first).
  void tet_vertices(std::span<const uint32_t> slots, std::vector<uint32_t>& quads) const {
    quads.clear();
    for (uint32_t t : slots) quads.insert(quads.end(), tet(t), tet(t) + 4);
  }

  // While `log` is set (null: none), replace() appends the slots it fills
  // and move_vertex() the slots of the moved vertex's star: every tet whose
  // quality may have changed since, trials that were undone included.
  void log_changes(std::vector<uint32_t>* log) { change_log_ = log; }

  // Change marks. Every replace() and move_vertex() is a change, counted
  // from 1; each vertex keeps the count of the last change to its star (a
  // tet having it replaced, or a vertex of such a tet moved). A local
  // operation on tet t that reads only the stars of t's vertices (a flip
  // search) and failed at count c fails again while unchanged_since(t, c):
  // the same decisions on the same tets and points. The count saturates at
  // UINT32_MAX; then nothing is unchanged.
  uint32_t changes() const { return changes_; }
  bool unchanged_since(uint32_t t, uint32_t count) const {
    if (count == UINT32_MAX) return false;
    for (int k = 0; k < 4; ++k)
      if (changed_at_[tet(t)[k]] > count) return false;
    return true;
  }
  // The same for an operation that reads only vertex v's star.
  bool vertex_unchanged_since(uint32_t v, uint32_t count) const {
    return count != UINT32_MAX && changed_at_[v] <= count;
  }
  // Writes the alive tets back to the mesh's tet array, in slot order.
  void compact();

 private:
  // Links every face to its twin (the constructor's).
  void link_faces();
  void link(uint32_t code, uint32_t other) {
    twin_[code] = other;
    if (other != kNone) twin_[other] = code;
  }

  TetMesh& mesh_;
  std::vector<uint32_t> twin_;         // per face code
  std::vector<uint32_t> vertex_tet_;   // an alive tet having the vertex, or kNone
  std::vector<uint8_t> on_boundary_;   // see boundary_vertices
  std::vector<uint32_t> free_slots_;   // dead slots, reused last freed first
  double measure(uint32_t t) const;
  double measure_radius_ratio(uint32_t t) const;
  // Per slot, side by side (the relaxation reads both of each star tet:
  // one cache line instead of two): tet_quality and tet_radius_ratio, NaN
  // when not known.
  struct Measures {
    double quality;
    double radius_ratio;
  };
  mutable std::vector<Measures> measures_;
  // Both kept measures of slot t unknown again (its tet or a point of it changed).
  void forget_measures(uint32_t t);
  std::vector<uint32_t>* change_log_ = nullptr;  // see log_changes
  uint32_t changes_ = 1;              // see changes()
  std::vector<uint32_t> changed_at_;  // per vertex: the last change to its star
  std::vector<uint32_t> moved_star_;  // move_vertex's star walk, reused
  uint32_t next_change() { return changes_ == UINT32_MAX ? changes_ : ++changes_; }
  mutable std::vector<uint32_t> mark_; // per slot: stamp of the last star walk or replace
  mutable uint32_t stamp_ = 0;
  mutable std::vector<uint32_t> vertex_mark_;  // per vertex: stamp of the last star_neighbours
  mutable uint32_t vertex_stamp_ = 0;
  // A stamp no slot has in mark_ yet (clearing mark_ when the count wraps).
  uint32_t next_stamp() const;
  // replace()'s face table (open addressing, reused between calls): a
  // cavity's outer face, closed by a new tet, or a new tet's face waiting
  // for its partner among the new tets.
  struct FaceMatch {
    enum State : uint8_t { kFree, kOuter, kWaiting, kClosed };
    FaceKey key{};
    uint32_t code = kNone;  // outer: the face behind it (or kNone); waiting: its code
    State state = kFree;
    static uint32_t hash(const FaceKey& key);
  };
  // The entry of `key`: its own, or the free one where it goes (key set).
  FaceMatch* find_match(const FaceKey& key);
  std::vector<FaceMatch> matches_;
};

// tet_radius_ratio of the tet with vertex quadruple v (slots or not).
inline double radius_ratio_of(const TetTopology& topo, const uint32_t* v) {
  return tet_radius_ratio(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3]));
}

// Local index of vertex v in tet t (0..3), or -1.
inline int local_index(const uint32_t* tet, uint32_t v) {
  for (int k = 0; k < 4; ++k)
    if (tet[k] == v) return k;
  return -1;
}


}  // namespace partet
