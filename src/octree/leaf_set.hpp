// A set of leaf indices that only grows (a two-level bitset): one bit per
// leaf, and one summary bit per word of 64 leaves that is set when the
// word is not empty, so that a range query (LeafRangeQuery) can skip a run
// of leaves holding no member in a few word tests and list the members of
// a run without testing every leaf.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet {

class LeafSet {
 public:
  explicit LeafSet(size_t leaves = 0) : words_((leaves + 63) / 64, 0), summary_((words_.size() + 63) / 64, 0) {}

  void insert(size_t leaf) {
    words_[leaf >> 6] |= uint64_t{1} << (leaf & 63);
    summary_[leaf >> 12] |= uint64_t{1} << ((leaf >> 6) & 63);
  }
  bool contains(size_t leaf) const { return (words_[leaf >> 6] >> (leaf & 63)) & 1; }

  // True when a member lies in [b, e).
  bool any(size_t b, size_t e) const { return any_bit(words_, b, e, &summary_); }

  // Calls visit(leaf) for every member in [b, e), ascending.
  template <class Visit>
  void for_each(size_t b, size_t e, Visit&& visit) const {
    if (b >= e) return;
    const size_t we = (e - 1) >> 6;
    for (size_t w = b >> 6; w <= we;) {
      if ((w & 63) == 0 && w + 64 <= we && summary_[w >> 6] == 0) {
        w += 64;
        continue;
      }
      uint64_t bits = words_[w];
      if (w == b >> 6) bits &= bits_from(b);
      if (w == we) bits &= bits_through(e - 1);
      while (bits != 0) {
        visit((w << 6) + static_cast<size_t>(std::countr_zero(bits)));
        bits &= bits - 1;
      }
      ++w;
    }
  }

 private:
  static uint64_t bits_from(size_t i) { return ~uint64_t{0} << (i & 63); }
  static uint64_t bits_through(size_t i) { return ~uint64_t{0} >> (63 - (i & 63)); }
  // True when a bit in [b, e) of `bits` is set; the whole words in between
  // are looked up in `summary` (a bit per word of `bits`) when given.
  static bool any_bit(const std::vector<uint64_t>& bits, size_t b, size_t e, const std::vector<uint64_t>* summary) {
    if (b >= e) return false;
    const size_t wb = b >> 6, we = (e - 1) >> 6;
    if (wb == we) return (bits[wb] & bits_from(b) & bits_through(e - 1)) != 0;
    if ((bits[wb] & bits_from(b)) != 0 || (bits[we] & bits_through(e - 1)) != 0) return true;
    if (summary) return any_bit(*summary, wb + 1, we, nullptr);
    for (size_t w = wb + 1; w < we; ++w)
      if (bits[w] != 0) return true;
    return false;
  }

  std::vector<uint64_t> words_;    // bit i of word w: leaf 64 w + i
  std::vector<uint64_t> summary_;  // bit i of word s: word 64 s + i is not empty
};

}  // namespace partet
