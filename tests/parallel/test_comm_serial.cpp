// Comm without a launcher: one rank, collectives are the identity, and
// collective_step passes errors through with their exit codes.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "parallel/collective_step.hpp"
#include "parallel/comm.hpp"
#include "parallel/write_parts.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

TEST(CommSerial, OneRankIdentityCollectives) {
  Comm comm = Comm::world();
  EXPECT_EQ(comm.rank(), 0);
  EXPECT_EQ(comm.size(), 1);
  EXPECT_EQ(comm.sum(int64_t{5}), 5);
  EXPECT_EQ(comm.max(2.5), 2.5);
  EXPECT_EQ(comm.all_gather(1.5), std::vector<double>{1.5});
  std::string s = "abc";
  comm.broadcast(s, 0);
  EXPECT_EQ(s, "abc");
  EXPECT_EQ(comm.gather("xy", 0), std::vector<std::string>{"xy"});
  comm.barrier();
}

TEST(CommSerial, CollectiveStepKeepsExitCodes) {
  Comm comm = Comm::world();
  try {
    collective_step(comm, [] { throw MeshingError("stuck at (1, 2, 3)"); });
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), kExitMeshing);
    EXPECT_STREQ(e.what(), "stuck at (1, 2, 3)");
  }
  try {
    collective_step(comm, [] { throw std::runtime_error("boom"); });
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), kExitInternal);
  }
}

TEST(CommSerial, PartImageRoundTrips) {
  TetMesh m = test::cube_tets();
  m.global_ids = {10, 11, 12, 13, 14, 15, 16, 17};
  TetMesh back = deserialize_part(serialize_part(m));
  EXPECT_EQ(back.xyz, m.xyz);
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_EQ(back.tris, m.tris);
  EXPECT_EQ(back.global_ids, m.global_ids);
  TetMesh empty;  // no arrays at all: nothing to copy from or to
  TetMesh none = deserialize_part(serialize_part(empty));
  EXPECT_EQ(none.num_vertices(), 0u);
  EXPECT_TRUE(none.global_ids.empty());
}

}  // namespace
}  // namespace partet
