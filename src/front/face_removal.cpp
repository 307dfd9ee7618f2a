// Tree-supported face removals: the queue, the neighbourhood and target
// ordering, and the bookkeeping after each tet (see face_removal.hpp).
#include "front/face_removal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "core/predicates.hpp"
#include "core/shape_measure.hpp"
#include "front/face_queue.hpp"
#include "front/removal_checks.hpp"
#include "octree/range_query.hpp"
#include "octree/sizing.hpp"

namespace partet {

namespace {

// Targets a face tries in a capped pass: three quarters of the faces take
// their first target, and a face whose first 8 fail rarely succeeds soon.
constexpr size_t kCappedTargets = 8;
// Targets a face tries in a full pass: long faces can have hundreds, and
// past the first few dozen they almost never make a valid tet.
constexpr size_t kFullTargets = 64;
// See Remover::run: a productive pass makes a tet per this many waiting faces.
constexpr size_t kProductive = 4;

// The queue's size classes: the bits of a positive double's exponent and
// its first mantissa bit, which grow with it; one class spans a factor
// √2 of squared length (2^(1/4) of length).
constexpr int kSizeClassShift = 51;

uint64_t size_class(double squared_length) {
  uint64_t bits;
  std::memcpy(&bits, &squared_length, sizeof bits);
  return bits >> kSizeClassShift;
}

struct Target {
  double score;
  uint32_t vertex;
};

double squared_distance(const double* x, const double* y) {
  const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
  return dx * dx + dy * dy + dz * dz;
}

// The target order's weights (face_removal.hpp): a face closed counts as
// this much sphere height, in base circumradii, and q (at most 1) this much.
constexpr double kClosingWeight = 0.05;
constexpr double kShapeWeight = 0.01;

// The spheres through a base face (a, b, c): their centres lie on the line
// through the face's circumcentre along its normal.
class BaseSpheres {
 public:
  BaseSpheres(const double* a, const double* b, const double* c) : a_(a) {
    double u[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = b[k] - a[k];
      w[k] = c[k] - a[k];
    }
    cross(u, w, normal_);
    const double uu = dot(u, u), ww = dot(w, w), nn = dot(normal_, normal_);
    // The circumcentre: a + ((|u|² w - |w|² u) × n) / (2 |n|²).
    double m[3], x[3];
    for (int k = 0; k < 3; ++k) m[k] = uu * w[k] - ww * u[k];
    cross(m, normal_, x);
    for (int k = 0; k < 3; ++k) centre_[k] = a[k] + x[k] / (2 * nn);
    squared_radius_ = squared_distance(centre_, a);
    scale_ = std::sqrt(nn / squared_radius_);
  }

  // The height of the centre of the sphere through the face and q (q on
  // the normal's side) above the circumcentre, along the unit normal, in
  // circumradii: the smallest is the vertex the sphere meets first as it
  // sweeps from the face's plane to the normal's side, so that no other
  // target lies inside its sphere. +inf (last) when doubles cannot tell
  // (a flat face, or q's height under their rounding): NaN never reaches
  // the sort.
  double height(const double* q) const {
    const double d[3] = {q[0] - a_[0], q[1] - a_[1], q[2] - a_[2]};
    const double above = dot(normal_, d);
    const double h = (squared_distance(q, centre_) - squared_radius_) * scale_ / (2 * above);
    return above > 0 && !std::isnan(h) ? h : std::numeric_limits<double>::infinity();
  }

 private:
  static double dot(const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
  static void cross(const double* x, const double* y, double* z) {
    z[0] = x[1] * y[2] - x[2] * y[1];
    z[1] = x[2] * y[0] - x[0] * y[2];
    z[2] = x[0] * y[1] - x[1] * y[0];
  }

  const double* a_;
  double normal_[3];
  double centre_[3];
  double squared_radius_;
  double scale_;  // |n| / circumradius: turns the height along n into circumradii
};

// Everything one call keeps between faces.
class Remover {
 public:
  Remover(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out, const RemovalOptions& options,
          RemovalMemo& memo)
      : front_(front), tree_(tree), root_(root), out_(out), options_(options), memo_(memo) {}

  RemovalCounts run(const std::vector<uint32_t>* seeds);

