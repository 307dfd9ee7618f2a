// FlatHashMap against std::map under random inserts, updates and erases
// (erase by backward shift is where open addressing goes wrong), with a
// deliberately poor hash so probe runs are long and wrap around the table.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>

#include "core/flat_hash_map.hpp"

namespace partet {
namespace {

struct GoodTraits {
  static uint64_t empty() { return UINT64_MAX; }
  static uint64_t hash(uint64_t k) { return k * 0x9E3779B97F4A7C15ull ^ (k >> 17); }
};

// Every key lands in one of 4 home slots: runs of hundreds, wrapping.
struct ClusteredTraits {
  static uint64_t empty() { return UINT64_MAX; }
  static uint64_t hash(uint64_t k) { return (k % 4) * 0x4000000000000001ull + 0x3FFFFFFFFFFFFFF0ull; }
};

template <class Traits>
void agree_with_map(uint32_t seed, uint64_t key_range, int steps) {
  FlatHashMap<uint64_t, uint32_t, Traits> table;
  std::map<uint64_t, uint32_t> oracle;
  std::mt19937_64 rng(seed);
  for (int step = 0; step < steps; ++step) {
    const uint64_t key = rng() % key_range;
    const int op = static_cast<int>(rng() % 3);
    if (op == 0) {
      const uint32_t v = static_cast<uint32_t>(rng());
      table.get_or_insert(key, 0) = v;
      oracle[key] = v;
    } else if (op == 1) {
      EXPECT_EQ(table.erase(key), oracle.erase(key) == 1) << "step " << step;
    } else {
      const uint32_t* found = table.find(key);
      auto it = oracle.find(key);
      ASSERT_EQ(found != nullptr, it != oracle.end()) << "step " << step << " key " << key;
      if (found) {
        EXPECT_EQ(*found, it->second);
      }
    }
    ASSERT_EQ(table.size(), oracle.size());
  }
  for (uint64_t key = 0; key < key_range; ++key) {
    const uint32_t* found = table.find(key);
    auto it = oracle.find(key);
    ASSERT_EQ(found != nullptr, it != oracle.end()) << "key " << key;
    if (found) {
      EXPECT_EQ(*found, it->second);
    }
  }
}

TEST(FlatHashMap, AgreesWithStdMap) {
  for (uint32_t seed = 1; seed <= 4; ++seed) agree_with_map<GoodTraits>(seed, 3000, 40000);
}

TEST(FlatHashMap, AgreesWithStdMapUnderLongProbeRuns) {
  for (uint32_t seed = 1; seed <= 4; ++seed) agree_with_map<ClusteredTraits>(seed, 400, 20000);
}

TEST(FlatHashMap, GetOrInsertKeepsExistingValue) {
  FlatHashMap<uint64_t, uint32_t, GoodTraits> table;
  table.get_or_insert(7, 1) += 5;
  EXPECT_EQ(table.get_or_insert(7, 100), 6u);
  EXPECT_EQ(table.size(), 1u);
  EXPECT_FALSE(table.erase(8));
  EXPECT_TRUE(table.erase(7));
  EXPECT_EQ(table.find(7), nullptr);
  EXPECT_TRUE(table.empty());
}

TEST(FlatHashMap, ReserveAvoidsGrowthAndClearKeepsSlots) {
  FlatHashMap<uint64_t, uint32_t, GoodTraits> table;
  table.reserve(1000);
  const size_t bytes = table.bytes();
  for (uint64_t k = 0; k < 1000; ++k) table.get_or_insert(k, static_cast<uint32_t>(k));
  EXPECT_EQ(table.bytes(), bytes);
  table.clear();
  EXPECT_TRUE(table.empty());
  EXPECT_EQ(table.find(5), nullptr);
  EXPECT_EQ(table.bytes(), bytes);
}

}  // namespace
}  // namespace partet
