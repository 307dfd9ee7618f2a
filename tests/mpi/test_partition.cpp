// Recursive bisection on 1, 2, 3, 4 and 8 ranks: destinations in range,
// weight balance, separators consistent with the points and identical on all
// ranks, determinism (also over how the global set is spread on the ranks),
// the axes of ROB, RIB and MROB; migration and the Comm exchanges it uses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "parallel/comm.hpp"
#include "parallel/migrate.hpp"
#include "partition/recursive_bisection.hpp"

namespace partet {
namespace {

constexpr BisectionMethod kMethods[] = {BisectionMethod::kRob, BisectionMethod::kRib, BisectionMethod::kMrob};
const char* name(BisectionMethod m) {
  return m == BisectionMethod::kRob ? "ROB" : m == BisectionMethod::kRib ? "RIB" : "MROB";
}

struct Points {
  std::vector<double> xyz, weight;
  size_t size() const { return weight.size(); }
};

// n points per rank, uniform in a box, seeded by the rank.
Points uniform_points(const Comm& comm, size_t n, bool skewed_weights) {
  std::mt19937_64 rng(1000 + static_cast<uint64_t>(comm.rank()));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  for (size_t i = 0; i < n; ++i) {
    p.xyz.insert(p.xyz.end(), {2 * u(rng), u(rng), 0.5 * u(rng)});
    p.weight.push_back(skewed_weights ? std::exp(4 * u(rng)) : 1.0);
  }
  return p;
}

// A clustered set: most points in a small ball, weights heavier near it;
// only the even ranks hold points.
Points clustered_points(const Comm& comm, size_t n) {
  std::mt19937_64 rng(2000 + static_cast<uint64_t>(comm.rank()));
  std::normal_distribution<double> g(0.0, 0.05);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points p;
  if (comm.rank() % 2 == 1) return p;
  for (size_t i = 0; i < n; ++i) {
    bool in_cluster = i % 4 != 0;
    double x = in_cluster ? 0.3 + g(rng) : u(rng), y = in_cluster ? g(rng) : u(rng), z = in_cluster ? g(rng) : u(rng);
    p.xyz.insert(p.xyz.end(), {x, y, z});
    p.weight.push_back(in_cluster ? 1.0 + 10 * std::fabs(g(rng)) : 0.25);
  }
  return p;
}

std::string bytes_of(const std::vector<Separator>& seps) {
  std::string s(seps.size() * sizeof(Separator), '\0');
  if (!seps.empty()) std::memcpy(s.data(), seps.data(), s.size());
  return s;
}

// Checks what holds for any partition; returns the load imbalance
// (max received weight / mean).
double check_partition(const Comm& comm, const Points& p, const PartitionResult& r) {
  const int np = comm.size();
  EXPECT_EQ(r.destination.size(), p.size());
  std::vector<double> received(static_cast<size_t>(np), 0.0);
  for (size_t i = 0; i < p.size(); ++i) {
    int32_t d = r.destination[i];
    EXPECT_TRUE(d >= 0 && d < np) << d;
    if (d < 0 || d >= np) continue;
    received[static_cast<size_t>(d)] += p.weight[i];
    for (const Separator& s : r.separators) {
      if (d < s.first_rank || d >= s.last_rank) continue;
      double v = project(s.normal, &p.xyz[3 * i]);
      if (d < s.mid_rank) {
        EXPECT_LE(v, s.offset) << "depth " << s.depth;
      } else {
        EXPECT_GE(v, s.offset) << "depth " << s.depth;
      }
    }
  }
  // One cut per rank set of two or more ranks.
  EXPECT_EQ(r.separators.size(), static_cast<size_t>(np - 1));
  for (const Separator& s : r.separators) {
    EXPECT_EQ(s.mid_rank - s.first_rank, (s.last_rank - s.first_rank) / 2);
    EXPECT_NEAR(project(s.normal, s.normal), 1.0, 1e-12);
    if (s.axis >= 0) {
      EXPECT_EQ(s.normal[s.axis], 1.0);
    }
  }
  std::string mine = bytes_of(r.separators), root = mine;
  comm.broadcast(root, 0);
  EXPECT_TRUE(mine == root) << "separators differ from rank 0's on rank " << comm.rank();
  double total = 0, worst = 0;
  for (int d = 0; d < np; ++d) {
    double w = comm.sum(received[static_cast<size_t>(d)]);
    total += w;
    worst = std::max(worst, w);
  }
  return total > 0 ? worst / (total / np) : 1.0;
}

void report(const Comm& comm, const char* what, BisectionMethod m, double imbalance) {
  if (comm.rank() == 0)
    std::printf("[ partition ] P=%d %-28s %-4s imbalance %.5f\n", comm.size(), what, name(m), imbalance);
}

TEST(PartitionMpi, UniformWeightsAreBalanced) {
  Comm comm = Comm::world();
  Points p = uniform_points(comm, 20000, false);
  for (BisectionMethod m : kMethods) {
    PartitionResult r = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), m);
    double imbalance = check_partition(comm, p, r);
    report(comm, "uniform, unit weights", m, imbalance);
    EXPECT_LE(imbalance, 1.05);
  }
}