 private:
  // Tries one face, its best kCappedTargets targets or, when `full`, all of
  // them; true when a tet was made.
  bool try_face(uint32_t f, bool full);
  void neighbourhood(uint32_t f);
  // The grid cells of `leaves` (6 each, LeafCover::cells).
  void cells_of(const std::vector<size_t>& leaves, std::vector<uint32_t>& cells) const;
  bool neighbourhood_changed_since(uint64_t stamp) const;
  bool neighbourhood_foreign() const;
  // True when face f's last failure (this call's or an earlier one's, see
  // RemovalMemo) checked target p and what blocked it then still does
  // (still_blocked): checking it again must fail; `why` is set to that
  // blocker.
  bool known_blocked(uint32_t f, uint32_t p, size_t hint, RemovalBlocker& why) const;
  // Keeps why face f failed (blocked_, the targets it checked) in the memo.
  void remember_failure(uint32_t f);
  void make_tet(uint32_t f, uint32_t p);
  // closers_ = the third vertex of every other alive face along an edge of
  // face f: a target closes one face for each time it appears there.
  void find_closers(uint32_t f);
  // near_ = the front over the leaves that meet the tet's bounding box.
  void gather_around_tet(const double* pa, const double* pb, const double* pc, const double* pp);

  Front& front_;
  LinearOctree& tree_;
  const RootCube& root_;
  TetMesh& out_;
  const RemovalOptions& options_;
  RemovalMemo& memo_;
  RemovalCounts counts_;

  FaceQueue queue_;
  QueuedFace entry(uint32_t f) const;
  std::vector<QueuedFace> batch_;  // faces to load into the queue as one run
  std::vector<uint8_t> foreign_;     // per face slot: skipped for a foreign leaf
  double box_lo_[3] = {0, 0, 0}, box_hi_[3] = {0, 0, 0};
  // This rank owns every leaf: no neighbourhood is foreign, and it needs
  // only the leaves the front has been listed in (Front::listed_leaves).
  bool owns_every_leaf_ = false;
  std::vector<size_t> leaves_;      // over the neighbourhood box: where targets come from
  std::vector<uint32_t> leaf_cells_;  // their grid cells, lo then hi (6 per leaf)
  std::vector<size_t> tet_leaves_;  // over one candidate tet's box: what its checks need
  std::vector<uint32_t> tet_cells_;  // their grid cells when they cover it (make_tet)
  NearFront near_;
  Suspects suspects_;  // what blocked this face's targets so far: tested first
  const NearFront no_front_;  // to test the suspects alone
  std::vector<Target> targets_;
  std::vector<uint32_t> closers_;
  std::vector<uint32_t> added_, shrunk_;

