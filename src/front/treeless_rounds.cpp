// One attempt of the tree-less face removals with one strategy: rounds over
// the front components, star fills, growth by tet deletion, partial cones,
// patch cones and advances (see treeless_removal.hpp, steps 1-5).
#include "front/treeless_rounds.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "core/distance.hpp"
#include "core/error.hpp"
#include "core/predicates.hpp"
#include "front/front_cavities.hpp"
#include "front/kernel_point.hpp"
#include "front/removal_checks.hpp"
#include "front/tet_incidence.hpp"
#include "octree/range_query.hpp"

namespace partet {

namespace {

double squared_distance(const double* x, const double* y) {
  const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
  return dx * dx + dy * dy + dz * dz;
}

constexpr size_t kMaxCavityFaces = 256;  // largest component filled (and grown) as one cavity
constexpr size_t kMaxSmallCavityFaces = 64;  // the same, with TreelessStrategy::kSmallCavities
constexpr size_t kSuspects = 16;  // blockers valid_tet keeps to test first
constexpr size_t kMaxGrownFaces = 4 * kMaxCavityFaces;  // largest component a growth may reach
constexpr size_t kPatchSizes[] = {64, 24, 8};           // patch cone sizes, largest first
// A patch's kernel point is searched in its own bounding box, and when that
// point is less deep than kPlainDepth mean edge lengths, in the box lifted
// along the patch's normal by kPatchLift mean edge lengths
// (treeless_removal.hpp, step 4).
constexpr double kPlainDepth = 0.2;
constexpr double kPatchLift = 0.75;

class TreelessRemover {
 public:
  TreelessRemover(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out, const RemovalOptions& options,
                  RemovalMemo& memo, TreelessStrategy strategy)
      : front_(front), tree_(tree), root_(root), out_(out), options_(options), memo_(memo), strategy_(strategy) {}

  TreelessCounts run();

 private:
  void tree_pass();
  // The last pass when the rounds leave faces (RemovalOptions::
  // close_flat_cavities), with a memo of its own: the rounds' has them waiting.
  void flat_cavity_pass();
  // Tree-supported removals starting from the given faces only.
  void local_tree_pass(const std::vector<uint32_t>& seeds);
  // Sum of the squared edge lengths of face f.
  double face_size(uint32_t f) const;
  // Sets `lift` to the patch's area-weighted unit normal times kPatchLift
  // times its mean edge length (zero when the normals cancel) and returns
  // that mean edge length (the mean of its faces' root-mean-square edges).
  double patch_lift(const std::vector<uint32_t>& patch, double lift[3]) const;
  // `bounded`: the patch and the alive front faces over the patch's box
  // swept by `lift` that see the patch's centre (orient3d > 0: the patch
  // lies on their unmeshed side). False when there are none, or a leaf
  // there is owned by another rank.
  bool bounded_by_facing_faces(const std::vector<uint32_t>& patch, const double lift[3],
                               std::vector<uint32_t>& bounded);
  uint32_t add_vertex(const double* p);
  void drop_vertex();
  // Leaves over the box of the given points; false when one is owned by
  // another rank.
  bool own_leaves_around(const double* const* points, int n);
  // False when another rank owns a leaf over the component's box grown by
  // half its largest extent on every side: room for what a fill or a
  // growth there may touch. The rounds leave such a component alone (the
  // ranks that share it could only churn at its cut; rank 0 closes it
  // afterwards). Always true when this rank owns every leaf.
  bool own_component(std::vector<uint32_t>::const_iterator first, std::vector<uint32_t>::const_iterator last);
  bool valid_tet(uint32_t f, uint32_t v);
  bool sees_all(const std::vector<uint32_t>& faces, const double* q) const;
  // Cones the faces that see q to a new vertex at q where valid; returns
  // the number of tets made (the vertex is dropped when 0).
  size_t cone(const std::vector<uint32_t>& faces, const double* q);
  bool fill(std::vector<uint32_t> faces);
  // Patch cones over the given faces: around each seed face (smallest
  // first), the breadth-first patch of the given faces still alive
  // (kPatchSizes faces, largest first) is coned to its deepest kernel point
  // when that sees every patch face. Returns the number of cones made.
  size_t patch_cones(const std::vector<uint32_t>& faces);
  // Classic advancing-front step on face f: an existing front vertex near
  // the ideal apex (above the centroid at the height of the regular tet),
  // else a new vertex there or lower; false when none is valid.
  bool advance_face(uint32_t f);
  // Deletes the tets behind the faces that do not see q (with `every`,
  // behind all the faces); false when none.
  bool reopen_blockers(const std::vector<uint32_t>& faces, const double* q, bool every);
  // Undoes the deletions in reopened_, newest first: each tet is made
  // again (appended to `out`) from one of its faces the deletion opened,
  // so the front is as before the deletions.
  void restore_reopened();
  // The component holding alive face f, in face index order, found by a
  // breadth-first walk across edges (as faces_across_edge crosses them);
  // the walk stops past `limit` faces.
  std::vector<uint32_t> component_of(uint32_t f, size_t limit);
  // A new walk over the face slots: walk_ marks none of them yet.
  void start_walk();

