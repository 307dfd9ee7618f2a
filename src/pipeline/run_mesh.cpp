// run_mesh: the attempts of the meshing pipeline in turn, cheap ones first,
// until one closes the front (see the comment below).
#include <optional>
#include <string>

#include "core/error.hpp"
#include "io/file_bytes.hpp"
#include "pipeline/mesh_attempt.hpp"
#include "pipeline/mesh_command.hpp"

namespace partet {

// Closure comes first, then the cheap attempts, then the costly ones. The
// tree-less removals' short growth fails in a few rounds without a smaller
// front, their other strategies only after many (a needle whose fronts do
// not close spends minutes in each). The thin-core refinement is for
// quality and the first tree is what meshed before it; the Delaunay fill
// is for speed, and its front on a corrugated needle (most input triangles
// not Delaunay faces) may not close where the front from the surface and
// the core does. So:
//  1. the tree as built (refined for a thin core where it needs it), with
//     the fill, short growth only (the default going on from a few faces:
//     every corpus input closes here); on P > 1 ranks the tree-supported
//     removals on rank 0 alone, unless the options put them on the ranks,
//     and then, when that fails, the same on rank 0 alone;
//  2. when that tree was refined, the first tree the same way;
//  3. the first tree without the fill (where the fill ran), the same way;
//  4. the first tree with the fill, the default and the rescue strategies;
//  5. when the tree was refined, the refined tree the same way;
//  6. the first tree with targets best shape first, every strategy: the
//     orders leave different pockets, and where the Delaunay order's cannot
//     be closed the shape order's may be (stress-check seed 673).
// Without the tree-less removals only 1 and 2 run. The attempts are
// deterministic, so none repeats another (stress-check seed 5193: 1 fails
// in 21 s, 2 in 20, 3 closes in 20; it took over ten minutes when 2 ran
// every strategy). On P > 1 ranks every retry makes the tree-supported
// removals on rank 0 alone: the tree-less removals (rank 0's) then start
// from one rank's front, and the retries are one rank's attempts, so the
// ranks close what one rank closes (stress-check seed 2123 closes on one
// rank in 1; on 2 ranks, from the ranks' front, 1 left 208 faces and 2 and
// 3 after it 102 and 78).
int run_mesh(const MeshOptions& options, const Comm& comm, const Log& log) {
  const std::string name = file_basename(options.input);
  MeshOptions first = options;
  first.min_core = 0;
  FrontLeftOpen open;
  try {
    return mesh_once(options, comm, log, {.once = true, .removals_on_root = !options.removals_on_ranks()});
  } catch (const FrontLeftOpen& e) {
    open = e;
  }
  // A retry, after a note saying why: its exit code, or none when it left
  // the front open too.
  const auto retry = [&](const std::string& why, const MeshOptions& o, MeshAttempt attempt) -> std::optional<int> {
    log.note(name + ": " + why);
    attempt.removals_on_root = true;
    try {
      return mesh_once(o, comm, log, attempt);
    } catch (const FrontLeftOpen&) {
      return std::nullopt;
    }
  };
  std::optional<int> code;
  if (comm.size() > 1 && options.treeless && options.removals_on_ranks())
    code = retry("the front did not close after the face removals on the ranks: meshing again with rank 0 making "
                 "them, as one rank does",
                 options, {.once = true, .report_key = "retried with the tree-supported removals on rank 0"});
  if (!code && open.refined)
    code = retry("the front did not close on the tree refined for a thin core: meshing again on the first tree", first,
                 {.once = true, .report_key = "retried without the thin-core refinement"});
  if (!code && open.filled)
    code = retry("the front did not close after the Delaunay fill: meshing again without it", first,
                 {.fill = false, .once = true, .report_key = "retried without the Delaunay fill"});
  if (!code)
    code = retry("short growth did not close the front: the other strategies on the first tree", first,
                 {.short_growth = false, .report_key = "retried with the other strategies"});
  if (!code && open.refined)
    code = retry("the front did not close on the first tree either: the other strategies on the refined tree", options,
                 {.short_growth = false, .report_key = "retried with the other strategies on the refined tree"});
  if (!code)
    code = retry("the front did not close with targets in Delaunay order: meshing again on the first tree with "
                 "targets best shape first",
                 first, {.shape_order = true, .last = true, .report_key = "retried with targets best shape first"});
  PARTET_ASSERT(code.has_value(), "the last attempt left the front open without an error");
  return *code;
}

}  // namespace partet
