// The replacement operator new (memory/huge_page_new.hpp): large blocks are
// mapped on their own at a 2 MiB boundary, advised for huge pages where the
// kernel offers them, and unmapped when deleted; every form of new and
// delete, and blocks past the registry's capacity, keep their contents.
#include <gtest/gtest.h>

#include <cstdint>
#include <algorithm>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "memory/huge_page_new.hpp"

namespace partet {
namespace {

constexpr uintptr_t kTwoMiB = uintptr_t{2} << 20;

// The VmFlags line of the mapping of /proc/self/smaps holding `address`,
// or "" when no mapping holds it.
std::string vm_flags_of(uintptr_t a) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= a && a < hi;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

bool kernel_offers_huge_pages() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
}

TEST(HugePageNew, LargeBlocksAreMappedAlignedAndUnmapped) {
  if (!huge_page_new_in_use()) GTEST_SKIP() << "sanitizer build: the sanitizer's allocator is in use";
  const size_t live = huge_page_blocks_live();
  auto* block = new uint32_t[(kHugeBlockBytes * 3) / sizeof(uint32_t)];
  const auto address = reinterpret_cast<uintptr_t>(block);
  EXPECT_EQ(address % kTwoMiB, 0u);
  EXPECT_EQ(huge_page_blocks_live(), live + 1);
  block[0] = 7;
  const std::string flags = vm_flags_of(address);
  ASSERT_FALSE(flags.empty());
  if (kernel_offers_huge_pages()) {
    EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  }
  delete[] block;
  EXPECT_EQ(huge_page_blocks_live(), live);
  // Unmapped: no mapping holds the block's address, or one made since (not
  // advised: this test made none).
  EXPECT_EQ(vm_flags_of(address).find(" hg"), std::string::npos);

  auto small = std::make_unique<char[]>(kHugeBlockBytes - 1);
  EXPECT_EQ(huge_page_blocks_live(), live);
}

TEST(HugePageNew, EveryFormKeepsItsContents) {
  // Vectors (sized delete), nothrow arrays and plain arrays on both sides
  // of the threshold, more arrays at once than the registry holds (only
  // the first and the last ones touched: a touched page is 2 MiB), freed in
  // random order.
  const size_t live = huge_page_blocks_live();
  std::mt19937 random(5);
  std::vector<std::vector<uint32_t>> vectors;
  std::vector<std::pair<uint64_t*, size_t>> nothrows;
  for (int i = 0; i < 40; ++i) {
    const size_t bytes = kHugeBlockBytes / 2 + random() % (kHugeBlockBytes * 2);
    vectors.emplace_back(bytes / 4, static_cast<uint32_t>(i));
    const size_t words = bytes / 8;
    auto* n = new (std::nothrow) uint64_t[words];
    ASSERT_NE(n, nullptr);
    n[words - 1] = static_cast<uint64_t>(i) * 3;
    nothrows.emplace_back(n, words);
  }
  std::vector<std::unique_ptr<uint8_t[]>> arrays;
  const auto touched = [](size_t i) { return i < 20 || i >= kHugeBlockSlots; };
  for (size_t i = 0; i < kHugeBlockSlots + 20; ++i) {
    arrays.emplace_back(new uint8_t[kHugeBlockBytes]);
    if (!touched(i)) continue;
    arrays.back()[0] = static_cast<uint8_t>(i);
    arrays.back()[kHugeBlockBytes - 1] = static_cast<uint8_t>(i + 1);
  }
  if (huge_page_new_in_use()) {
    EXPECT_EQ(huge_page_blocks_live(), kHugeBlockSlots);
  }
  for (size_t i = 0; i < vectors.size(); ++i) {
    EXPECT_EQ(vectors[i].front(), static_cast<uint32_t>(i));
    EXPECT_EQ(vectors[i].back(), static_cast<uint32_t>(i));
    EXPECT_EQ(nothrows[i].first[nothrows[i].second - 1], static_cast<uint64_t>(i) * 3);
  }
  for (size_t i = 0; i < arrays.size(); ++i) {
    if (!touched(i)) continue;
    EXPECT_EQ(arrays[i][0], static_cast<uint8_t>(i));
    EXPECT_EQ(arrays[i][kHugeBlockBytes - 1], static_cast<uint8_t>(i + 1));
  }
  std::shuffle(vectors.begin(), vectors.end(), random);
  std::shuffle(arrays.begin(), arrays.end(), random);
  vectors.clear();
  for (auto& [p, words] : nothrows) delete[] p;
  arrays.clear();
  EXPECT_EQ(huge_page_blocks_live(), live);
}

}  // namespace
}  // namespace partet
