// MPI runtime on 1, 2 and 4 ranks: checked collectives, agreement on errors
// (no rank left waiting), per-rank report timings, distributed writes, a
// whole mesh written in pieces by rank 0.
#include <gtest/gtest.h>

#include <filesystem>

#include "check/validate.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_file.hpp"
#include "parallel/collective_step.hpp"
#include "parallel/comm.hpp"
#include "parallel/write_parts.hpp"
#include "pipeline/mesh_command.hpp"
#include "pipeline/report.hpp"
#include "mpi/mpi_scratch.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

TEST(MpiRuntime, Collectives) {
  Comm comm = Comm::world();
  const int p = comm.size();
  EXPECT_EQ(comm.sum(int64_t{comm.rank()}), int64_t{p} * (p - 1) / 2);
  EXPECT_EQ(comm.max(int64_t{comm.rank()}), p - 1);
  EXPECT_DOUBLE_EQ(comm.sum(0.5), 0.5 * p);
  std::vector<double> all = comm.all_gather(double(comm.rank()) * 2.0);
  ASSERT_EQ(all.size(), size_t(p));
  for (int r = 0; r < p; ++r) EXPECT_EQ(all[size_t(r)], 2.0 * r);
  std::string s = comm.rank() == 0 ? "hello" : "";
  comm.broadcast(s, 0);
  EXPECT_EQ(s, "hello");
  std::vector<std::string> g = comm.gather(std::string(size_t(comm.rank()) + 1, 'x'), 0);
  if (comm.rank() == 0) {
    ASSERT_EQ(g.size(), size_t(p));
    for (int r = 0; r < p; ++r) EXPECT_EQ(g[size_t(r)].size(), size_t(r) + 1);
  } else {
    EXPECT_TRUE(g.empty());
  }
}

// While rank 0 works alone for 0.3 s, the others wait in idle_barrier
// sleeping: most of that wall time, a small part of it on the CPU (a plain
// MPI_Barrier spins, with --oversubscribe yielding, near 100 %).
TEST(MpiRuntime, IdleBarrierWaitsAsleep) {
  Comm comm = Comm::world();
  const Stopwatch watch;
  if (comm.rank() == 0) {
    volatile uint64_t spins = 0;
    while (watch.wall() < 0.3) spins = spins + 1;
  }
  comm.idle_barrier();
  const double wall = watch.wall(), cpu = watch.cpu();
  if (comm.rank() == 0) return;
  EXPECT_GE(wall, 0.2);  // the ranks' stopwatches start a little apart
  EXPECT_LT(cpu, 0.25 * wall) << "rank " << comm.rank() << " spent " << cpu << " s of CPU in " << wall << " s";
}

TEST(MpiRuntime, StepWithoutErrorsReturns) {
  Comm comm = Comm::world();
  int ran = 0;
  collective_step(comm, [&] { ran = 1; });
  EXPECT_EQ(ran, 1);
}

TEST(MpiRuntime, ErrorOnOneRankEndsTheStepOnAll) {
  Comm comm = Comm::world();
  const int last = comm.size() - 1;
  try {
    collective_step(comm, [&] {
      if (comm.rank() == last) throw InputError("bad.stl: broken on the last rank");
    });
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), kExitInput);
    EXPECT_NE(std::string(e.what()).find("broken on the last rank"), std::string::npos);
  }
}

TEST(MpiRuntime, LowestFailingRankSpeaksForAll) {
  Comm comm = Comm::world();
  try {
    collective_step(comm, [&] {
      if (comm.rank() == 0) throw MeshingError("rank zero stuck");
      throw InputError("other rank");
    });
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), kExitMeshing);
    EXPECT_EQ(std::string(e.what()), "rank zero stuck");
  }
}

TEST(MpiRuntime, ReportGathersTimesPerRank) {
  Comm comm = Comm::world();
  Log log(comm.rank(), true, false);
  RunReport report(comm, log);
  report.run_step("work", [&] {
    ojson c;
    c["items"] = comm.rank();
    return c;
  });
  const ojson& j = report.finish(0, "");
  EXPECT_EQ(j["ranks"], comm.size());
  EXPECT_EQ(j["steps"][0]["wall_s"].size(), size_t(comm.size()));
  EXPECT_EQ(j["steps"][0]["cpu_s"].size(), size_t(comm.size()));
  EXPECT_EQ(j["peak_rss_mib"].size(), size_t(comm.size()));
}