TEST(PartitionMpi, SkewedDistributionsAreReported) {
  Comm comm = Comm::world();
  Points skewed = uniform_points(comm, 20000, true);
  Points clustered = clustered_points(comm, 20000);
  for (BisectionMethod m : kMethods) {
    double a = check_partition(comm, skewed, partition_points(comm, skewed.xyz.data(), skewed.weight.data(),
                                                              skewed.size(), m));
    report(comm, "uniform, weights e^(4u)", m, a);
    EXPECT_LE(a, 1.05);
    double b = check_partition(comm, clustered, partition_points(comm, clustered.xyz.data(),
                                                                 clustered.weight.data(), clustered.size(), m));
    report(comm, "clustered, on even ranks", m, b);
    EXPECT_LE(b, 1.05);
  }
}

TEST(PartitionMpi, FewerPointsThanRanksAndZeroWeights) {
  Comm comm = Comm::world();
  Points p;
  if (comm.rank() == 0) p = Points{{0, 0, 0, 1, 0, 0, 2, 0, 0}, {0, 0, 0}};
  for (BisectionMethod m : kMethods) {
    PartitionResult r = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), m);
    check_partition(comm, p, r);
  }
}

TEST(PartitionMpi, RunsAreDeterministic) {
  Comm comm = Comm::world();
  Points p = uniform_points(comm, 5000, true);
  for (BisectionMethod m : kMethods) {
    PartitionResult a = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), m);
    PartitionResult b = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), m);
    EXPECT_EQ(a.destination, b.destination);
    EXPECT_TRUE(bytes_of(a.separators) == bytes_of(b.separators));
  }
}

TEST(PartitionMpi, RobCutsAlongXThenYThenZ) {
  Comm comm = Comm::world();
  Points p = uniform_points(comm, 2000, false);
  PartitionResult r = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), BisectionMethod::kRob);
  for (const Separator& s : r.separators) {
    EXPECT_EQ(s.axis, s.depth % 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(s.normal[k], k == s.depth % 3 ? 1.0 : 0.0);
  }
}

TEST(PartitionMpi, RibFollowsTheInertiaAxisAndMrobTheClosestCoordinateAxis) {
  Comm comm = Comm::world();
  // A thin cloud along d = (0.5, 1, 0.3)/|.|: the first cut is across d.
  const double len = std::sqrt(0.25 + 1 + 0.09), d[3] = {0.5 / len, 1 / len, 0.3 / len};
  std::mt19937_64 rng(3000 + static_cast<uint64_t>(comm.rank()));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points p;
  for (int i = 0; i < 4000; ++i) {
    double t = 10 * u(rng);
    for (int k = 0; k < 3; ++k) p.xyz.push_back(t * d[k] + 0.05 * u(rng));
    p.weight.push_back(1.0);
  }
  if (comm.size() < 2) return;
  PartitionResult rib = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), BisectionMethod::kRib);
  check_partition(comm, p, rib);
  EXPECT_GT(project(rib.separators[0].normal, d), 0.999);
  EXPECT_EQ(rib.separators[0].axis, -1);
  PartitionResult mrob = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), BisectionMethod::kMrob);
  check_partition(comm, p, mrob);
  EXPECT_EQ(mrob.separators[0].axis, 1);
}

// The global set: distinct cells of a 64^3 grid (many equal coordinates),
// weights from the cell; point g is held by rank g % P in reverse order, or
// in blocks in order.
Points grid_points(const Comm& comm, size_t total, bool blocks, std::vector<size_t>& global_index) {
  const size_t np = static_cast<size_t>(comm.size()), me = static_cast<size_t>(comm.rank());
  global_index.clear();
  if (blocks) {
    for (size_t g = total * me / np; g < total * (me + 1) / np; ++g) global_index.push_back(g);
  } else {
    for (size_t g = total; g-- > 0;)
      if (g % np == me) global_index.push_back(g);
  }
  Points p;
  for (size_t g : global_index) {
    size_t c = (g * 7919) % (size_t{1} << 18);
    p.xyz.insert(p.xyz.end(), {(double(c & 63) + 0.5) / 64, (double((c >> 6) & 63) + 0.5) / 64,
                               (double(c >> 12) + 0.5) / 64});
    p.weight.push_back(1.0 + double(c % 5));
  }
  return p;
}