  Front& front_;
  LinearOctree& tree_;
  const RootCube& root_;
  TetMesh& out_;
  const RemovalOptions& options_;
  RemovalMemo& memo_;
  const TreelessStrategy strategy_;
  TreelessCounts counts_;
  bool ids_ = false;
  bool shared_ = false;  // another rank owns a leaf of the tree
  size_t vertex_budget_ = 0;
  size_t deletion_budget_ = 0;
  std::unique_ptr<TetIncidence> incidence_;

  std::vector<size_t> leaves_;
  NearFront near_;
  Suspects suspects_;          // what blocked the last tets valid_tet refused
  const NearFront no_front_;   // to test the suspects alone
  std::vector<uint32_t> added_, shrunk_;
  // Tets deleted by the current growth step; false when one of them had
  // all four faces on the front (its deletion opened none to rebuild it from).
  std::vector<uint32_t> reopened_;
  bool restorable_ = true;
  std::vector<uint32_t> components_;
  std::vector<size_t> component_first_;
  std::vector<uint32_t> walk_mark_;  // per face slot: the walk (component or patch) that last reached it
  uint32_t walk_ = 0;
};

void TreelessRemover::tree_pass() {
  const RemovalCounts n = remove_faces_tree_supported(front_, tree_, root_, out_, options_, nullptr, &memo_);
  counts_.tree_tets += n.tets;
  counts_.checks += n.checks;
  counts_.foreign_faces = n.foreign_faces;
}

void TreelessRemover::flat_cavity_pass() {
  RemovalOptions options = options_;
  options.close_flat_cavities = true;
  const RemovalCounts n = remove_faces_tree_supported(front_, tree_, root_, out_, options, nullptr, nullptr);
  counts_.tree_tets += n.tets;
  counts_.checks += n.checks;
}

void TreelessRemover::local_tree_pass(const std::vector<uint32_t>& seeds) {
  const RemovalCounts n = remove_faces_tree_supported(front_, tree_, root_, out_, options_, &seeds, &memo_);
  counts_.tree_tets += n.tets;
  counts_.checks += n.checks;
}

double TreelessRemover::face_size(uint32_t f) const {
  const uint32_t* t = front_.face(f);
  return squared_distance(front_.point(t[0]), front_.point(t[1])) +
         squared_distance(front_.point(t[1]), front_.point(t[2])) +
         squared_distance(front_.point(t[2]), front_.point(t[0]));
}

double TreelessRemover::patch_lift(const std::vector<uint32_t>& patch, double lift[3]) const {
  double normal[3] = {0, 0, 0}, edge = 0;
  for (uint32_t f : patch) {
    const uint32_t* t = front_.face(f);
    const double *pa = front_.point(t[0]), *pb = front_.point(t[1]), *pc = front_.point(t[2]);
    const double e1[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const double e2[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
    normal[0] += e1[1] * e2[2] - e1[2] * e2[1];
    normal[1] += e1[2] * e2[0] - e1[0] * e2[2];
    normal[2] += e1[0] * e2[1] - e1[1] * e2[0];
    edge += std::sqrt(face_size(f) / 3);
  }
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  edge /= static_cast<double>(patch.size());
  const double scale = length > 0 ? kPatchLift * edge / length : 0;
  for (int k = 0; k < 3; ++k) lift[k] = normal[k] * scale;
  return edge;
}

bool TreelessRemover::bounded_by_facing_faces(const std::vector<uint32_t>& patch, const double lift[3],
                                              std::vector<uint32_t>& bounded) {
  double lo[3], hi[3], centre[3] = {0, 0, 0};
  std::copy_n(front_.point(front_.face(patch[0])[0]), 3, lo);
  std::copy_n(lo, 3, hi);
  const double share = 1.0 / (3.0 * static_cast<double>(patch.size()));
  for (uint32_t f : patch)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        const double x = front_.point(front_.face(f)[i])[k];
        lo[k] = std::min({lo[k], x, x + lift[k]});
        hi[k] = std::max({hi[k], x, x + lift[k]});
        centre[k] += x * share;
      }
  const double* corners[2] = {lo, hi};
  if (!own_leaves_around(corners, 2)) return false;
  gather_near_front(front_, leaves_, near_);
  bounded = patch;
  std::sort(bounded.begin(), bounded.end());
  const size_t patch_faces = bounded.size();
  for (uint32_t f : near_.faces) {
    const uint32_t* t = front_.face(f);
    if (!std::binary_search(bounded.begin(), bounded.begin() + static_cast<ptrdiff_t>(patch_faces), f) &&
        orient3d(front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), centre) > 0)
      bounded.push_back(f);
  }
  return bounded.size() > patch_faces;
}

uint32_t TreelessRemover::add_vertex(const double* p) {
  const uint32_t v = front_.add_vertex(p, kSteinerVertexId | front_.num_vertices());
  out_.xyz.insert(out_.xyz.end(), p, p + 3);
  if (ids_) out_.global_ids.push_back(front_.global_ids()[v]);
  return v;
}

void TreelessRemover::drop_vertex() {
  front_.remove_last_vertex();
  out_.xyz.resize(out_.xyz.size() - 3);
  if (ids_) out_.global_ids.pop_back();
}

bool TreelessRemover::own_leaves_around(const double* const* points, int n) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = hi[k] = points[0][k];
    for (int i = 1; i < n; ++i) {
      lo[k] = std::min(lo[k], points[i][k]);
      hi[k] = std::max(hi[k], points[i][k]);
    }
  }
  uint32_t glo[3], ghi[3];
  grid_range(root_, lo, hi, glo, ghi);
  if (!shared_) {  // every leaf is this rank's: the front's are enough
    front_.query().leaves_in_range(glo, ghi, leaves_, front_.listed_leaves());
    return true;
  }
  front_.query().leaves_in_range(glo, ghi, leaves_);
  for (size_t leaf : leaves_)
    if (tree_.owner[leaf] != options_.rank) return false;
  return true;
}

