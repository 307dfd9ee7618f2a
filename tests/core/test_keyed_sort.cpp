// Tests of sort_keyed_in_index_order: the (key, index) order std::sort
// gives, on keys with many ties, on keys differing only in high or only in
// low bytes, on equal keys and tiny inputs; indices out of order are
// refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "core/keyed_sort.hpp"

namespace partet {
namespace {

std::vector<KeyedIndex> keyed_from(const std::vector<uint64_t>& keys) {
  std::vector<KeyedIndex> out;
  for (size_t i = 0; i < keys.size(); ++i) out.push_back({keys[i], static_cast<uint32_t>(i)});
  return out;
}

void expect_as_std_sort(const std::vector<uint64_t>& keys) {
  std::vector<KeyedIndex> mine = keyed_from(keys), reference = keyed_from(keys);
  sort_keyed_in_index_order(mine);
  std::sort(reference.begin(), reference.end());
  EXPECT_EQ(mine, reference);
}

TEST(KeyedSort, IsStdSortOnRandomKeysWithTies) {
  std::mt19937_64 rng(3);
  std::vector<uint64_t> wide(20000), few(20000);
  for (uint64_t& k : wide) k = rng() >> 1;
  for (uint64_t& k : few) k = rng() % 37;  // every key repeated hundreds of times
  expect_as_std_sort(wide);
  expect_as_std_sort(few);
}

TEST(KeyedSort, KeysDifferingInHighOrLowBytesOnly) {
  std::mt19937_64 rng(4);
  std::vector<uint64_t> high(5000), low(5000);
  for (uint64_t& k : high) k = (rng() % 200) << 56 | 0x00123456789abcdeULL;
  for (uint64_t& k : low) k = 0x7f00000000000000ULL | (rng() % 300);
  expect_as_std_sort(high);
  expect_as_std_sort(low);
}

TEST(KeyedSort, EqualKeysAndTinyInputsKeepTheirOrder) {
  expect_as_std_sort({});
  expect_as_std_sort({42});
  expect_as_std_sort({5, 5, 5, 5});
  expect_as_std_sort({UINT64_MAX, 0, UINT64_MAX, 1});
}

TEST(KeyedSort, IndicesOutOfOrderAreRefused) {
  std::vector<KeyedIndex> keyed = {{1, 2}, {0, 1}};
  EXPECT_THROW(sort_keyed_in_index_order(keyed), InternalError);
}

}  // namespace
}  // namespace partet