TEST(PartitionMpi, SameGlobalSetSameResultWhateverTheDistribution) {
  Comm comm = Comm::world();
  const size_t total = 5000 * static_cast<size_t>(comm.size()) + 7;
  for (BisectionMethod m : kMethods) {
    std::vector<std::vector<int64_t>> global_destination;
    std::vector<std::string> separators;
    for (bool blocks : {true, false}) {
      std::vector<size_t> index;
      Points p = grid_points(comm, total, blocks, index);
      PartitionResult r = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), m);
      double imbalance = check_partition(comm, p, r);
      if (blocks) report(comm, "64^3 grid cells (ties)", m, imbalance);
      EXPECT_LE(imbalance, 1.05);
      std::vector<int64_t> dest(total, 0);
      for (size_t i = 0; i < index.size(); ++i) dest[index[i]] = r.destination[i];
      comm.sum(dest.data(), dest.size());
      global_destination.push_back(dest);
      separators.push_back(bytes_of(r.separators));
    }
    EXPECT_EQ(global_destination[0], global_destination[1]) << name(m);
    EXPECT_TRUE(separators[0] == separators[1]) << name(m);
  }
}

struct Record {
  double xyz[3];
  int64_t global;
  int32_t destination;
  int32_t source;
};

TEST(PartitionMpi, MigrateDeliversEveryRecordToItsDestination) {
  Comm comm = Comm::world();
  const int np = comm.size();
  Points p = uniform_points(comm, 3000 + 100 * static_cast<size_t>(comm.rank()), true);
  PartitionResult r = partition_points(comm, p.xyz.data(), p.weight.data(), p.size(), BisectionMethod::kMrob);
  std::vector<Record> records(p.size());
  std::vector<int64_t> expected(static_cast<size_t>(np), 0);
  for (size_t i = 0; i < p.size(); ++i) {
    Record& rec = records[i];
    std::memcpy(rec.xyz, &p.xyz[3 * i], sizeof rec.xyz);
    rec.global = static_cast<int64_t>(i);
    rec.destination = r.destination[i];
    rec.source = comm.rank();
    ++expected[static_cast<size_t>(r.destination[i])];
  }
  comm.sum(expected.data(), expected.size());
  std::vector<int32_t> sources;
  std::vector<Record> got = migrate(comm, r.destination, records, 1, &sources);
  ASSERT_EQ(got.size(), static_cast<size_t>(expected[static_cast<size_t>(comm.rank())]));
  ASSERT_EQ(sources.size(), got.size());
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].destination, comm.rank());
    EXPECT_EQ(got[i].source, sources[i]);
    if (i > 0) {  // by source rank, then in the source's order
      EXPECT_LE(sources[i - 1], sources[i]);
      if (sources[i - 1] == sources[i]) {
        EXPECT_LT(got[i - 1].global, got[i].global);
      }
    }
  }
  // The typed form with several values per record moves the coordinates alike.
  std::vector<double> xyz = migrate(comm, r.destination, p.xyz, 3);
  ASSERT_EQ(xyz.size(), 3 * got.size());
  for (size_t i = 0; i < got.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(xyz[3 * i + k], got[i].xyz[k]);
  // Everything to the last rank, nothing elsewhere.
  std::vector<int32_t> last(p.size(), np - 1);
  const int64_t total = comm.sum(static_cast<int64_t>(p.size()));
  std::vector<Record> all = migrate(comm, last, records);
  EXPECT_EQ(static_cast<int64_t>(all.size()), comm.rank() == np - 1 ? total : 0);
}

TEST(PartitionMpi, CommArrayReductionsAndAllToAll) {
  Comm comm = Comm::world();
  const int np = comm.size(), me = comm.rank();
  std::vector<int64_t> s{me, 1, -me};
  comm.sum(s.data(), s.size());
  EXPECT_EQ(s, (std::vector<int64_t>{np * (np - 1) / 2, np, -np * (np - 1) / 2}));
  std::vector<double> lo{double(me), -double(me)}, hi = lo;
  comm.min(lo.data(), lo.size());
  comm.max(hi.data(), hi.size());
  EXPECT_EQ(lo, (std::vector<double>{0.0, -double(np - 1)}));
  EXPECT_EQ(hi, (std::vector<double>{double(np - 1), 0.0}));
  // Rank r sends (r + d) bytes of value r to rank d.
  std::vector<int64_t> send_bytes(static_cast<size_t>(np));
  std::vector<char> send;
  for (int d = 0; d < np; ++d) {
    send_bytes[static_cast<size_t>(d)] = me + d;
    send.insert(send.end(), static_cast<size_t>(me + d), static_cast<char>(me));
  }
  std::vector<int64_t> recv_bytes;
  std::vector<char> recv = comm.all_to_all(send, send_bytes, recv_bytes);
  size_t at = 0;
  for (int src = 0; src < np; ++src) {
    ASSERT_EQ(recv_bytes[static_cast<size_t>(src)], src + me);
    for (int b = 0; b < src + me; ++b) EXPECT_EQ(recv[at++], static_cast<char>(src));
  }
  EXPECT_EQ(at, recv.size());
}

}  // namespace
}  // namespace partet