  std::vector<RemovalMemo::Blocked> blocked_;  // the current try's checked targets
  void drop_garbage_failures();
};

void Remover::neighbourhood(uint32_t f) {
  removal_neighbourhood(front_, root_, f, options_, box_lo_, box_hi_);
  uint32_t glo[3], ghi[3];
  grid_range(root_, box_lo_, box_hi_, glo, ghi);
  if (owns_every_leaf_)
    front_.query().leaves_in_range(glo, ghi, leaves_, front_.listed_leaves());
  else
    front_.query().leaves_in_range(glo, ghi, leaves_);
  cells_of(leaves_, leaf_cells_);
}

void Remover::cells_of(const std::vector<size_t>& leaves, std::vector<uint32_t>& cells) const {
  cells.resize(6 * leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) front_.query().leaf_cells(leaves[i], &cells[6 * i], &cells[6 * i + 3]);
}

bool Remover::neighbourhood_changed_since(uint64_t stamp) const {
  for (size_t leaf : leaves_)
    if (front_.leaf_changed(leaf) > stamp) return true;
  return false;
}

bool Remover::neighbourhood_foreign() const {
  for (size_t leaf : leaves_)
    if (tree_.owner[leaf] != options_.rank) return true;
  return false;
}

void Remover::make_tet(uint32_t f, uint32_t p) {
  // Targets lie in the neighbourhood box, and so does the tet's box. Its
  // new faces need every leaf there, not only the listed ones: with the
  // listed leaves alone, the leaves over the tet's box are the cover.
  if (owns_every_leaf_) {
    const uint32_t* t = front_.face(f);
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min({front_.point(t[0])[k], front_.point(t[1])[k], front_.point(t[2])[k], front_.point(p)[k]});
      hi[k] = std::max({front_.point(t[0])[k], front_.point(t[1])[k], front_.point(t[2])[k], front_.point(p)[k]});
    }
    uint32_t glo[3], ghi[3];
    grid_range(root_, lo, hi, glo, ghi);
    front_.query().leaves_in_range(glo, ghi, tet_leaves_);
    cells_of(tet_leaves_, tet_cells_);
  }
  const LeafCover cover = owns_every_leaf_ ? LeafCover{tet_leaves_, tet_cells_} : LeafCover{leaves_, leaf_cells_};
  make_removal_tet(front_, tree_, out_, f, p, added_, shrunk_, &cover);
  ++counts_.tets;
  for (uint32_t g : added_) queue_.push(entry(g));
  foreign_.resize(front_.num_face_slots(), 0);
}

bool Remover::known_blocked(uint32_t f, uint32_t p, size_t hint, RemovalBlocker& why) const {
  const RemovalMemo::Record* failure = memo_.find(f);
  if (!failure) return false;
  // Targets mostly keep their rank between tries: look at `hint` first.
  for (size_t k = 0; k < failure->count; ++k) {
    const RemovalMemo::Blocked& b = memo_.blocked_pool[failure->first + (hint + k) % failure->count];
    if (b.target != p) continue;
    if (!still_blocked(front_, f, p, b.why)) return false;
    why = b.why;
    return true;
  }
  return false;
}

void Remover::remember_failure(uint32_t f) {
  memo_.live_blocked -= memo_.record(f).count;
  if (memo_.blocked_pool.size() > 1024 && memo_.blocked_pool.size() > 2 * memo_.live_blocked) drop_garbage_failures();
  PARTET_ASSERT(memo_.blocked_pool.size() + blocked_.size() < kNoIndex, "failure pool overflow");
  RemovalMemo::Record& failure = memo_.record(f);  // looked up again: packing moves records
  failure.first = static_cast<uint32_t>(memo_.blocked_pool.size());
  failure.count = static_cast<uint32_t>(blocked_.size());
  memo_.blocked_pool.insert(memo_.blocked_pool.end(), blocked_.begin(), blocked_.end());
  memo_.live_blocked += blocked_.size();
}

void Remover::drop_garbage_failures() {
  std::vector<RemovalMemo::Blocked> kept;
  kept.reserve(memo_.live_blocked);
  memo_.live_blocked = 0;
  // Closed faces lose their records (nothing reads a closed face's), the
  // others keep their failure times and their runs, packed.
  std::vector<uint32_t> recorded;
  recorded.reserve(memo_.recorded.size());
  for (uint32_t f : memo_.recorded) {
    if (!front_.alive(f)) {
      memo_.records.erase(f);
      continue;
    }
    recorded.push_back(f);
    RemovalMemo::Record& failure = *memo_.records.find(f);
    if (failure.count == 0) continue;
    const uint32_t first = static_cast<uint32_t>(kept.size());
    kept.insert(kept.end(), memo_.blocked_pool.begin() + failure.first,
                memo_.blocked_pool.begin() + failure.first + failure.count);
    failure.first = first;
    memo_.live_blocked += failure.count;
  }
  memo_.recorded.swap(recorded);
  memo_.blocked_pool.swap(kept);
}

QueuedFace Remover::entry(uint32_t f) const {
  const uint32_t* t = front_.face(f);
  const double* p[3] = {front_.point(t[0]), front_.point(t[1]), front_.point(t[2])};
  const double size = std::max({squared_distance(p[0], p[1]), squared_distance(p[1], p[2]), squared_distance(p[2], p[0])});
  double centroid[3];
  for (int k = 0; k < 3; ++k) centroid[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
  uint32_t cell[3];
  grid_cell(root_, centroid, cell);
  return {size_class(size), morton_key(cell[0], cell[1], cell[2]), f};
}

bool Remover::try_face(uint32_t f, bool full) {
  const uint32_t* t = front_.face(f);
  const uint32_t a = t[0], b = t[1], c = t[2];
  const double *pa = front_.point(a), *pb = front_.point(b), *pc = front_.point(c);
  const PlaneSide base_side(pa, pb, pc);
  const BaseSpheres spheres(pa, pb, pc);
  targets_.clear();
  find_closers(f);
  for (size_t leaf : leaves_)
    for (uint32_t v = front_.first_vertex(leaf); v != kNoIndex; v = front_.next_vertex(v)) {
      if (v == a || v == b || v == c) continue;
      const double* q = front_.point(v);
      bool inside = true;
      for (int k = 0; k < 3; ++k) inside = inside && box_lo_[k] <= q[k] && q[k] <= box_hi_[k];
      if (!inside || base_side(q) <= 0) continue;
      const int closed = static_cast<int>(std::count(closers_.begin(), closers_.end(), v));
      // The shape is measured in doubles: a tet too flat for them (its
      // height under the coordinates' rounding) may measure 0 or less
      // though orient3d is positive (RemovalOptions::close_flat_cavities).
      double shape = shape_measure(pa, pb, pc, q);
      if (closed == 3 && options_.close_flat_cavities) shape = std::max(shape, std::numeric_limits<double>::min());
      if (shape < options_.min_quality) continue;
      const double score = options_.shape_order ? shape * (1 + closed)
                                                : kClosingWeight * closed + kShapeWeight * shape - spheres.height(q);
      targets_.push_back({score, v});
    }
  std::sort(targets_.begin(), targets_.end(), [](const Target& x, const Target& y) {
    return x.score != y.score ? x.score > y.score : x.vertex < y.vertex;
  });
  // The first targets are checked against the front around their tet
  // alone (most faces take their first target); the rest, in full mode
  // only, against one gather over the whole neighbourhood.
  // A target this face's last failure found blocked by what still blocks
  // it is not checked again.
  const size_t n = std::min(targets_.size(), full ? kFullTargets : kCappedTargets);
  blocked_.clear();
  suspects_.clear();
  bool near_is_neighbourhood = false;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t p = targets_[i].vertex;
    RemovalBlocker why;
    if (known_blocked(f, p, i, why)) {
      ++counts_.skipped_checks;
      blocked_.push_back({p, why});
      suspects_.add(why);
      continue;
    }
    ++counts_.checks;
    // What blocked the earlier targets goes first, before any gather: the
    // far targets of a long face mostly fail on it.
    const bool gathered = i >= kCappedTargets && near_is_neighbourhood;
    if (!gathered && !suspects_.empty() &&
        check_removal(front_, f, p, no_front_, &why, &suspects_) != RemovalVerdict::kValid) {
      blocked_.push_back({p, why});
      continue;
    }
    if (i < kCappedTargets) {
      gather_around_tet(pa, pb, pc, front_.point(p));
    } else if (!near_is_neighbourhood) {
      gather_near_front(front_, leaves_, near_);
      near_is_neighbourhood = true;
    }
    if (check_removal(front_, f, p, near_, &why, gathered ? &suspects_ : nullptr) == RemovalVerdict::kValid) {
      make_tet(f, p);
      return true;
    }
    blocked_.push_back({p, why});
    suspects_.add(why);
  }
  remember_failure(f);
  return false;
}

void Remover::find_closers(uint32_t f) {
  const uint32_t* t = front_.face(f);
  closers_.clear();
  for (int k = 0; k < 3; ++k) {
    const uint32_t u = t[k], w = t[(k + 1) % 3];
    front_.for_each_other_face_on_edge(f, u, w, [&](uint32_t g) {
      const uint32_t* h = front_.face(g);
      for (int i = 0; i < 3; ++i)
        if (h[i] != u && h[i] != w) closers_.push_back(h[i]);
    });
  }
}

void Remover::gather_around_tet(const double* pa, const double* pb, const double* pc, const double* pp) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min({pa[k], pb[k], pc[k], pp[k]});
    hi[k] = std::max({pa[k], pb[k], pc[k], pp[k]});
  }
  uint32_t glo[3], ghi[3];
  grid_range(root_, lo, hi, glo, ghi);
  // The tet's box lies in the neighbourhood box (targets are taken inside
  // it), so its leaves are those of the neighbourhood that overlap it: the
  // same list, in the same order, as a range query.
  leaves_in_cover(LeafCover{leaves_, leaf_cells_}, glo, ghi, tet_leaves_);
  gather_near_front(front_, tet_leaves_, near_);
}

