// remove_faces_treeless: the short-growth and default strategies' rounds
// (the default going on from where short growth stalled when it left few
// faces), then, while faces are left, the rescue strategies' rounds, each
// from the starting state (see treeless_removal.hpp, "Short growth first" and
// "Rescue"); the rounds themselves are in
// treeless_rounds.cpp.
#include "front/treeless_removal.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "front/treeless_rounds.hpp"

namespace partet {

namespace {

// Everything a run changes: the state every attempt after the first
// starts again from.
struct TreelessState {
  Front front;
  std::vector<LeafClass> cls;
  TetMesh out;
  RemovalMemo memo;

  void restore(Front& f, LinearOctree& tree, TetMesh& o, RemovalMemo& m) const {
    f = front;
    tree.cls = cls;
    o = out;
    m = memo;
  }
};

}  // namespace

const char* strategy_name(TreelessStrategy strategy) {
  switch (strategy) {
    case TreelessStrategy::kShortGrowth: return "short growth";
    case TreelessStrategy::kDefault: return "default";
    case TreelessStrategy::kUndoOvergrowth: return "undo overgrowth";
    case TreelessStrategy::kConeFirst: return "cone first";
    case TreelessStrategy::kSmallCavities: return "small cavities";
  }
  return "?";
}

int growth_steps(TreelessStrategy strategy) {
  return strategy == TreelessStrategy::kShortGrowth ? kShortGrowthSteps : kMaxGrowthSteps;
}

size_t stall_rounds(TreelessStrategy strategy, size_t option) {
  return strategy == TreelessStrategy::kShortGrowth ? std::min(option, kShortGrowthStall) : option;
}

TreelessCounts remove_faces_treeless(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                     const RemovalOptions& options, RemovalMemo* memo) {
  PARTET_ASSERT(tree.size() == tree.owner.size() && tree.size() == tree.cls.size(), "tree arrays disagree");
  RemovalMemo own;
  RemovalMemo& m = memo ? *memo : own;
  std::vector<TreelessStrategy> strategies;
  if (options.short_growth_first) strategies.push_back(TreelessStrategy::kShortGrowth);
  strategies.push_back(TreelessStrategy::kDefault);
  const size_t rescues = std::min(static_cast<size_t>(std::max(options.rescues, 0)), std::size(kRescueStrategies));
  strategies.insert(strategies.end(), kRescueStrategies, kRescueStrategies + rescues);
  PARTET_ASSERT(options.starts > 0, "tree-less removals with no attempt");
  if (strategies.size() == 1) {
    TreelessCounts n = run_treeless_rounds(front, tree, root, out, options, m, strategies[0]);
    n.faces_left_by_attempt = {n.faces_left};
    return n;
  }
  // A copy of the starting state only when an attempt may start from it
  // again (it is a whole mesh at the peak).
  const bool restarts = options.starts > 1 || options.rerun_best;
  const std::optional<TreelessState> start =
      restarts ? std::optional<TreelessState>(TreelessState{front, tree.cls, out, m}) : std::nullopt;
  // Each attempt runs from the call's start: one strategy, then, while it
  // stalls with at most options.go_on_faces faces, the next strategies
  // going on from where the last one stopped. chains[a] is how attempt a's
  // front was reached; faces_left[a] what it left.
  std::vector<size_t> faces_left;
  std::vector<std::vector<TreelessStrategy>> chains;
  TreelessCounts n;
  for (size_t first = 0; first < std::min(strategies.size(), options.starts); ++first) {
    if (!faces_left.empty()) start->restore(front, tree, out, m);
    std::vector<TreelessStrategy> chain;
    for (size_t k = first; k < strategies.size(); ++k) {
      if (k > first && n.faces_left > options.go_on_faces) break;
      n = run_treeless_rounds(front, tree, root, out, options, m, strategies[k]);
      chain.push_back(strategies[k]);
      faces_left.push_back(n.faces_left);
      chains.push_back(chain);
      n.faces_left_by_attempt = faces_left;
      if (n.faces_left == 0) return n;
    }
  }
  // None closed the front: the attempt that left the fewest faces (the
  // earliest on ties), run again from the start unless it is the last one
  // (the rounds are deterministic; a copy of the best attempt's state held
  // one more whole mesh at the peak: blobby r4 2,119 -> 2,699 MB).
  const auto fewest = std::min_element(faces_left.begin(), faces_left.end());
  const size_t best = static_cast<size_t>(fewest - faces_left.begin());
  if (options.rerun_best && best + 1 < faces_left.size()) {
    start->restore(front, tree, out, m);
    for (const TreelessStrategy strategy : chains[best])
      n = run_treeless_rounds(front, tree, root, out, options, m, strategy);
    PARTET_ASSERT(n.faces_left == *fewest, "a tree-less attempt run again left other faces");
    n.faces_left_by_attempt = faces_left;
  }
  return n;
}

}  // namespace partet
