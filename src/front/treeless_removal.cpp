// Tree-less face removals with new vertices: the rounds, the cavity fill
// and apex candidates, and the bookkeeping of added vertices (see
// steiner_removal.hpp).
#include "front/steiner_removal.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "front/removal_checks.hpp"
#include "octree/range_query.hpp"

namespace partet {

namespace {

constexpr size_t kMaxCavityFaces = 64;

class SteinerRemover {
 public:
  SteinerRemover(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out, const RemovalOptions& options)
      : front_(front), tree_(tree), root_(root), out_(out), options_(options) {}

  RemovalCounts run();

 private:
  void tree_pass();
  uint32_t add_vertex(const double* p);
  void drop_vertex();
  // Gathers the near front over the bounding box of face f and point v;
  // false when a leaf there is owned by another rank.
  bool gather_around(uint32_t f, uint32_t v);
  bool valid_tet(uint32_t f, uint32_t v);
  void make_tet(uint32_t f, uint32_t v);
  bool try_cavity(const std::vector<uint32_t>& faces);
  // Alive faces grouped by edge-connected component: components_ holds the
  // faces, component_first_ the start of each (plus one past the end).
  void find_components();

  Front& front_;
  LinearOctree& tree_;
  const RootCube& root_;
  TetMesh& out_;
  const RemovalOptions& options_;
  RemovalCounts counts_;
  bool ids_ = false;
  size_t budget_ = 0;

  std::vector<size_t> leaves_;
  NearFront near_;
  std::vector<uint32_t> added_, shrunk_;
  std::vector<uint32_t> components_;
  std::vector<size_t> component_first_;
};

void SteinerRemover::tree_pass() {
  const RemovalCounts n = remove_faces_tree_supported(front_, tree_, root_, out_, options_);
  counts_.tets += n.tets;
  counts_.checks += n.checks;
  counts_.passes += n.passes;
  counts_.foreign_faces = n.foreign_faces;
}

uint32_t SteinerRemover::add_vertex(const double* p) {
  const uint32_t v = front_.add_vertex(p, kSteinerVertexId | front_.num_vertices());
  out_.xyz.insert(out_.xyz.end(), p, p + 3);
  if (ids_) out_.global_ids.push_back(front_.global_ids()[v]);
  return v;
}

void SteinerRemover::drop_vertex() {
  front_.remove_last_vertex();
  out_.xyz.resize(out_.xyz.size() - 3);
  if (ids_) out_.global_ids.pop_back();
}

bool SteinerRemover::gather_around(uint32_t f, uint32_t v) {
  const uint32_t* t = front_.face(f);
  const double* p[4] = {front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), front_.point(v)};
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({p[0][k], p[1][k], p[2][k], p[3][k]});
    hi[k] = std::max({p[0][k], p[1][k], p[2][k], p[3][k]});
  }
  uint32_t glo[3], ghi[3];
  grid_range(root_, lo, hi, glo, ghi);
  front_.query().leaves_in_range(glo, ghi, leaves_);
  for (size_t leaf : leaves_)
    if (tree_.owner[leaf] != options_.rank) return false;
  gather_near_front(front_, leaves_, near_);
  return true;
}

bool SteinerRemover::valid_tet(uint32_t f, uint32_t v) {
  if (!gather_around(f, v)) return false;
  ++counts_.checks;
  return check_removal(front_, f, v, near_) == RemovalVerdict::kValid;
}

void SteinerRemover::make_tet(uint32_t f, uint32_t v) {
  make_removal_tet(front_, tree_, out_, f, v, added_, shrunk_);
  ++counts_.tets;
}

