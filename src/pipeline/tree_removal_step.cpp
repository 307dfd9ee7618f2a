// tree_removal_step: the two passes on one rank, or on every rank's copy of
// the front with the other ranks' tets and front changes merged on rank 0
// (see tree_removal_step.hpp).
#include "pipeline/tree_removal_step.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "parallel/byte_image.hpp"
#include "partition/leaf_owners.hpp"

namespace partet {

namespace {

// The shaped pass (with `shaped_memo`), then the plain one (with `memo`);
// their counts summed.
RemovalCounts two_passes(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& mesh, int rank,
                         RemovalMemo& shaped_memo, RemovalMemo& memo) {
  // Well-shaped tets first (the best few targets of each face); the
  // nearly flat ones a front may need only where nothing better was found.
  RemovalOptions shaped;
  shaped.rank = rank;
  shaped.min_quality = kShapedRemovalQuality;
  RemovalOptions plain;
  plain.rank = rank;
  const RemovalCounts first = remove_faces_tree_supported(front, tree, root, mesh, shaped, nullptr, &shaped_memo);
  RemovalCounts n = remove_faces_tree_supported(front, tree, root, mesh, plain, nullptr, &memo);
  n.tets += first.tets;
  n.passes += first.passes;
  n.checks += first.checks;
  n.skipped_checks += first.skipped_checks;
  return n;
}

// A rank's tets made after `first_tet` and its front's changes.
std::string removal_image(const TetMesh& mesh, size_t first_tet, const Front::Changes& changes) {
  std::string out;
  put_array(out, mesh.tets.data() + 4 * first_tet, mesh.tets.size() - 4 * first_tet);
  for (const std::vector<uint32_t>* v : {&changes.closed, &changes.added, &changes.taken}) put_array(out, *v);
  return out;
}

}  // namespace

ojson tree_removal_step(const Comm& comm, const InitialFront& initial, LinearOctree& tree, const RootCube& root,
                        TetMesh& mesh, const RankLeaves& ranks, std::unique_ptr<Front>& front, RemovalMemo& memo) {
  const bool root_rank = comm.rank() == 0;
  const bool distributed = comm.size() > 1;
  ojson c;
  front = std::make_unique<Front>(initial, tree, root);
  size_t tets = 0, passes = 0, checks = 0, skipped = 0;
  RemovalMemo shaped_memo;  // the shaped passes' failures (rank 0's, for its finishing passes)
  if (distributed) {
    PARTET_ASSERT(ranks.own && ranks.separators, "the ranks' leaves are needed on P > 1 ranks");
    set_leaf_owners(comm, *ranks.own, *ranks.separators, root, tree);
    const size_t core_tets = mesh.num_tets(), slots = front->num_face_slots();
    const uint32_t first_free = static_cast<uint32_t>(front->num_vertices() - initial.free_vertices);
    Stopwatch clock;
    // Rank 0 keeps what its passes learnt for the passes that finish.
    const RemovalCounts mine = two_passes(*front, tree, root, mesh, comm.rank(), shaped_memo, memo);
    const double rank_s = clock.wall();
    c["tets per rank"] = comm.all_gather(static_cast<int64_t>(mine.tets));
    c["faces left per rank"] = comm.all_gather(static_cast<int64_t>(mine.faces_left));
    c["foreign faces per rank"] = comm.all_gather(static_cast<int64_t>(mine.foreign_faces));
    c["rank s per rank"] = comm.all_gather(rank_s);
    const std::vector<std::string> images = comm.gather(
        root_rank ? std::string() : removal_image(mesh, core_tets, front->changes_since(slots, first_free)), 0);
    tets = static_cast<size_t>(comm.sum(static_cast<int64_t>(mine.tets)));
    passes = mine.passes;
    checks = static_cast<size_t>(comm.sum(static_cast<int64_t>(mine.checks)));
    skipped = static_cast<size_t>(comm.sum(static_cast<int64_t>(mine.skipped_checks)));
    if (!root_rank) {
      front.reset();
      mesh = TetMesh{};
      return ojson::object();
    }
    // The other ranks' tets join the mesh, and their changes rank 0's front.
    clock.restart();
    std::vector<uint32_t> shrunk;
    for (size_t r = 1; r < images.size(); ++r) {
      size_t pos = 0;
      const std::vector<uint32_t> theirs = get_array<uint32_t>(images[r], pos);
      mesh.tets.insert(mesh.tets.end(), theirs.begin(), theirs.end());
      Front::Changes changes;
      changes.closed = get_array<uint32_t>(images[r], pos);
      changes.added = get_array<uint32_t>(images[r], pos);
      changes.taken = get_array<uint32_t>(images[r], pos);
      shrunk.clear();
      front->merge(changes, shrunk);
      mark_done_leaves(*front, tree, shrunk);
    }
    c["merge s"] = clock.wall();
    std::fill(tree.owner.begin(), tree.owner.end(), 0);
  }
  const RemovalCounts n = two_passes(*front, tree, root, mesh, 0, shaped_memo, memo);
  // Gap vertices no tet took are dropped: the tree-less removals place
  // their own where a cavity needs one, and a free vertex inside a cavity
  // would only block its fills.
  const size_t unused = drop_free_vertices(*front, tree);
  // The closed faces (most slots by now) go before the tree-less removals
  // allocate theirs.
  memo.renumber(front->compact());
  if (distributed) c["tets on rank 0 after"] = n.tets;
  c["tets"] = tets + n.tets;
  c["faces left"] = n.faces_left;
  c["passes"] = passes + n.passes;
  c["checks"] = checks + n.checks;
  c["checks skipped"] = skipped + n.skipped_checks;
  c["gap vertices used"] = initial.free_vertices - unused;
  return c;
}

}  // namespace partet
