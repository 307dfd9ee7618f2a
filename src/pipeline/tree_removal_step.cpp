// tree_removal_step: the two passes on one rank; on P ranks, each pass in
// rounds on every rank's copy of the front, the interfaces left by one
// round spread over the ranks for the next, and what is left done by rank
// 0 alone (see tree_removal_step.hpp).
#include "pipeline/tree_removal_step.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "parallel/byte_image.hpp"
#include "partition/interface_owners.hpp"
#include "partition/leaf_owners.hpp"

namespace partet {

namespace {

// One pass of the tree-supported removals taking targets of quality at
// least `quality`, in Delaunay order or, with `shape_order`, best shape
// first (RemovalOptions::shape_order), from `seeds` (every alive face when
// null).
RemovalCounts one_pass(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& mesh, int rank, double quality,
                       bool shape_order, RemovalMemo& memo, const std::vector<uint32_t>* seeds) {
  RemovalOptions options;
  options.rank = rank;
  options.shape_order = shape_order;
  options.min_quality = quality;
  return remove_faces_tree_supported(front, tree, root, mesh, options, seeds, &memo);
}

// The work counts of `x` (tets, passes, checks, skipped checks) added to
// `into`.
void add_work(RemovalCounts& into, const RemovalCounts& x) {
  into.tets += x.tets;
  into.passes += x.passes;
  into.checks += x.checks;
  into.skipped_checks += x.skipped_checks;
}

// The shaped pass (with `shaped_memo`), then the plain one (with `memo`),
// over every alive face; their counts summed.
RemovalCounts two_passes(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& mesh, int rank,
                         bool shape_order, RemovalMemo& shaped_memo, RemovalMemo& memo) {
  // Well-shaped tets first (the best few targets of each face); the
  // nearly flat ones a front may need only where nothing better was found.
  const RemovalCounts first =
      one_pass(front, tree, root, mesh, rank, kShapedRemovalQuality, shape_order, shaped_memo, nullptr);
  RemovalCounts n = one_pass(front, tree, root, mesh, rank, 0, shape_order, memo, nullptr);
  add_work(n, first);
  return n;
}

std::string changes_image(const Front::Changes& changes) {
  std::string out;
  for (const std::vector<uint32_t>* v : {&changes.closed, &changes.added, &changes.taken}) put_array(out, *v);
  return out;
}

// Every other rank's front changes (images by rank, changes_image) merged
// into this rank's front, in rank order.
void merge_others(const Comm& comm, const std::vector<std::string>& images, Front& front, LinearOctree& tree) {
  std::vector<uint32_t> shrunk;
  for (size_t r = 0; r < images.size(); ++r) {
    if (static_cast<int>(r) == comm.rank()) continue;
    size_t pos = 0;
    Front::Changes changes;
    changes.closed = get_array<uint32_t>(images[r], pos);
    changes.added = get_array<uint32_t>(images[r], pos);
    changes.taken = get_array<uint32_t>(images[r], pos);
    shrunk.clear();
    front.merge(changes, shrunk);
    mark_done_leaves(front, tree, shrunk);
  }
}

// This rank's failures in its plain passes' `memo` that still stand
// (standing_failures), in capped and in full passes, as vertex triples:
// rank 0 records them (take_failures) and the tree-less removals' first
// pass skips those faces instead of failing them again.
void put_failures(const Front& front, const RootCube& root, const RemovalMemo& memo, std::string& out) {
  for (const bool full : {false, true}) {
    std::vector<uint32_t> triples;
    for (uint32_t f : standing_failures(front, root, RemovalOptions{}, memo, full))
      triples.insert(triples.end(), front.face(f), front.face(f) + 3);
    put_array(out, triples);
  }
}

void take_failures(const std::string& image, size_t& pos, const Front& front, RemovalMemo& memo) {
  for (const bool full : {false, true}) {
    const std::vector<uint32_t> triples = get_array<uint32_t>(image, pos);
    std::vector<uint32_t> faces;
    for (size_t i = 0; i + 3 <= triples.size(); i += 3) {
      const uint32_t f = front.find_face(triples[i], triples[i + 1], triples[i + 2]);
      PARTET_ASSERT(f != kNoIndex, "a failure another rank found is for a face not alive here");
      faces.push_back(f);
    }
    record_failures(front, faces, full, 0, memo);
  }
}

}  // namespace

ojson tree_removal_step(const Comm& comm, const InitialFront& initial, LinearOctree& tree, const RootCube& root,
                        TetMesh& mesh, const RankLeaves& ranks, std::unique_ptr<Front>& front, RemovalMemo& memo,
                        bool shape_order, bool on_root) {
  const bool root_rank = comm.rank() == 0;
  const bool distributed = comm.size() > 1 && !on_root;
  ojson c;
  if (on_root && !root_rank) {
    front.reset();
    mesh = TetMesh{};
    return c;
  }
  front = std::make_unique<Front>(initial, tree, root);
  size_t tets = 0, passes = 0, checks = 0, skipped = 0;
  RemovalMemo shaped_memo;  // the shaped passes' failures (this rank's)
  RemovalCounts n;  // rank 0's own passes over every leaf
  if (distributed) {
    PARTET_ASSERT(ranks.own && ranks.separators, "the ranks' leaves are needed on P > 1 ranks");
    const size_t core_tets = mesh.num_tets();
    RemovalCounts ranks_work;  // this rank's passes in the rounds
    double rank_s = 0, merge_s = 0, interface_s = 0, after_s = 0;
    ojson interfaces = ojson::array();
    std::vector<uint32_t> seeds;  // the faces the last round left across the ranks
    // The shaped pass, then the plain one, each over the whole front as on
    // one rank: rounds on the ranks, then rank 0 alone on the faces the
    // last round left across the ranks. Every rank ends each round with
    // the same faces (the others' changes merged).
    for (const bool shaped : {true, false}) {
      RemovalMemo& m = shaped ? shaped_memo : memo;
      const double quality = shaped ? kShapedRemovalQuality : 0;
      set_leaf_owners(comm, *ranks.own, *ranks.separators, root, tree);
      ojson phase = ojson::array();
      for (int round = 0;; ++round) {
        const Front::Snapshot start = front->snapshot();
        Stopwatch clock;
        const RemovalCounts mine =
            one_pass(*front, tree, root, mesh, comm.rank(), quality, shape_order, m, round == 0 ? nullptr : &seeds);
        rank_s += clock.wall();
        add_work(ranks_work, mine);
        if (shaped && round == 0) {
          c["faces left per rank"] = comm.all_gather(static_cast<int64_t>(mine.faces_left));
          c["foreign faces per rank"] = comm.all_gather(static_cast<int64_t>(mine.foreign_faces));
        }
        clock.restart();
        merge_others(comm, comm.all_gather(changes_image(front->changes_since(start))), *front, tree);
        merge_s += clock.wall();
        // The fronts are now the same on every rank (as sets of faces): the
        // faces no rank could remove for a leaf of another are the same too.
        clock.restart();
        const InterfaceFaces faces = interface_faces(*front, tree, root, RemovalOptions{});
        phase.push_back(faces.faces.size());
        seeds = faces.faces;
        // Another round only while the interfaces shrink (the same faces
        // would be cut the same way again).
        const bool last = round == kInterfaceRounds || faces.faces.empty() ||
                          (round > 0 && faces.faces.size() >= phase[phase.size() - 2].get<size_t>());
        if (!last) reown_leaves_by_faces(comm, *front, faces.faces, faces.lowest, root, tree);
        interface_s += clock.wall();
        if (last) break;
      }
      interfaces.push_back(phase);
      // Rank 0 alone on what is left across the ranks; the others take in
      // its changes.
      std::fill(tree.owner.begin(), tree.owner.end(), 0);
      const Front::Snapshot start = front->snapshot();
      Stopwatch clock;
      if (root_rank) add_work(n, one_pass(*front, tree, root, mesh, 0, quality, shape_order, m, &seeds));
      after_s += clock.wall();
      merge_others(comm, comm.all_gather(changes_image(root_rank ? front->changes_since(start) : Front::Changes{})),
                   *front, tree);
    }
    c["tets per rank"] = comm.all_gather(static_cast<int64_t>(ranks_work.tets));
    c["rank s per rank"] = comm.all_gather(rank_s);
    c["merge s per rank"] = comm.all_gather(merge_s);
    c["interface faces after round"] = interfaces;
    c["interface s"] = interface_s;
    c["rank 0 after s"] = after_s;
    tets = static_cast<size_t>(comm.sum(static_cast<int64_t>(ranks_work.tets)));
    passes = ranks_work.passes;
    checks = static_cast<size_t>(comm.sum(static_cast<int64_t>(ranks_work.checks)));
    skipped = static_cast<size_t>(comm.sum(static_cast<int64_t>(ranks_work.skipped_checks)));
    std::string mine;
    if (!root_rank) {
      put_array(mine, mesh.tets.data() + 4 * core_tets, mesh.tets.size() - 4 * core_tets);
      put_failures(*front, root, memo, mine);
    }
    const std::vector<std::string> images = comm.gather(mine, 0);
    if (!root_rank) {
      front.reset();
      mesh = TetMesh{};
      return ojson::object();
    }
    // The other ranks' tets join the mesh (their front changes already
    // joined the front), and what their plain passes could not remove is
    // not tried again by the tree-less removals while it stands.
    for (size_t r = 1; r < images.size(); ++r) {
      size_t pos = 0;
      const std::vector<uint32_t> theirs = get_array<uint32_t>(images[r], pos);
      mesh.tets.insert(mesh.tets.end(), theirs.begin(), theirs.end());
      take_failures(images[r], pos, *front, memo);
    }
    n.faces_left = front->num_alive_faces();
  } else {
    n = two_passes(*front, tree, root, mesh, 0, shape_order, shaped_memo, memo);
  }
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
