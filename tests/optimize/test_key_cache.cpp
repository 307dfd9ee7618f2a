// KeyCache: a key just put is found with its value, a key never put is not
// found, and after many more keys than slots every key is either found with
// its own latest value or forgotten, never another key's value; a cache
// for a few keys keeps few.
#include <gtest/gtest.h>

#include <cstdint>

#include "optimize/key_cache.hpp"

namespace partet {
namespace {

TEST(KeyCache, FindsWhatWasPutOrNothing) {
  KeyCache cache(uint64_t{1} << 16);
  EXPECT_EQ(cache.find(7), nullptr);
  cache.put(7, 70);
  ASSERT_NE(cache.find(7), nullptr);
  EXPECT_EQ(*cache.find(7), 70u);
  cache.put(7, 71);
  EXPECT_EQ(*cache.find(7), 71u);
  EXPECT_EQ(cache.find(8), nullptr);

  // Four times as many keys as slots: many share a slot.
  constexpr uint64_t kKeys = uint64_t{1} << 18;
  size_t found = 0;
  for (uint64_t k = 1; k <= kKeys; ++k) {
    cache.put(k << 20, static_cast<uint32_t>(k));
    ASSERT_NE(cache.find(k << 20), nullptr);  // the latest is always there
  }
  for (uint64_t k = 1; k <= kKeys; ++k) {
    const uint32_t* value = cache.find(k << 20);
    if (!value) continue;
    EXPECT_EQ(*value, static_cast<uint32_t>(k));
    ++found;
  }
  EXPECT_GT(found, kKeys / 8);
  EXPECT_LT(found, kKeys);

  KeyCache small(8);
  for (uint64_t k = 1; k <= 1000; ++k) small.put(k, static_cast<uint32_t>(k));
  size_t kept = 0;
  for (uint64_t k = 1; k <= 1000; ++k) kept += small.find(k) != nullptr;
  EXPECT_GT(kept, 0u);
  EXPECT_LE(kept, 64u);
}

}  // namespace
}  // namespace partet
