// remove_faces_treeless: the short-growth and default strategies' rounds,
// then, while faces are left, the rescue strategies' rounds, each from the
// starting state (see treeless_removal.hpp, "Short growth first" and
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

// Everything a run changes: the state a rescue starts again from, or the
// result of an attempt.
struct TreelessState {
  Front front;
  std::vector<LeafClass> cls;
  TetMesh out;
  RemovalMemo memo;
  TreelessCounts counts;

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
  if (strategies.size() == 1) {
    TreelessCounts n = run_treeless_rounds(front, tree, root, out, options, m, strategies[0]);
    n.faces_left_by_attempt = {n.faces_left};
    return n;
  }
  const TreelessState start{front, tree.cls, out, m, {}};
  std::optional<TreelessState> best;
  std::vector<size_t> faces_left;
  for (const TreelessStrategy strategy : strategies) {
    if (!faces_left.empty()) start.restore(front, tree, out, m);
    TreelessCounts n = run_treeless_rounds(front, tree, root, out, options, m, strategy);
    faces_left.push_back(n.faces_left);
    n.faces_left_by_attempt = faces_left;
    if (n.faces_left == 0) return n;
    if (!best || n.faces_left < best->counts.faces_left) best = TreelessState{front, tree.cls, out, m, n};
  }
  // None closed the front: the attempt that left the fewest faces.
  best->restore(front, tree, out, m);
  best->counts.faces_left_by_attempt = faces_left;
  return best->counts;
}

}  // namespace partet