RemovalCounts Remover::run(const std::vector<uint32_t>* seeds) {
  const size_t have = out_.num_vertices();
  PARTET_ASSERT(have <= front_.num_vertices(), "output mesh has more vertices than the front");
  const bool ids = out_.global_ids.size() == have;
  owns_every_leaf_ = std::all_of(tree_.owner.begin(), tree_.owner.end(), [&](int32_t o) { return o == options_.rank; });
  out_.xyz.insert(out_.xyz.end(), front_.xyz().begin() + 3 * have, front_.xyz().end());
  if (ids) out_.global_ids.insert(out_.global_ids.end(), front_.global_ids().begin() + have, front_.global_ids().end());

  memo_.use_min_quality(options_.min_quality);
  foreign_.assign(front_.num_face_slots(), 0);
  batch_.clear();
  if (seeds) {
    for (uint32_t f : *seeds)
      if (front_.alive(f)) batch_.push_back(entry(f));
  } else {
    for (uint32_t f = 0; f < front_.num_face_slots(); ++f)
      if (front_.alive(f)) batch_.push_back(entry(f));
  }
  queue_.load(batch_);
  std::vector<uint32_t> waiting;
  bool full = false;  // checking every target of a face, not only the best ones
  while (!queue_.empty()) {
    ++counts_.passes;
    const size_t made_before = counts_.tets;
    waiting.clear();
    while (!queue_.empty()) {
      const uint32_t f = queue_.pop().face;
      if (!front_.alive(f)) continue;
      neighbourhood(f);
      if (neighbourhood_foreign()) {
        foreign_[f] = 1;
        continue;
      }
      const uint32_t failed_at = memo_.failed_at(f, full);
      if (failed_at != kNeverFailed && !neighbourhood_changed_since(failed_at)) {
        waiting.push_back(f);
        continue;
      }
      if (!try_face(f, full)) {
        PARTET_ASSERT(front_.changes() < kNeverFailed, "more front changes than the memo can stamp");
        const uint32_t now = static_cast<uint32_t>(front_.changes());
        RemovalMemo::Record& record = memo_.record(f);
        record.failed_capped_at = now;
        if (full) record.failed_full_at = now;
        waiting.push_back(f);
      }
    }
    // A pass is productive when it makes a tet for every kProductive faces
    // left waiting; later passes then pay off. After an unproductive capped
    // pass comes one full pass; after an unproductive full pass, what is left
    // goes to the tree-less removals, which close it for less.
    const bool productive = (counts_.tets - made_before) * kProductive >= std::max<size_t>(waiting.size(), 1);
    if (full && !productive) break;
    full = !productive;
    batch_.clear();
    for (uint32_t g : waiting) batch_.push_back(entry(g));
    queue_.load(batch_);
  }
  for (uint32_t f = 0; f < front_.num_face_slots(); ++f)
    if (front_.alive(f)) {
      ++counts_.faces_left;
      counts_.foreign_faces += foreign_[f];
    }
  return counts_;
}

}  // namespace

