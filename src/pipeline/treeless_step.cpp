// treeless_step: the tree-less removals on one rank, or on every rank's
// components and then on rank 0 (see treeless_step.hpp).
#include "pipeline/treeless_step.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "front/treeless_removal.hpp"
#include "front/treeless_rounds.hpp"
#include "parallel/byte_image.hpp"
#include "partition/interface_owners.hpp"

namespace partet {

namespace {

// How the tree-less removals ended when they left faces, for the error:
// " (the tree-less removals tried 4 strategies, leaving 706, 402, 270 and
// 310 faces; this front is what \"cone first\" left, stalled: 64 rounds
// without a smaller front)".
std::string treeless_ending(const TreelessCounts& n) {
  std::string text;
  const std::vector<size_t>& left = n.faces_left_by_attempt;
  if (left.size() > 1) {
    text = "the tree-less removals tried " + std::to_string(left.size()) + " strategies, leaving ";
    for (size_t i = 0; i < left.size(); ++i)
      text += (i == 0 ? "" : i + 1 == left.size() ? " and " : ", ") + std::to_string(left[i]);
    text += std::string(" faces; this front is what \"") + strategy_name(n.strategy) + "\" left";
  }
  if (n.stalled)
    text += (text.empty() ? "the tree-less removals " : ", ") + std::string("stalled: ") +
            std::to_string(stall_rounds(n.strategy, RemovalOptions{}.stall_rounds)) + " rounds without a smaller front";
  return text.empty() ? text : " (" + text + ")";
}

ojson counts_json(const TreelessCounts& n) {
  ojson c;
  c["tets (tree-supported)"] = n.tree_tets;
  c["tets (new vertices)"] = n.new_vertex_tets;
  c["vertices added"] = n.vertices_added;
  c["tets deleted"] = n.tets_deleted;
  c["star fills"] = n.star_fills;
  c["partial cones"] = n.partial_cones;
  c["advances"] = n.advances;
  c["rounds"] = n.rounds;
  c["stalled"] = n.stalled;
  c["strategy"] = strategy_name(n.strategy);
  c["faces left by attempt"] = n.faces_left_by_attempt;
  c["faces left"] = n.faces_left;
  return c;
}

// The work counts of the tree-less removals (tets, vertices, deletions,
// fills, cones, advances, checks; not rounds, faces left or how they
// ended), as one list: what the ranks and rank 0 add up.
std::array<size_t*, 8> work_of(TreelessCounts& n) {
  return {&n.tree_tets,  &n.new_vertex_tets, &n.vertices_added, &n.tets_deleted,
          &n.star_fills, &n.partial_cones,   &n.advances,       &n.checks};
}

// Per tet of `before` (the tets when the ranks' rounds started): its index
// in `now` (the same tets with the deleted ones dropped, order kept, and
// new ones after them), or kNoIndex when it was deleted.
std::vector<uint32_t> surviving_tets(const std::vector<uint32_t>& before, const std::vector<uint32_t>& now) {
  std::vector<uint32_t> index(before.size() / 4, kNoIndex);
  size_t j = 0;
  for (size_t i = 0; i < index.size(); ++i)
    if (4 * j < now.size() && std::equal(&before[4 * i], &before[4 * i] + 4, &now[4 * j])) index[i] = static_cast<uint32_t>(j++);
  return index;
}

// What a rank's rounds did, for rank 0: the vertices they added (from
// `first_new` on), the tets of `before` they deleted, the tets they made
// that are left (in the rank's numbering) and the front's changes.
std::string work_image(const Front& front, size_t first_new, const std::vector<uint32_t>& before, const TetMesh& mesh,
                       const Front::Snapshot& start) {
  std::string out;
  std::vector<double> xyz;
  for (size_t v = first_new; v < front.num_vertices(); ++v)
    xyz.insert(xyz.end(), front.point(static_cast<uint32_t>(v)), front.point(static_cast<uint32_t>(v)) + 3);
  put_array(out, xyz);
  const std::vector<uint32_t> index = surviving_tets(before, mesh.tets);
  std::vector<uint32_t> deleted;
  size_t kept = 0;
  for (size_t i = 0; i < index.size(); ++i) {
    if (index[i] == kNoIndex)
      deleted.push_back(static_cast<uint32_t>(i));
    else
      ++kept;
  }
  put_array(out, deleted);
  put_array(out, mesh.tets.data() + 4 * kept, mesh.tets.size() - 4 * kept);
  const Front::Changes changes = front.changes_since(start);
  put_array(out, changes.closed);
  put_array(out, changes.added);
  return out;
}

// Rank 0's state sent to every rank: the front's vertices beyond the
// initial front's `first` (coordinates and leaves), its faces (slot order),
// the mesh's tets and whether it has global ids, and the memo's standing
// failures (capped, then full; as slots of the front rebuilt from those
// faces).
std::string state_image(const Front& front, size_t first, const TetMesh& mesh, const RootCube& root,
                        const RemovalMemo& memo) {
  std::string out;
  std::vector<double> xyz;
  std::vector<uint32_t> leaf;
  for (size_t v = first; v < front.num_vertices(); ++v) {
    xyz.insert(xyz.end(), front.point(static_cast<uint32_t>(v)), front.point(static_cast<uint32_t>(v)) + 3);
    leaf.push_back(front.vertex_leaf(static_cast<uint32_t>(v)));
  }
  put_array(out, xyz);
  put_array(out, leaf);
  std::vector<uint32_t> faces, slot(front.num_face_slots(), kNoIndex);
  uint32_t n = 0;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f)
    if (front.alive(f)) {
      faces.insert(faces.end(), front.face(f), front.face(f) + 3);
      slot[f] = n++;
    }
  put_array(out, faces);
  put_array(out, mesh.tets);
  put_array(out, std::vector<uint8_t>{static_cast<uint8_t>(!mesh.global_ids.empty())});
  for (const bool full : {false, true}) {
    std::vector<uint32_t> failed;
    for (uint32_t f : standing_failures(front, root, RemovalOptions{}, memo, full)) failed.push_back(slot[f]);
    put_array(out, failed);
  }
  return out;
}

// Every rank's copy of rank 0's state (state_image): the front rebuilt from
// the initial front's vertices, the new ones and the faces, the mesh on
// the same vertices, the memo's standing failures recorded. Returns the
// tets, the ranks' rounds' starting point.
std::vector<uint32_t> take_state(const std::string& state, const InitialFront& initial, const LinearOctree& tree,
                                 const RootCube& root, std::unique_ptr<Front>& front, TetMesh& mesh,
                                 RemovalMemo& memo) {
  size_t pos = 0;
  InitialFront now;
  now.xyz = initial.xyz;
  now.global_ids = initial.global_ids;
  now.vertex_leaf = initial.vertex_leaf;
  const std::vector<double> xyz = get_array<double>(state, pos);
  const std::vector<uint32_t> leaf = get_array<uint32_t>(state, pos);
  for (size_t i = 0; i < leaf.size(); ++i) {
    now.global_ids.push_back(kSteinerVertexId | now.vertex_leaf.size());
    now.vertex_leaf.push_back(leaf[i]);
  }
  now.xyz.insert(now.xyz.end(), xyz.begin(), xyz.end());
  now.faces = get_array<uint32_t>(state, pos);
  std::vector<uint32_t> tets = get_array<uint32_t>(state, pos);
  const bool ids = get_array<uint8_t>(state, pos).at(0) != 0;
  front = std::make_unique<Front>(now, tree, root);
  mesh.xyz = std::move(now.xyz);
  mesh.global_ids = ids ? std::move(now.global_ids) : std::vector<uint64_t>{};
  mesh.tets = tets;
  memo = RemovalMemo{};
  for (const bool full : {false, true}) record_failures(*front, get_array<uint32_t>(state, pos), full, 0, memo);
  return tets;
}

// Rank 0 takes in the other ranks' work (work_image, by rank): their new
// vertices are numbered after its own, rank by rank, the tets they deleted
// are dropped, the tets they made appended, and their front changes merged.
void take_work(const std::vector<std::string>& images, size_t first_new, const std::vector<uint32_t>& before,
               Front& front, LinearOctree& tree, TetMesh& mesh) {
  const bool ids = !mesh.global_ids.empty();
  const std::vector<uint32_t> index = surviving_tets(before, mesh.tets);
  std::vector<uint8_t> dead(mesh.num_tets(), 0);
  std::vector<uint32_t> shrunk;
  for (size_t r = 1; r < images.size(); ++r) {
    size_t at = 0;
    const std::vector<double> xyz = get_array<double>(images[r], at);
    const uint32_t base = static_cast<uint32_t>(front.num_vertices());
    const auto renumber = [&](std::vector<uint32_t> v) {
      for (uint32_t& x : v)
        if (x >= first_new) x = base + (x - static_cast<uint32_t>(first_new));
      return v;
    };
    for (size_t i = 0; i + 3 <= xyz.size(); i += 3) {
      const uint32_t v = front.add_vertex(&xyz[i], kSteinerVertexId | front.num_vertices());
      mesh.xyz.insert(mesh.xyz.end(), &xyz[i], &xyz[i] + 3);
      if (ids) mesh.global_ids.push_back(front.global_ids()[v]);
    }
    for (uint32_t t : get_array<uint32_t>(images[r], at)) {
      PARTET_ASSERT(index[t] != kNoIndex && !dead[index[t]], "two ranks deleted one tet");
      dead[index[t]] = 1;
    }
    const std::vector<uint32_t> made = renumber(get_array<uint32_t>(images[r], at));
    mesh.tets.insert(mesh.tets.end(), made.begin(), made.end());
    dead.resize(mesh.num_tets(), 0);
    Front::Changes changes;
    changes.closed = renumber(get_array<uint32_t>(images[r], at));
    changes.added = renumber(get_array<uint32_t>(images[r], at));
    shrunk.clear();
    front.merge(changes, shrunk);
    mark_done_leaves(front, tree, shrunk);
  }
  size_t kept = 0;
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    if (!dead[t]) std::copy_n(&mesh.tets[4 * t], 4, &mesh.tets[4 * kept++]);
  mesh.tets.resize(4 * kept);
}

}  // namespace

