// The face removals on 1, 2 and 4 ranks (--tree-removals-on-ranks).
// Tree-supported (pipeline step 4 on every rank's copy of the front, rounds
// on the interfaces, the rest on rank 0; without the Delaunay fill, so that
// they fill the whole gap): the
// finished mesh is valid against the surface; on P > 1 ranks
// some faces waited because their neighbourhood reached another rank's
// leaves, and the tets counted are the ranks' and rank 0's finishing ones;
// where the body is large enough for the ranks' regions (not pipe, whose
// 16 leaves put every face's neighbourhood across a cut), every rank made
// tets and the interface rounds left fewer faces across the ranks than the
// first round. Each leaf has one owner, the same on every rank, and a
// boundary leaf's owner is the rank the boundary partition sent it to.
// Tree-less (step 10): the ranks close part of what is left and the mesh
// is valid and the same from run to run.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "check/validate.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "parallel/comm.hpp"
#include "partition/boundary_partition.hpp"
#include "partition/leaf_owners.hpp"
#include "pipeline/mesh_command.hpp"
#include "pipeline/tree_removal_step.hpp"
#include "pipeline/treeless_step.hpp"
#include "mpi/mpi_scratch.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

struct Case {
  const char* surface;
  bool every_rank_removes;  // false for a body so small that every face's neighbourhood crosses a cut at first
};

class DistributedRemovals : public testing::TestWithParam<Case> {};