bool TreelessRemover::own_component(std::vector<uint32_t>::const_iterator first,
                                    std::vector<uint32_t>::const_iterator last) {
  if (!shared_) return true;
  double lo[3], hi[3];
  std::copy_n(front_.point(front_.face(*first)[0]), 3, lo);
  std::copy_n(lo, 3, hi);
  for (auto it = first; it != last; ++it)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], front_.point(front_.face(*it)[i])[k]);
        hi[k] = std::max(hi[k], front_.point(front_.face(*it)[i])[k]);
      }
  const double margin = 0.5 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  for (int k = 0; k < 3; ++k) {
    lo[k] -= margin;
    hi[k] += margin;
  }
  const double* corners[2] = {lo, hi};
  return own_leaves_around(corners, 2);
}

bool TreelessRemover::valid_tet(uint32_t f, uint32_t v) {
  const uint32_t* t = front_.face(f);
  const double* p[4] = {front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), front_.point(v)};
  if (!own_leaves_around(p, 4)) return false;
  ++counts_.checks;
  // What blocked the last tets tried (mostly the same cone's) goes first,
  // before the gather.
  RemovalBlocker why;
  if (!suspects_.empty() && check_removal(front_, f, v, no_front_, &why, &suspects_) != RemovalVerdict::kValid)
    return false;
  gather_near_front(front_, leaves_, near_);
  if (check_removal(front_, f, v, near_, &why) == RemovalVerdict::kValid) return true;
  if (suspects_.faces.size() + suspects_.vertices.size() >= kSuspects) suspects_.clear();
  suspects_.add(why);
  return false;
}

bool TreelessRemover::sees_all(const std::vector<uint32_t>& faces, const double* q) const {
  for (uint32_t f : faces) {
    const uint32_t* t = front_.face(f);
    if (orient3d(front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), q) <= 0) return false;
  }
  return true;
}