ojson treeless_step(const Comm& comm, const InitialFront& initial, LinearOctree& tree, const RootCube& root,
                    TetMesh& mesh, std::unique_ptr<Front>& front, RemovalMemo& memo, std::string& note,
                    bool on_ranks, const RemovalOptions& options) {
  const bool root_rank = comm.rank() == 0;
  if (comm.size() == 1 || !on_ranks) {
    if (!root_rank) return ojson::object();
    std::fill(tree.owner.begin(), tree.owner.end(), 0);
    const TreelessCounts n = remove_faces_treeless(*front, tree, root, mesh, options, &memo);
    note = treeless_ending(n);
    return counts_json(n);
  }
  // Rounds: every rank takes rank 0's state, the leaves are owned by
  // shares of the front's faces, each rank's rounds close what it owns and
  // rank 0 takes in the others' work.
  TreelessCounts total;
  std::vector<double> rank_s(static_cast<size_t>(comm.size()), 0.0);
  ojson rounds = ojson::array(), left_after = ojson::array();
  double merge_s = 0;
  for (int round = 0;; ++round) {
    std::string state;
    if (root_rank) {
      PARTET_ASSERT(front->num_vertices() == mesh.num_vertices() && mesh.num_vertices() >= initial.vertex_leaf.size(),
                    "the front and the mesh share their vertices");
      state = state_image(*front, initial.vertex_leaf.size(), mesh, root, memo);
    }
    comm.broadcast(state, 0);
    const std::vector<uint32_t> before = take_state(state, initial, tree, root, front, mesh, memo);
    state = std::string();
    std::vector<uint32_t> faces(front->num_face_slots());
    std::iota(faces.begin(), faces.end(), 0u);
    reown_leaves_by_faces(comm, *front, faces, std::vector<int32_t>(faces.size(), 0), root, tree);
    const size_t first_new = front->num_vertices();
    const size_t faces_before = front->num_alive_faces();
    const Front::Snapshot start = front->snapshot();
    RemovalOptions mine_options;
    mine_options.rank = comm.rank();
    mine_options.stall_rounds = kRankStallRounds;
    mine_options.shape_order = options.shape_order;
    Stopwatch clock;
    const TreelessCounts mine =
        run_treeless_rounds(*front, tree, root, mesh, mine_options, memo, TreelessStrategy::kDefault);
    const std::vector<double> seconds = comm.all_gather(clock.wall());
    for (size_t r = 0; r < rank_s.size(); ++r) rank_s[r] += seconds[r];
    rounds.push_back(comm.all_gather(static_cast<int64_t>(mine.rounds)));
    TreelessCounts done = mine;
    std::vector<int64_t> work;
    for (size_t* count : work_of(done)) work.push_back(static_cast<int64_t>(*count));
    comm.sum(work.data(), work.size());
    const auto into = work_of(total);
    for (size_t k = 0; k < work.size(); ++k) *into[k] += static_cast<size_t>(work[k]);
    const std::vector<std::string> images =
        comm.gather(root_rank ? std::string() : work_image(*front, first_new, before, mesh, start), 0);
    if (root_rank) {
      clock.restart();
      take_work(images, first_new, before, *front, tree, mesh);
      merge_s += clock.wall();
    }
    // Another round while the ranks' rounds closed a good share of the
    // faces (kTreelessRankRounds at most).
    const size_t left = static_cast<size_t>(comm.max(static_cast<int64_t>(root_rank ? front->num_alive_faces() : 0)));
    left_after.push_back(left);
    if (left == 0 || round + 1 == kTreelessRankRounds || 4 * left > 3 * faces_before) break;
  }
  ojson c;
  c["rank s per rank"] = rank_s;
  c["rounds per rank"] = rounds;
  c["faces left after ranks"] = left_after;
  if (!root_rank) {
    front.reset();
    mesh = TetMesh{};
    memo = RemovalMemo{};
    return ojson::object();
  }
  c["merge s"] = merge_s;

  // What no rank could close, on rank 0 with every leaf.
  std::fill(tree.owner.begin(), tree.owner.end(), 0);
  TreelessCounts rest;
  rest.faces_left_by_attempt = {0};
  if (front->num_alive_faces() > 0) rest = remove_faces_treeless(*front, tree, root, mesh, options, &memo);
  const auto into = work_of(rest), from = work_of(total);
  for (size_t k = 0; k < into.size(); ++k) *into[k] += *from[k];
  note = treeless_ending(rest);
  c.update(counts_json(rest));
  return c;
}

}  // namespace partet