bool SteinerRemover::try_cavity(const std::vector<uint32_t>& faces) {
  double candidates[2][3] = {{0, 0, 0}, {0, 0, 0}};
  std::vector<uint32_t> vertices;
  for (uint32_t f : faces)
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = front_.face(f)[i];
      vertices.push_back(v);
      for (int k = 0; k < 3; ++k) candidates[0][k] += front_.point(v)[k] / (3.0 * static_cast<double>(faces.size()));
    }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (uint32_t v : vertices)
    for (int k = 0; k < 3; ++k) candidates[1][k] += front_.point(v)[k] / static_cast<double>(vertices.size());
  for (const double* q : candidates) {
    bool sees_all = true;
    for (uint32_t f : faces) {
      const uint32_t* t = front_.face(f);
      sees_all = sees_all && orient3d(front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), q) > 0;
    }
    if (!sees_all) continue;
    const uint32_t v = add_vertex(q);
    bool made = false;
    for (uint32_t f : faces) {
      if (!front_.alive(f) || !valid_tet(f, v)) continue;
      make_tet(f, v);
      made = true;
    }
    if (made) return true;
    drop_vertex();
  }
  return false;
}

void SteinerRemover::find_components() {
  std::vector<std::pair<uint64_t, uint32_t>> edge_face;
  std::vector<uint32_t> parent(front_.num_face_slots());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (uint32_t f = 0; f < front_.num_face_slots(); ++f) {
    if (!front_.alive(f)) continue;
    const uint32_t* t = front_.face(f);
    for (int i = 0; i < 3; ++i) {
      const uint32_t x = std::min(t[i], t[(i + 1) % 3]), y = std::max(t[i], t[(i + 1) % 3]);
      edge_face.emplace_back((uint64_t{x} << 32) | y, f);
    }
  }
  std::sort(edge_face.begin(), edge_face.end());
  for (size_t i = 1; i < edge_face.size(); ++i)
    if (edge_face[i].first == edge_face[i - 1].first) {
      const uint32_t x = find(edge_face[i].second), y = find(edge_face[i - 1].second);
      parent[std::max(x, y)] = std::min(x, y);  // the root is the lowest face index
    }
  // Faces by (root, index): components in order of their lowest face.
  std::vector<std::pair<uint32_t, uint32_t>> by_root;
  for (uint32_t f = 0; f < front_.num_face_slots(); ++f)
    if (front_.alive(f)) by_root.emplace_back(find(f), f);
  std::sort(by_root.begin(), by_root.end());
  components_.clear();
  component_first_.clear();
  for (size_t i = 0; i < by_root.size(); ++i) {
    if (i == 0 || by_root[i].first != by_root[i - 1].first) component_first_.push_back(i);
    components_.push_back(by_root[i].second);
  }
  component_first_.push_back(components_.size());
}

RemovalCounts SteinerRemover::run() {
  tree_pass();  // also appends the front vertices `out` lacks
  ids_ = out_.global_ids.size() == out_.num_vertices();
  budget_ = front_.num_vertices() + 4 * front_.num_alive_faces() + 64;

  std::vector<uint32_t> cavity;
  bool made = front_.num_alive_faces() > 0;
  while (made && front_.num_alive_faces() > 0 && front_.num_vertices() < budget_) {
    made = false;
    find_components();
    for (size_t i = 0; i + 1 < component_first_.size(); ++i) {
      cavity.assign(components_.begin() + static_cast<ptrdiff_t>(component_first_[i]),
                    components_.begin() + static_cast<ptrdiff_t>(component_first_[i + 1]));
      if (cavity.size() > kMaxCavityFaces || front_.num_vertices() >= budget_) continue;
      bool all_alive = true;
      for (uint32_t f : cavity) all_alive = all_alive && front_.alive(f);
      if (all_alive && try_cavity(cavity)) {
        made = true;
        tree_pass();
      }
    }
  }
  counts_.faces_left = front_.num_alive_faces();
  return counts_;
}

}  // namespace

RemovalCounts remove_faces_with_new_vertices(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                             const RemovalOptions& options) {
  PARTET_ASSERT(tree.size() == tree.owner.size() && tree.size() == tree.cls.size(), "tree arrays disagree");
  return SteinerRemover(front, tree, root, out, options).run();
}

}  // namespace partet