TEST_P(DistributedRemovals, EveryRankMakesTetsAndTheMeshIsValid) {
  const Comm comm = Comm::world();
  const Log log(comm.rank(), false, false);
  const std::string dir = test::shared_dir(comm, "removals");
  MeshOptions o;
  o.input = test::data_path(GetParam().surface);
  o.output = dir + "/mesh.vtu";
  o.report = dir + "/report.json";
  o.quiet = true;
  // The removals fill the whole gap: with the Delaunay fill and its edge
  // recovery, sphere966 leaves them 28 faces, too few for every rank.
  o.delaunay_fill = false;
  o.tree_removals_on_ranks = true;
  ASSERT_EQ(run_mesh(o, comm, log), kExitOk);
  if (comm.rank() != 0) return;
  const SurfaceMesh surface = read_surface_file(o.input);
  const ValidationResult v = validate_mesh(read_volume_file(o.output), &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  const nlohmann::json report = nlohmann::json::parse(test::read_text(o.report));
  const auto& steps = report["steps"];
  const auto step = std::find_if(steps.begin(), steps.end(), [](const auto& s) { return s["name"] == "face removals (tree)"; });
  ASSERT_NE(step, steps.end());
  const auto& c = (*step)["counts"];
  if (comm.size() == 1) {
    EXPECT_FALSE(c.contains("tets per rank"));
    return;
  }
  const std::vector<int64_t> per_rank = c["tets per rank"].get<std::vector<int64_t>>();
  ASSERT_EQ(per_rank.size(), static_cast<size_t>(comm.size()));
  EXPECT_EQ(c["merge s per rank"].size(), static_cast<size_t>(comm.size()));
  EXPECT_EQ(c["tets"].get<int64_t>(),
            std::accumulate(per_rank.begin(), per_rank.end(), int64_t{0}) + c["tets on rank 0 after"].get<int64_t>());
  const std::vector<int64_t> foreign = c["foreign faces per rank"].get<std::vector<int64_t>>();
  EXPECT_GT(std::accumulate(foreign.begin(), foreign.end(), int64_t{0}), 0);
  // Per pass (shaped, then plain), the interface faces after each round.
  const auto passes = c["interface faces after round"];
  ASSERT_EQ(passes.size(), 2u);
  const std::vector<int64_t> interfaces = passes[0].get<std::vector<int64_t>>();
  ASSERT_FALSE(interfaces.empty());
  EXPECT_LE(interfaces.size(), static_cast<size_t>(kInterfaceRounds + 1));
  if (!GetParam().every_rank_removes) return;
  for (int64_t tets : per_rank) EXPECT_GT(tets, 0);
  // The shaped pass's rounds on the interfaces leave fewer faces across the
  // ranks' leaves than its first round did.
  EXPECT_GT(interfaces.size(), 1u);
  EXPECT_LT(interfaces.back(), interfaces.front());
}

// A level-2 tree (64 leaves) on every rank: leaves 0-31 are "boundary"
// leaves, leaf i held by rank i mod P; the others are placed by separators
// cut over their centres (held by rank 0).
TEST(LeafOwnersMpi, BoundaryLeavesKeepTheirRankAndTheRestFollowTheSeparators) {
  const Comm comm = Comm::world();
  const int p = comm.size();
  LinearOctree tree;
  const uint32_t e = octant_edge(2);
  for (uint32_t z = 0; z < 4; ++z)
    for (uint32_t y = 0; y < 4; ++y)
      for (uint32_t x = 0; x < 4; ++x) tree.key.push_back(morton_key(x * e, y * e, z * e));
  std::sort(tree.key.begin(), tree.key.end());
  tree.level.assign(64, 2);
  tree.cls.assign(64, LeafClass::kInterior);
  tree.owner.assign(64, -1);
  const RootCube root;
  LinearOctree own;
  std::vector<double> centres, weights;
  for (size_t i = 0; i < 64; ++i) {
    if (i < 32 && static_cast<int>(i % static_cast<size_t>(p)) == comm.rank()) own.key.push_back(tree.key[i]);
    if (i >= 32 && comm.rank() == 0) {
      double c[3];
      octant_centre(root, tree.key[i], 2, c);
      centres.insert(centres.end(), c, c + 3);
      weights.push_back(1);
    }
  }
  const PartitionResult cut = partition_points(comm, centres.data(), weights.data(), weights.size());
  set_leaf_owners(comm, own, cut.separators, root, tree);
  for (size_t i = 0; i < 64; ++i) {
    if (i < 32) {
      EXPECT_EQ(tree.owner[i], static_cast<int32_t>(i % static_cast<size_t>(p))) << i;
    } else {
      double c[3];
      octant_centre(root, tree.key[i], 2, c);
      EXPECT_EQ(tree.owner[i], rank_of_point(cut.separators, p, c)) << i;
    }
  }
  // Rank 0's leaves among 32-63 are where the partition sent their centres.
  if (comm.rank() == 0) {
    for (size_t i = 32; i < 64; ++i) EXPECT_EQ(tree.owner[i], cut.destination[i - 32]) << i;
  }
  // The same owners on every rank.
  std::vector<int64_t> sum(64), mine(64);
  for (size_t i = 0; i < 64; ++i) sum[i] = mine[i] = tree.owner[i];
  comm.sum(sum.data(), sum.size());
  for (size_t i = 0; i < 64; ++i) EXPECT_EQ(sum[i], mine[i] * p) << i;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, DistributedRemovals,
                         testing::Values(Case{"good/sphere966.off", true}, Case{"good/eight.off", true},
                                         Case{"good/pipe.off", false}),
                         [](const testing::TestParamInfo<Case>& info) {
                           const std::string name = info.param.surface;
                           return name.substr(5, name.find('.') - 5);
                         });

// The tree-less removals on the ranks (spool: a CAD part whose tree-less
// removals delete thousands of tets; --treeless-on-ranks): the mesh is
// valid against the surface and, on P > 1 ranks, the ranks' first round
// closes part of the front the tree-supported removals left, every round
// reporting each rank's rounds; a second run gives the same mesh. By
// default rank 0 makes them alone: a valid mesh, no rounds on the ranks.
// Without the Delaunay fill, which leaves spool's removals little to do.
TEST(DistributedTreeless, TheRanksCloseCavitiesAndTheMeshIsValid) {
  const Comm comm = Comm::world();
  const Log log(comm.rank(), false, false);
  const std::string dir = test::shared_dir(comm, "treeless");
  MeshOptions o;
  o.input = test::data_path("good/spool.off");
  o.output = dir + "/mesh.vtu";
  o.report = dir + "/report.json";
  o.quiet = true;
  o.treeless_on_ranks = true;
  o.delaunay_fill = false;
  ASSERT_EQ(run_mesh(o, comm, log), kExitOk);
  MeshOptions alone = o;
  alone.treeless_on_ranks = false;
  alone.output = dir + "/alone.vtu";
  alone.report = dir + "/alone.json";
  ASSERT_EQ(run_mesh(alone, comm, log), kExitOk);
  MeshOptions again = o;
  again.output = dir + "/again.vtu";
  again.report = "";
  ASSERT_EQ(run_mesh(again, comm, log), kExitOk);
  if (comm.rank() != 0) return;
  EXPECT_EQ(test::read_text(o.output), test::read_text(again.output));
  const SurfaceMesh surface = read_surface_file(o.input);
  const ValidationResult v = validate_mesh(read_volume_file(o.output), &surface);
  EXPECT_TRUE(v.valid) << format_text(v);
  const auto counts_of = [](const std::string& path, const char* name) {
    const nlohmann::json report = nlohmann::json::parse(test::read_text(path));
    for (const auto& step : report["steps"])
      if (step["name"] == name) return step["counts"];
    return nlohmann::json();
  };
  const nlohmann::json tree = counts_of(o.report, "face removals (tree)");
  const nlohmann::json treeless = counts_of(o.report, "face removals (tree-less)");
  ASSERT_FALSE(treeless.is_null());
  EXPECT_EQ(treeless["faces left"].get<int64_t>(), 0);
  const ValidationResult by_rank_0 = validate_mesh(read_volume_file(alone.output), &surface);
  EXPECT_TRUE(by_rank_0.valid) << format_text(by_rank_0);
  const nlohmann::json rank_0_alone = counts_of(alone.report, "face removals (tree-less)");
  ASSERT_FALSE(rank_0_alone.is_null());
  EXPECT_EQ(rank_0_alone["faces left"].get<int64_t>(), 0);
  EXPECT_FALSE(rank_0_alone.contains("rounds per rank"));
  if (comm.size() == 1) {
    EXPECT_FALSE(treeless.contains("rounds per rank"));
    return;
  }
  const auto rounds = treeless["rounds per rank"];
  const auto left = treeless["faces left after ranks"].get<std::vector<int64_t>>();
  ASSERT_FALSE(left.empty());
  EXPECT_EQ(rounds.size(), left.size());
  EXPECT_LE(left.size(), static_cast<size_t>(kTreelessRankRounds));
  for (const auto& round : rounds) EXPECT_EQ(round.size(), static_cast<size_t>(comm.size()));
  EXPECT_LT(left.front(), tree["faces left"].get<int64_t>());
  EXPECT_GT(treeless["tets deleted"].get<int64_t>(), 0);
}

}  // namespace
}  // namespace partet