TEST(MpiRuntime, MeshCommandAgreesOnInputErrors) {
  Comm comm = Comm::world();
  Log log(comm.rank(), true, false);
  MeshOptions o;
  o.input = test::data_path("bad/holes.off");
  o.output = "/tmp/partet_mpi_never_written.vtu";
  try {
    run_mesh(o, comm, log);
    ADD_FAILURE() << "accepted a surface with holes";
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), kExitInput);
    EXPECT_NE(std::string(e.what()).find("open edges"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

// Rank r holds the cube's tets r, r+P, ... with all eight vertices.
TetMesh cube_part(const Comm& comm) {
  TetMesh cube = test::cube_tets();
  TetMesh part;
  part.xyz = cube.xyz;
  for (size_t t = size_t(comm.rank()); t < cube.num_tets(); t += size_t(comm.size()))
    part.tets.insert(part.tets.end(), cube.tets.begin() + 4 * t, cube.tets.begin() + 4 * t + 4);
  return part;
}

TEST(MpiRuntime, DistributedWritesJoinToTheWholeMesh) {
  Comm comm = Comm::world();
  const std::string dir = test::shared_dir(comm, "write");
  TetMesh part = cube_part(comm);
  SurfaceMesh box = test::box_surface();
  for (const char* name : {"/cube.pvtu", "/cube.vtu", "/cube.mesh", "/cube.msh"}) {
    write_distributed_mesh(part, dir + name, {}, comm);
    if (comm.rank() != 0) continue;
    TetMesh whole = read_volume_file(dir + name);
    EXPECT_EQ(whole.num_tets(), 6u) << name;
    EXPECT_EQ(whole.num_vertices(), 8u) << name;
    ValidationResult v = validate_mesh(whole, &box);
    EXPECT_TRUE(v.valid) << name;
  }
  if (comm.rank() == 0) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/cube_" + std::to_string(comm.size() - 1) + ".vtu"));
  }
}

// A mesh whole on rank 0 (the other ranks hold nothing) is written as it
// is: the same bytes as writing it alone, with no merge of parts.
TEST(MpiRuntime, WholeMeshOnRankZeroIsWrittenAsItIs) {
  Comm comm = Comm::world();
  const std::string dir = test::shared_dir(comm, "write_whole");
  const TetMesh whole = test::cube_tets();
  const TetMesh part = comm.rank() == 0 ? whole : TetMesh{};
  for (const char* name : {"/cube.vtu", "/cube.mesh", "/cube.msh"}) {
    write_distributed_mesh(part, dir + name, {}, comm);
    if (comm.rank() != 0) continue;
    const std::string alone = dir + "/alone_" + std::string(name + 1);
    write_volume_file(whole, alone, {});
    EXPECT_EQ(read_file_bytes(dir + name), read_file_bytes(alone)) << name;
  }
}

// A mesh whole on rank 0 goes to a .pvtu of one piece per rank, all
// written by rank 0: consecutive runs of tets of equal size (within one),
// each piece on the vertices its tets use, numbered by the whole mesh;
// together the whole mesh.
TEST(MpiRuntime, WholeMeshOnRankZeroIsWrittenInPieces) {
  Comm comm = Comm::world();
  const std::string dir = test::shared_dir(comm, "write_pieces");
  const TetMesh whole = test::cube_tets();
  const TetMesh mine = comm.rank() == 0 ? whole : TetMesh{};
  write_whole_as_pieces(mine, dir + "/cube.pvtu", {}, comm);
  if (comm.rank() != 0) return;
  const TetMesh joined = read_volume_file(dir + "/cube.pvtu");
  EXPECT_EQ(joined.num_tets(), 6u);
  EXPECT_EQ(joined.num_vertices(), 8u);
  const SurfaceMesh box = test::box_surface();
  EXPECT_TRUE(validate_mesh(joined, &box).valid);
  size_t tets = 0;
  for (int r = 0; r < comm.size(); ++r) {
    const TetMesh piece = read_volume_file(pvtu_piece_path(dir + "/cube.pvtu", r));
    const size_t first = 6 * static_cast<size_t>(r) / static_cast<size_t>(comm.size());
    ASSERT_EQ(piece.num_tets(), 6 * static_cast<size_t>(r + 1) / static_cast<size_t>(comm.size()) - first) << r;
    for (size_t t = 0; t < piece.num_tets(); ++t)
      for (int k = 0; k < 4; ++k) {
        const uint32_t v = piece.tets[4 * t + static_cast<size_t>(k)];
        if (comm.size() == 1) {
          EXPECT_EQ(v, whole.tets[4 * (first + t) + static_cast<size_t>(k)]);
          continue;
        }
        ASSERT_EQ(piece.global_ids.size(), piece.num_vertices());
        const uint64_t g = piece.global_ids[v];
        EXPECT_EQ(g, whole.tets[4 * (first + t) + static_cast<size_t>(k)]) << r;
        for (int i = 0; i < 3; ++i) EXPECT_EQ(piece.point(v)[i], whole.point(g)[i]);
      }
    tets += piece.num_tets();
  }
  EXPECT_EQ(tets, 6u);
}

}  // namespace
}  // namespace partet
