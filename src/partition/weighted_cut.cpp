// weighted_cut: byte-by-byte refinement of the crossing point of every slot,
// one all-reduce of a (slots x 256 x {weight, count}) histogram per round.
#include "partition/weighted_cut.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace partet {
namespace {

constexpr size_t kBuckets = 256;
constexpr size_t kRounds = 8 * kCutKeyWords;

// Byte `round` of point i's key, the most significant byte of the first
// word first.
size_t key_byte(const CutKeys& keys, size_t i, size_t round) {
  return static_cast<size_t>((keys.word(i, round / 8) >> (8 * (7 - round % 8))) & 0xff);
}

struct SlotState {
  int64_t below = 0;   // weight decided low so far
  size_t bucket = 0;   // this round's bucket of the crossing point
  bool done = false;   // decided before this round
  bool ends = false;   // decided by this round
  bool take_last = false;  // when it ends: whether the last undecided point goes low
};

}  // namespace

std::vector<uint8_t> weighted_cut(const Comm& comm, const CutKeys& keys, const uint64_t* weight,
                                  const int32_t* slot, size_t n, const std::vector<uint64_t>& target) {
  const size_t slots = target.size();
  std::vector<uint8_t> low(n, 0);
  std::vector<size_t> open;  // the undecided points
  for (size_t i = 0; i < n; ++i)
    if (slot[i] >= 0) open.push_back(i);
  std::vector<SlotState> state(slots);
  std::vector<int64_t> hist(slots * kBuckets * 2);

  for (size_t round = 0; round < kRounds; ++round) {
    std::fill(hist.begin(), hist.end(), 0);
    for (size_t i : open) {
      size_t at = (static_cast<size_t>(slot[i]) * kBuckets + key_byte(keys, i, round)) * 2;
      hist[at] += static_cast<int64_t>(weight[i]);
      hist[at + 1] += 1;
    }
    comm.sum(hist.data(), hist.size());

    bool all_done = true;
    for (size_t s = 0; s < slots; ++s) {
      SlotState& st = state[s];
      if (st.done) continue;
      const int64_t* h = &hist[s * kBuckets * 2];
      const int64_t want = static_cast<int64_t>(target[s]);
      // The first non-empty bucket where the running weight reaches the
      // target; the last non-empty one when none does (no points: none).
      int64_t before = st.below;
      size_t chosen = kBuckets;
      int64_t chosen_before = 0;
      for (size_t b = 0; b < kBuckets; ++b) {
        if (h[2 * b + 1] == 0) continue;
        chosen = b;
        chosen_before = before;
        before += h[2 * b];
        if (before >= want) break;
      }
      if (chosen == kBuckets) {  // no undecided point: the slot is empty
        st.done = true;
        continue;
      }
      st.bucket = chosen;
      st.below = chosen_before;
      const int64_t count = h[2 * chosen + 1];
      PARTET_ASSERT(count == 1 || round + 1 < kRounds, "cut keys must be distinct within a slot");
      if (count == 1) {
        st.ends = true;
        int64_t with = chosen_before + h[2 * chosen];
        st.take_last = want - chosen_before >= with - want;
      } else {
        all_done = false;
      }
    }

    size_t kept = 0;
    for (size_t i : open) {
      SlotState& st = state[static_cast<size_t>(slot[i])];
      size_t b = key_byte(keys, i, round);
      if (b < st.bucket) {
        low[i] = 1;
      } else if (b == st.bucket) {
        if (st.ends)
          low[i] = st.take_last ? 1 : 0;
        else
          open[kept++] = i;
      }
    }
    open.resize(kept);
    for (SlotState& st : state) {
      if (!st.ends) continue;
      st.done = true;
      st.ends = false;
    }
    if (all_done) break;
  }
  return low;
}

}  // namespace partet
