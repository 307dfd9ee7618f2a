// The live front during face removals: oriented triangles facing the
// unmeshed region, which shrink as tets are made.
//
// Contents (flat arrays, indices stable for the front's lifetime):
//  - vertices: the InitialFront's joint numbering unchanged, then the
//    vertices appended by add_vertex (coordinates, global ids, the leaf
//    whose half-open box contains each); a vertex is a front vertex while
//    at least one alive face uses it, or while it is free: the
//    InitialFront's free vertices (gap_vertices.hpp) are front vertices,
//    listed in their leaves as targets, from the start until a face first
//    uses them (or drop_free_vertices);
//  - faces: 3 vertex indices each, counterclockwise seen from the unmeshed
//    region (normal (b-a)x(c-a) into it), with an alive flag and a float
//    bounding box rounded outward (for cheap rejections); closed faces
//    stay as dead entries, new faces are appended;
//  - a hash from the sorted vertex triple to the alive face with those
//    vertices (at most one: a face whose reverse is alive closes both), and
//    a hash from the sorted vertex pair to the number of alive faces using
//    that edge (front edges), both flat open-addressing tables;
//  - the leaf index: every alive face is listed in every leaf whose
//    half-open box [lo, hi) it meets (exact box-triangle test over the
//    leaves of grid_range(face's bounding box); closed on the root cube's
//    upper faces), and in the leaves of its three vertices. Half-open
//    boxes tile the root cube, so a face meeting a box B at a point x is
//    listed in the one leaf holding x, which is one of grid_range(B), and
//    gathering the faces of the leaves over B finds every face that can
//    meet B; the validity checks need exactly that. (Closed boxes list a
//    face lying on a leaf's side, as the templated core's faces do, in
//    every leaf that touches it: two to three times the entries.) After
//    compact() the lists are rebuilt with closed boxes: the tree-less
//    removals pick the faces to retry after an advance from a gather, and
//    on thin walls they close only with the closed lists' wider gathers
//    (pipe r1), while the front is small by then. Front vertices are
//    listed in their leaf, whose closed box holds them: the leaf
//    containing them, or for a core vertex the leaf that templated it. Both lists are doubly linked head/next lists in flat
//    arrays (face entries come from a pool with a free list).
// Every change stamps the leaves whose lists changed with a change counter,
// so callers can tell whether the front near a place changed since a time.
// The leaves whose lists ever held a face or a vertex form a growing set
// (listed_leaves): every stamped leaf is one, and a range query restricted
// to it finds every face, vertex and stamp in range (after the Delaunay
// fill the front is near a few of the leaves, and a long face's
// neighbourhood spans hundreds).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/flat_hash_map.hpp"
#include "core/vertex_triple.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"
#include "octree/range_query.hpp"

namespace partet {

constexpr uint32_t kNoIndex = UINT32_MAX;

// Leaves known to cover a region: every leaf that contains a grid cell of
// grid_range(box) for any box inside the region, ascending, with their
// grid cells (lo then hi, 6 per leaf; LeafRangeQuery::leaf_cells).
struct LeafCover {
  const std::vector<size_t>& leaves;
  const std::vector<uint32_t>& cells;
};

// Replaces `out` with the leaves of `cover` that contain a grid cell of
// [lo, hi] (inclusive), ascending: LeafRangeQuery::leaves_in_range's answer
// when the cover covers that range.
inline void leaves_in_cover(const LeafCover& cover, const uint32_t* lo, const uint32_t* hi, std::vector<size_t>& out) {
  out.clear();
  for (size_t i = 0; i < cover.leaves.size(); ++i) {
    const uint32_t* c = &cover.cells[6 * i];
    if (c[0] <= hi[0] && lo[0] <= c[3] && c[1] <= hi[1] && lo[1] <= c[4] && c[2] <= hi[2] && lo[2] <= c[5])
      out.push_back(cover.leaves[i]);
  }
}

class Front {
 public:
  // Copies the vertices and faces of `initial`, which must come from
  // make_initial_front over `tree` and `root`. Keeps a range query over
  // `tree`, whose leaves (keys and levels) must not change while the front
  // is used (the front keeps a reference to it); leaf classes and owners may.
  Front(const InitialFront& initial, const LinearOctree& tree, const RootCube& root);

  const RootCube& root() const { return root_; }
  const LeafRangeQuery& query() const { return query_; }

  size_t num_vertices() const { return vertex_leaf_.size(); }
  const double* point(uint32_t v) const { return &xyz_[3 * size_t{v}]; }
  const std::vector<double>& xyz() const { return xyz_; }
  const std::vector<uint64_t>& global_ids() const { return global_ids_; }
  uint32_t vertex_leaf(uint32_t v) const { return vertex_leaf_[v]; }
  // Number of alive faces using vertex v, plus one while v is free (0: not
  // a front vertex).
  uint32_t vertex_uses(uint32_t v) const { return vertex_uses_[v]; }
  // Front vertices that no face has used yet.
  size_t num_free_vertices() const { return free_count_; }