size_t TreelessRemover::cone(const std::vector<uint32_t>& faces, const double* q) {
  if (front_.num_vertices() >= vertex_budget_) return 0;
  const uint32_t v = add_vertex(q);
  size_t made = 0;
  for (uint32_t f : faces) {
    if (!front_.alive(f)) continue;
    const uint32_t* t = front_.face(f);
    if (orient3d(front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), q) <= 0 || !valid_tet(f, v)) continue;
    make_removal_tet(front_, tree_, out_, f, v, added_, shrunk_);
    ++made;
  }
  if (made == 0) {
    drop_vertex();
    return 0;
  }
  ++counts_.vertices_added;
  counts_.new_vertex_tets += made;
  return made;
}

bool TreelessRemover::reopen_blockers(const std::vector<uint32_t>& faces, const double* q, bool every) {
  if (!incidence_) incidence_ = std::make_unique<TetIncidence>(out_);
  incidence_->index_new(out_);
  std::vector<uint32_t> doomed;
  for (uint32_t f : faces) {
    const uint32_t* t = front_.face(f);
    if (!every && orient3d(front_.point(t[0]), front_.point(t[1]), front_.point(t[2]), q) > 0) continue;
    const uint32_t tet = incidence_->tet_behind(out_, t[0], t[1], t[2]);
    if (tet == kNoTet) continue;
    const uint32_t* v = &out_.tets[4 * size_t{tet}];
    const double* p[4] = {out_.point(v[0]), out_.point(v[1]), out_.point(v[2]), out_.point(v[3])};
    if (own_leaves_around(p, 4)) doomed.push_back(tet);
  }
  std::sort(doomed.begin(), doomed.end());
  doomed.erase(std::unique(doomed.begin(), doomed.end()), doomed.end());
  size_t deleted = 0;
  for (uint32_t tet : doomed) {
    if (counts_.tets_deleted >= deletion_budget_) break;
    added_.clear();
    shrunk_.clear();
    front_.remove_tet(&out_.tets[4 * size_t{tet}], added_, shrunk_);
    incidence_->kill(tet);
    reopened_.push_back(tet);
    restorable_ = restorable_ && !added_.empty();
    ++counts_.tets_deleted;
    ++deleted;
  }
  return deleted > 0;
}

void TreelessRemover::restore_reopened() {
  for (auto it = reopened_.rbegin(); it != reopened_.rend(); ++it) {
    const uint32_t* v = &out_.tets[4 * size_t{*it}];
    const uint32_t a = v[0], b = v[1], c = v[2], d = v[3];
    const uint32_t sides[4][4] = {{a, b, c, d}, {b, d, c, a}, {a, c, d, b}, {a, d, b, c}};
    uint32_t g = kNoIndex, apex = kNoIndex;
    for (const auto& side : sides)
      if (g == kNoIndex && (g = front_.find_face(side[0], side[1], side[2])) != kNoIndex) apex = side[3];
    PARTET_ASSERT(g != kNoIndex, "a reopened tet has a face to be rebuilt from");
    make_removal_tet(front_, tree_, out_, g, apex, added_, shrunk_);
  }
  reopened_.clear();
}