void removal_neighbourhood(const Front& front, const RootCube& root, uint32_t f, const RemovalOptions& options,
                           double* lo, double* hi) {
  const uint32_t* t = front.face(f);
  const double* p[3] = {front.point(t[0]), front.point(t[1]), front.point(t[2])};
  const double longest =
      std::sqrt(std::max({squared_distance(p[0], p[1]), squared_distance(p[1], p[2]), squared_distance(p[2], p[0])}));
  // The box is centred ahead of the face, where targets make good tets.
  double normal[3];
  const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
  const double w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
  normal[0] = u[1] * w[2] - u[2] * w[1];
  normal[1] = u[2] * w[0] - u[0] * w[2];
  normal[2] = u[0] * w[1] - u[1] * w[0];
  const double norm = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  const double ahead = norm > 0 ? options.ahead * longest / norm : 0;
  const double half = options.reach * longest;
  for (int k = 0; k < 3; ++k) {
    const double centre = (p[0][k] + p[1][k] + p[2][k]) / 3 + ahead * normal[k];
    lo[k] = std::max(std::min({p[0][k], p[1][k], p[2][k], centre - half}), root.origin[k]);
    hi[k] = std::min(std::max({p[0][k], p[1][k], p[2][k], centre + half}), root.origin[k] + root.edge());
  }
}

void removal_neighbourhood_leaves(const Front& front, const RootCube& root, uint32_t f, const RemovalOptions& options,
                                  std::vector<size_t>& leaves, bool listed_only) {
  double lo[3], hi[3];
  removal_neighbourhood(front, root, f, options, lo, hi);
  uint32_t glo[3], ghi[3];
  grid_range(root, lo, hi, glo, ghi);
  if (listed_only)
    front.query().leaves_in_range(glo, ghi, leaves, front.listed_leaves());
  else
    front.query().leaves_in_range(glo, ghi, leaves);
}