  // Face slots, alive or closed.
  size_t num_face_slots() const { return alive_.size(); }
  size_t num_alive_faces() const { return alive_count_; }
  bool alive(uint32_t f) const { return alive_[f] != 0; }
  const uint32_t* face(uint32_t f) const { return &faces_[3 * size_t{f}]; }
  // Bounding box of face slot f in floats rounded outward: lo[3] then
  // hi[3], a superset of the exact box for cheap rejections.
  const float* face_box(uint32_t f) const { return &face_box_[6 * size_t{f}]; }

  // The alive face with vertices {a, b, c} in any order, or kNoIndex.
  uint32_t find_face(uint32_t a, uint32_t b, uint32_t c) const;
  // Number of alive faces using edge {a, b} (0: not a front edge).
  uint32_t edge_uses(uint32_t a, uint32_t b) const;
  // Calls visit(g) for every alive face g with vertices u and w (u != w), in
  // leaf list order: a face containing u meets the closed box of the leaf
  // holding u, so it is listed there.
  template <class Visit>
  void for_each_face_on_edge(uint32_t u, uint32_t w, Visit&& visit) const {
    for (uint32_t e = first_face_entry(vertex_leaf(u)); e != kNoIndex; e = next_entry(e)) {
      const uint32_t g = entry_face(e);
      const uint32_t* h = face(g);
      const bool has_u = h[0] == u || h[1] == u || h[2] == u, has_w = h[0] == w || h[1] == w || h[2] == w;
      if (has_u && has_w) visit(g);
    }
  }
  // For an edge {u, w} of alive face f: calls visit(g) for every other
  // alive face g on it. On an edge of two faces (most) the other comes
  // from the edge's entry, the exclusive or of its faces, without a leaf
  // scan; on more, in leaf list order.
  template <class Visit>
  void for_each_other_face_on_edge(uint32_t f, uint32_t u, uint32_t w, Visit&& visit) const {
    const EdgeFaces* edge = find_edge(u, w);
    if (!edge || edge->uses < 2) return;
    if (edge->uses == 2) {
      visit(edge->faces_xor ^ f);
      return;
    }
    for_each_face_on_edge(u, w, [&](uint32_t g) {
      if (g != f) visit(g);
    });
  }

  // Leaf index. Faces listed in `leaf`: first_face_entry, then next_entry
  // until kNoIndex; entry_face gives the face. Front vertices in `leaf`:
  // first_vertex, then next_vertex until kNoIndex.
  uint32_t first_face_entry(size_t leaf) const { return leaf_entry_head_[leaf]; }
  uint32_t next_entry(uint32_t e) const { return entry_next_[e]; }
  uint32_t entry_face(uint32_t e) const { return entry_face_[e]; }
  uint32_t first_vertex(size_t leaf) const { return leaf_vertex_head_[leaf]; }
  uint32_t next_vertex(uint32_t v) const { return vertex_next_[v]; }
  // True when no face is listed in the leaf and no front vertex lies in it.
  bool leaf_front_empty(size_t leaf) const {
    return leaf_entry_head_[leaf] == kNoIndex && leaf_vertex_head_[leaf] == kNoIndex;
  }
  // The leaves whose lists ever held a face or a vertex (see above).
  const LeafSet& listed_leaves() const { return listed_; }
  // Value of the change counter when the leaf's lists last changed (0: never).
  uint64_t leaf_changed(size_t leaf) const { return leaf_changed_[leaf]; }
  // Number of tets applied so far (the change counter).
  uint64_t changes() const { return changes_; }

  // Appends a vertex at p with global id `global_id`, in the leaf whose
  // half-open box contains p (clamped into the root cube), and returns its
  // index. It becomes a front vertex, listed in that leaf, once a face uses
  // it.
  uint32_t add_vertex(const double* p, uint64_t global_id);
  // Takes the free vertices off the front (they stay, unused, in the vertex
  // arrays) and returns how many there were; the leaves that lost a vertex
  // are appended to `shrunk`.
  size_t drop_free_vertices(std::vector<uint32_t>& shrunk);
  // Removes the last vertex, which no face may have used (undoes add_vertex).
  void remove_last_vertex();

  // The front's state now (face slots, the alive faces and the free
  // vertices, ascending), to tell later what a copy of it changed.
  struct Snapshot {
    size_t slots = 0;
    std::vector<uint32_t> alive_faces, free_vertices;
  };
  Snapshot snapshot() const;
  // What this front changed since `then` (a snapshot of it, or of a copy
  // identical then as sets of faces and free vertices): the faces alive then
  // and closed now (3 vertex indices each, in the order of `then`), the
  // faces added since that are still alive (3 vertex indices each, in slot
  // order) and the vertices free then and not now (ascending). Faces are
  // named by their vertices, so copies whose slots are numbered differently
  // exchange them.
  struct Changes {
    std::vector<uint32_t> closed, added, taken;
  };
  Changes changes_since(const Snapshot& then) const;
  // Takes in the changes another copy of this front made (changes_since on
  // it, from the same front as this one) where this front changed
  // nothing: no face or vertex either touched. The faces closed there are
  // closed here, the faces added there are added here (new slots, in
  // order), and the free vertices taken there and used by no face here are
  // taken off the front. Appends the leaves that lost a face or a vertex to
  // `shrunk`. The alive faces, front edges and front vertices are then
  // those of the copy's tets made again on this front (apply_tet).
  void merge(const Changes& changes, std::vector<uint32_t>& shrunk);