bool TreelessRemover::fill(std::vector<uint32_t> faces) {
  const int max_growth = growth_steps(strategy_);
  KernelPoint kernel;
  for (int growth = 0;; ++growth) {
    kernel = deepest_kernel_point(front_, faces);
    // Candidates: the kernel's deepest point, the mean of the face
    // centroids, the mean of the vertices.
    double candidates[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    std::vector<uint32_t> vertices;
    for (uint32_t f : faces)
      for (int i = 0; i < 3; ++i) {
        const uint32_t v = front_.face(f)[i];
        vertices.push_back(v);
        for (int k = 0; k < 3; ++k)
          candidates[1][k] += front_.point(v)[k] / (3.0 * static_cast<double>(faces.size()));
      }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (uint32_t v : vertices)
      for (int k = 0; k < 3; ++k) candidates[2][k] += front_.point(v)[k] / static_cast<double>(vertices.size());
    std::copy_n(kernel.point, 3, candidates[0]);
    for (int c = kernel.found ? 0 : 1; c < 3; ++c)
      if (sees_all(faces, candidates[c]) && cone(faces, candidates[c]) > 0) {
        ++counts_.star_fills;
        return true;
      }
    // With kConeFirst a cavity that is not star-shaped (its deepest point
    // lies outside the kernel) is first split by a partial cone to that
    // point, before any tet is deleted.
    if (strategy_ == TreelessStrategy::kConeFirst && growth == 0 && kernel.found && cone(faces, kernel.point) > 0) {
      ++counts_.partial_cones;
      return true;
    }
    // Without a kernel (e.g. a flat cavity between coplanar faces) the
    // faces that do not see the mean of the vertices are reopened. When
    // only surface faces block the point, every face with a tet behind it
    // is reopened: the cavity grows away from the surface.
    const double* q = kernel.found ? kernel.point : candidates[2];
    reopened_.clear();
    restorable_ = true;
    if (growth == max_growth || !(reopen_blockers(faces, q, false) || reopen_blockers(faces, q, true))) break;
    // The grown component: the one holding an alive face of the old one or
    // a face the deletions added.
    uint32_t seed = kNoIndex;
    for (uint32_t f : faces)
      if (seed == kNoIndex && front_.alive(f)) seed = f;
    for (uint32_t f : added_)
      if (seed == kNoIndex && front_.alive(f)) seed = f;
    if (seed == kNoIndex) return true;  // the deletions closed it
    faces = component_of(seed, kMaxGrownFaces + 1);
    if (faces.size() > kMaxGrownFaces) {
      // Grown into a component too large for one cavity: it is left for
      // this round. With kUndoOvergrowth and kConeFirst the step's
      // deletions are undone (kept, the tree pass would rebuild the same
      // tets and the next round would grow the same way again).
      const bool undo =
          strategy_ == TreelessStrategy::kUndoOvergrowth || strategy_ == TreelessStrategy::kConeFirst;
      if (undo && restorable_) restore_reopened();
      return false;
    }
  }
  if (kernel.found && cone(faces, kernel.point) > 0) {
    ++counts_.partial_cones;
    return true;
  }
  std::vector<uint32_t> alive;
  for (uint32_t f : faces)
    if (front_.alive(f)) alive.push_back(f);
  return patch_cones(alive) > 0;
}

size_t TreelessRemover::patch_cones(const std::vector<uint32_t>& faces) {
  // Adjacency by shared edge, over the given faces.
  std::vector<std::pair<uint64_t, uint32_t>> edge_face;
  for (uint32_t f : faces) {
    const uint32_t* t = front_.face(f);
    for (int i = 0; i < 3; ++i) {
      const uint32_t x = std::min(t[i], t[(i + 1) % 3]), y = std::max(t[i], t[(i + 1) % 3]);
      edge_face.emplace_back((uint64_t{x} << 32) | y, f);
    }
  }
  std::sort(edge_face.begin(), edge_face.end());
  std::vector<std::pair<double, uint32_t>> order;
  for (uint32_t f : faces) order.emplace_back(face_size(f), f);
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> patch, bounded;
  size_t made = 0;
  for (const auto& [size, seed] : order) {
    for (size_t target : kPatchSizes) {
      if (!front_.alive(seed)) break;
      // Breadth-first patch of alive faces around the seed.
      patch.assign(1, seed);
      start_walk();
      walk_mark_[seed] = walk_;
      for (size_t head = 0; head < patch.size() && patch.size() < target; ++head) {
        const uint32_t* t = front_.face(patch[head]);
        for (int i = 0; i < 3 && patch.size() < target; ++i) {
          const uint32_t x = std::min(t[i], t[(i + 1) % 3]), y = std::max(t[i], t[(i + 1) % 3]);
          const uint64_t key = (uint64_t{x} << 32) | y;
          for (auto it = std::lower_bound(edge_face.begin(), edge_face.end(), std::make_pair(key, uint32_t{0}));
               it != edge_face.end() && it->first == key && patch.size() < target; ++it)
            if (front_.alive(it->second) && walk_mark_[it->second] != walk_) {
              walk_mark_[it->second] = walk_;
              patch.push_back(it->second);
            }
        }
      }
      // The point in the patch's own box when it is deep enough, else in
      // the lifted box.
      double lift[3];
      const double edge = patch_lift(patch, lift);
      KernelPoint kernel = deepest_kernel_point(front_, patch);
      if (!kernel.found || !(kernel.depth >= kPlainDepth * edge)) kernel = deepest_kernel_point(front_, patch, lift);
      bool coned = kernel.found && sees_all(patch, kernel.point) && cone(patch, kernel.point) > 0;
      // Else the point kept inside the unmeshed region in front of the
      // patch: bounded also by the front faces there that face the patch.
      if (!coned && bounded_by_facing_faces(patch, lift, bounded)) {
        kernel = deepest_kernel_point(front_, bounded, lift);
        coned = kernel.found && sees_all(patch, kernel.point) && cone(patch, kernel.point) > 0;
      }
      if (!coned) continue;
      ++counts_.partial_cones;
      ++made;
      break;
    }
  }
  return made;
}

bool TreelessRemover::advance_face(uint32_t f) {
  if (front_.num_vertices() >= vertex_budget_) return false;
  const uint32_t* t = front_.face(f);
  const uint32_t a = t[0], b = t[1], c = t[2];
  const double *pa = front_.point(a), *pb = front_.point(b), *pc = front_.point(c);
  double g[3], e1[3], e2[3], n[3];
  for (int k = 0; k < 3; ++k) {
    g[k] = (pa[k] + pb[k] + pc[k]) / 3;
    e1[k] = pb[k] - pa[k];
    e2[k] = pc[k] - pa[k];
  }
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double edge = (std::sqrt(squared_distance(pa, pb)) + std::sqrt(squared_distance(pb, pc)) +
                       std::sqrt(squared_distance(pc, pa))) / 3;
  if (!(length > 0) || !(edge > 0)) return false;
  const double regular_height = std::sqrt(2.0 / 3.0) * edge;
  double top[3];
  for (int k = 0; k < 3; ++k) top[k] = g[k] + n[k] / length * regular_height;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({pa[k], pb[k], pc[k], top[k]}) - 0.5 * edge;
    hi[k] = std::max({pa[k], pb[k], pc[k], top[k]}) + 0.5 * edge;
  }
  const double box[2][3] = {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
  const double* corners[2] = {box[0], box[1]};
  if (!own_leaves_around(corners, 2)) return false;
  gather_near_front(front_, leaves_, near_);
  // Existing front vertices near the ideal apex first, nearest first.
  std::vector<std::pair<double, uint32_t>> near_apex;
  for (uint32_t v : near_.vertices) {
    if (v == a || v == b || v == c) continue;
    const double d2 = squared_distance(front_.point(v), top);
    if (d2 < 0.5 * regular_height * regular_height && orient3d(pa, pb, pc, front_.point(v)) > 0)
      near_apex.emplace_back(d2, v);
  }
  std::sort(near_apex.begin(), near_apex.end());
  for (const auto& [d2, v] : near_apex) {
    ++counts_.checks;
    if (check_removal(front_, f, v, near_) == RemovalVerdict::kValid) {
      make_removal_tet(front_, tree_, out_, f, v, added_, shrunk_);
      ++counts_.advances;
      return true;
    }
  }
  for (double factor : {1.0, 0.7, 0.45, 0.25}) {
    const double height = factor * regular_height;
    double p[3];
    for (int k = 0; k < 3; ++k) p[k] = g[k] + n[k] / length * height;
    if (orient3d(pa, pb, pc, p) <= 0) continue;
    // Spacing: no front vertex within 0.45 height, no other front face
    // within 0.3 height (the tets they would make later would be flat).
    bool spaced = true;
    for (uint32_t v : near_.vertices)
      spaced = spaced && (v == a || v == b || v == c || squared_distance(front_.point(v), p) >= 0.2 * height * height);
    for (uint32_t h : near_.faces) {
      if (!spaced) break;
      const uint32_t* u = front_.face(h);
      spaced = h == f || squared_point_triangle_distance(p, front_.point(u[0]), front_.point(u[1]),
                                                         front_.point(u[2])) >= 0.09 * height * height;
    }
    if (!spaced) continue;
    const uint32_t v = add_vertex(p);
    ++counts_.checks;
    if (check_removal(front_, f, v, near_) == RemovalVerdict::kValid) {
      make_removal_tet(front_, tree_, out_, f, v, added_, shrunk_);
      ++counts_.vertices_added;
      ++counts_.new_vertex_tets;
      ++counts_.advances;
      return true;
    }
    drop_vertex();
  }
  return false;
}

void TreelessRemover::start_walk() {
  if (walk_mark_.size() < front_.num_face_slots()) walk_mark_.resize(front_.num_face_slots(), 0);
  if (++walk_ == 0) {
    std::fill(walk_mark_.begin(), walk_mark_.end(), 0);
    walk_ = 1;
  }
}

std::vector<uint32_t> TreelessRemover::component_of(uint32_t f, size_t limit) {
  start_walk();
  std::vector<uint32_t> faces = {f}, on_edge;
  walk_mark_[f] = walk_;
  for (size_t head = 0; head < faces.size() && faces.size() <= limit; ++head) {
    const uint32_t* t = front_.face(faces[head]);
    for (int k = 0; k < 3; ++k) {
      faces_across_edge(front_, faces[head], t[k], t[(k + 1) % 3], on_edge);
      for (uint32_t g : on_edge) {
        if (walk_mark_[g] == walk_) continue;
        walk_mark_[g] = walk_;
        faces.push_back(g);
      }
    }
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

TreelessCounts TreelessRemover::run() {
  tree_pass();  // also appends the front vertices `out` lacks
  ids_ = out_.global_ids.size() == out_.num_vertices();
  shared_ = std::any_of(tree_.owner.begin(), tree_.owner.end(), [&](int32_t o) { return o != options_.rank; });
  vertex_budget_ = front_.num_vertices() + 4 * front_.num_alive_faces() + 64;
  deletion_budget_ = 64 * front_.num_alive_faces() + 1024;

  const size_t max_cavity = strategy_ == TreelessStrategy::kSmallCavities ? kMaxSmallCavityFaces : kMaxCavityFaces;
  const size_t stall = stall_rounds(strategy_, options_.stall_rounds);
  std::vector<std::vector<uint32_t>> cavities;
  std::vector<uint32_t> stuck, seeds;
  bool changed = front_.num_alive_faces() > 0;
  size_t smallest = front_.num_alive_faces(), since_smallest = 0;
  while (changed && front_.num_alive_faces() > 0) {
    ++counts_.rounds;
    changed = false;
    const size_t tets_before = out_.num_tets(), deleted_before = counts_.tets_deleted;
    front_cavities(front_, components_, component_first_);
    cavities.clear();
    stuck.clear();
    for (size_t i = 0; i + 1 < component_first_.size(); ++i) {
      const auto first = components_.begin() + static_cast<ptrdiff_t>(component_first_[i]);
      const auto last = components_.begin() + static_cast<ptrdiff_t>(component_first_[i + 1]);
      if (!own_component(first, last)) continue;
      if (last - first <= static_cast<ptrdiff_t>(max_cavity))
        cavities.emplace_back(first, last);
      else
        stuck.insert(stuck.end(), first, last);
    }
    for (const std::vector<uint32_t>& cavity : cavities) {
      bool all_alive = true;
      for (uint32_t f : cavity) all_alive = all_alive && front_.alive(f);
      if (all_alive) fill(cavity);
    }
    // Components too large for one star point: patch cones, then the faces
    // still alive are advanced one by one, smallest face first, each advance
    // followed by tree-supported removals of the faces near it.
    patch_cones(stuck);
    std::vector<std::pair<double, uint32_t>> order;
    for (uint32_t f : stuck)
      if (front_.alive(f)) order.emplace_back(face_size(f), f);
    std::sort(order.begin(), order.end());
    for (const auto& [size, f] : order) {
      if (!front_.alive(f) || !advance_face(f)) continue;
      seeds.assign(added_.begin(), added_.end());
      seeds.insert(seeds.end(), near_.faces.begin(), near_.faces.end());
      local_tree_pass(seeds);
    }
    tree_pass();
    changed = out_.num_tets() != tets_before || counts_.tets_deleted != deleted_before;
    if (front_.num_vertices() >= vertex_budget_ || counts_.tets_deleted >= deletion_budget_) break;
    if (front_.num_alive_faces() < smallest) {
      smallest = front_.num_alive_faces();
      since_smallest = 0;
    } else if (++since_smallest >= stall) {
      counts_.stalled = true;
      break;
    }
  }
  if (front_.num_alive_faces() > 0) flat_cavity_pass();
  if (incidence_) incidence_->drop_dead_tets(out_);
  counts_.faces_left = front_.num_alive_faces();
  counts_.strategy = strategy_;
  return counts_;
}

}  // namespace

TreelessCounts run_treeless_rounds(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                   const RemovalOptions& options, RemovalMemo& memo, TreelessStrategy strategy) {
  return TreelessRemover(front, tree, root, out, options, memo, strategy).run();
}

}  // namespace partet