std::vector<uint32_t> standing_failures(const Front& front, const RootCube& root, const RemovalOptions& options,
                                        const RemovalMemo& memo, bool full) {
  std::vector<uint32_t> faces;
  std::vector<size_t> leaves;
  for (uint32_t f : memo.recorded) {
    const uint32_t failed_at = memo.failed_at(f, full);
    if (!front.alive(f) || failed_at == kNeverFailed) continue;
    // Only a listed leaf has been stamped.
    removal_neighbourhood_leaves(front, root, f, options, leaves, true);
    if (std::none_of(leaves.begin(), leaves.end(), [&](size_t leaf) { return front.leaf_changed(leaf) > failed_at; }))
      faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

void record_failures(const Front& front, const std::vector<uint32_t>& faces, bool full, double min_quality,
                     RemovalMemo& memo) {
  memo.use_min_quality(min_quality);
  PARTET_ASSERT(front.changes() < kNeverFailed, "more front changes than the memo can stamp");
  const uint32_t now = static_cast<uint32_t>(front.changes());
  for (uint32_t f : faces) {
    RemovalMemo::Record& record = memo.record(f);
    record.failed_capped_at = now;
    if (full) record.failed_full_at = now;
  }
}

uint64_t RemovalMemo::SlotTraits::hash(uint32_t f) { return hash_mix(f); }

RemovalMemo::Record& RemovalMemo::record(uint32_t f) {
  const size_t before = records.size();
  Record& r = records.get_or_insert(f, Record{});
  if (records.size() != before) recorded.push_back(f);
  return r;
}

uint32_t RemovalMemo::failed_at(uint32_t f, bool full) const {
  const Record* r = records.find(f);
  if (!r) return kNeverFailed;
  return full ? r->failed_full_at : r->failed_capped_at;
}

void RemovalMemo::use_min_quality(double q) {
  if (min_quality == q) return;
  min_quality = q;
  for (uint32_t f : recorded) {
    Record& r = *records.find(f);
    r.failed_capped_at = r.failed_full_at = kNeverFailed;
  }
}

void RemovalMemo::renumber(const std::vector<uint32_t>& new_face) {
  std::vector<uint32_t> old_faces = recorded;
  std::sort(old_faces.begin(), old_faces.end());
  FlatHashMap<uint32_t, Record, SlotTraits> kept_records;
  std::vector<uint32_t> kept_faces;
  std::vector<Blocked> pool;
  for (uint32_t f : old_faces) {
    if (f >= new_face.size() || new_face[f] == kNoIndex) continue;
    const Record& old = *records.find(f);
    Record kept{old.failed_capped_at, old.failed_full_at, static_cast<uint32_t>(pool.size()), 0};
    for (uint32_t k = 0; k < old.count; ++k) {
      Blocked b = blocked_pool[old.first + k];
      if (blocked_by_face(b.why)) {
        if (b.why.entity >= new_face.size() || new_face[b.why.entity] == kNoIndex) continue;
        b.why.entity = new_face[b.why.entity];
      }
      pool.push_back(b);
      ++kept.count;
    }
    if (kept.count == 0) kept.first = kNoIndex;
    kept_records.get_or_insert(new_face[f], kept);
    kept_faces.push_back(new_face[f]);
  }
  records = std::move(kept_records);
  recorded.swap(kept_faces);
  blocked_pool.swap(pool);
  live_blocked = blocked_pool.size();
}

void make_removal_tet(Front& front, LinearOctree& tree, TetMesh& out, uint32_t f, uint32_t p,
                      std::vector<uint32_t>& added, std::vector<uint32_t>& shrunk, const LeafCover* cover) {
  const uint32_t* t = front.face(f);
  out.tets.insert(out.tets.end(), {t[0], t[1], t[2], p});
  added.clear();
  shrunk.clear();
  front.apply_tet(f, p, added, shrunk, cover);
  mark_done_leaves(front, tree, shrunk);
}

void mark_done_leaves(const Front& front, LinearOctree& tree, const std::vector<uint32_t>& shrunk) {
  for (uint32_t leaf : shrunk) {
    LeafClass& cls = tree.cls[leaf];
    if ((cls == LeafClass::kBoundary || cls == LeafClass::kTooClose) && front.leaf_front_empty(leaf))
      cls = LeafClass::kDone;
  }
}

size_t drop_free_vertices(Front& front, LinearOctree& tree) {
  std::vector<uint32_t> shrunk;
  const size_t dropped = front.drop_free_vertices(shrunk);
  mark_done_leaves(front, tree, shrunk);
  return dropped;
}

RemovalCounts remove_faces_tree_supported(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                          const RemovalOptions& options, const std::vector<uint32_t>* seeds,
                                          RemovalMemo* memo) {
  PARTET_ASSERT(tree.size() == tree.owner.size() && tree.size() == tree.cls.size(), "tree arrays disagree");
  RemovalMemo own;
  return Remover(front, tree, root, out, options, memo ? *memo : own).run(seeds);
}

}  // namespace partet