  // Drops the closed face slots, renumbering the alive faces in their
  // order (every order by face index stays), rebuilds the leaf lists with
  // closed boxes (newest face first, as before) and gives the memory back.
  // Returns the new index of every old face slot (kNoIndex for a closed
  // face). Face indices held elsewhere must be mapped through it.
  std::vector<uint32_t> compact();

  // Applies the positively oriented tet (a, b, c, p) built on alive face f
  // = (a, b, c) (orient3d(a, b, c, p) > 0 is the caller's check): closes f;
  // each of the new faces (b, c, p), (a, p, c), (a, b, p) (oriented away
  // from the tet, i.e. into the unmeshed region) closes its reverse when
  // that is alive, else is added. The caller guarantees no new face
  // duplicates an alive face with the same orientation. Appends the new
  // faces' indices to `added` and the leaves that lost a face or a vertex
  // to `shrunk` (with repetitions). Returns the number of faces closed
  // besides f. With `cover` (leaves covering the tet's bounding box), the
  // new faces are listed from those leaves instead of a range query: the
  // same leaves, in the same order.
  int apply_tet(uint32_t f, uint32_t p, std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk,
                const LeafCover* cover = nullptr);
  // Undoes a tet: the positively oriented tet (a, b, c, d), made earlier,
  // is taken out of the meshed region. Each of its faces, oriented into it,
  // closes its reverse when that is alive (the unmeshed region on the other
  // side joins), else is added (the other side is meshed, or outside the
  // domain for a surface triangle). Appends the new faces' indices to
  // `added` and the leaves that lost a face or a vertex to `shrunk`.
  void remove_tet(const uint32_t tet[4], std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk);

 private:
  uint32_t add_face(uint32_t a, uint32_t b, uint32_t c, const LeafCover* cover = nullptr);
  // Lists face f in the leaves it meets (see the leaf index above), taking
  // the candidates from `cover` when given (it covers the face's box), else
  // from a range query; with `stamp`, marks them changed.
  void list_face(uint32_t f, bool stamp, const LeafCover* cover = nullptr);
  void close_face(uint32_t f, std::vector<uint32_t>& shrunk);
  void use_vertex(uint32_t v);
  void release_vertex(uint32_t v, std::vector<uint32_t>& shrunk);
  // Face f joins (delta 1) or leaves (-1) edge {a, b}.
  void change_edge(uint32_t a, uint32_t b, uint32_t f, int delta);

  const LinearOctree* tree_;  // pointers and values: a Front is assignable (the tree-less
                              // removals restore a snapshot of it)
  RootCube root_;
  LeafRangeQuery query_;
  std::vector<size_t> leaves_scratch_;

  std::vector<double> xyz_;
  std::vector<uint64_t> global_ids_;
  std::vector<uint32_t> vertex_leaf_;
  std::vector<uint32_t> vertex_uses_;
  std::vector<uint8_t> free_;  // per vertex: free (listed, used by no face yet)
  size_t free_count_ = 0;
  std::vector<uint32_t> vertex_prev_;  // in the leaf's vertex list
  std::vector<uint32_t> vertex_next_;
  std::vector<uint32_t> leaf_vertex_head_;
  LeafSet listed_;

  std::vector<uint32_t> faces_;
  std::vector<uint8_t> alive_;
  std::vector<float> face_box_;  // 6 per face slot, see face_box
  std::vector<uint32_t> face_first_entry_;  // chain of the face's entries via entry_chain_
  size_t alive_count_ = 0;

  // Face entry pool: one entry per (face, leaf).
  std::vector<uint32_t> entry_face_;
  std::vector<uint32_t> entry_leaf_;
  std::vector<uint32_t> entry_prev_;   // in the leaf's list
  std::vector<uint32_t> entry_next_;   // in the leaf's list; in the free list when free
  std::vector<uint32_t> entry_chain_;  // next entry of the same face
  uint32_t free_entry_ = kNoIndex;
  std::vector<uint32_t> leaf_entry_head_;
  bool closed_lists_ = false;  // closed leaf boxes (after compact), else half-open

  std::vector<uint64_t> leaf_changed_;
  uint64_t changes_ = 0;

  struct EdgeTraits {
    static uint64_t empty() { return UINT64_MAX; }
    static uint64_t hash(uint64_t k);
  };
  FlatHashMap<VertexTriple, uint32_t, VertexTripleTraits> face_of_triple_;
  // Per front edge: its alive faces, counted and combined by exclusive or.
  struct EdgeFaces {
    uint32_t uses = 0;
    uint32_t faces_xor = 0;
  };
  FlatHashMap<uint64_t, EdgeFaces, EdgeTraits> edge_faces_;
  const EdgeFaces* find_edge(uint32_t a, uint32_t b) const;
};

}  // namespace partet
