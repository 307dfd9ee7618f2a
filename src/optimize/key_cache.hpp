// A map from 64-bit keys to 32-bit values in a fixed number of slots: each
// key lives in the one slot its hash picks, and a newer key takes the slot
// of an older one. Its memory is bounded whatever the mesh's size (64 to
// 65,536 slots of 16 bytes, twice the keys the caller expects), which
// suits what the optimizer remembers of its recent failures: the work that
// asks about them again comes soon after (the tets of one block of slots,
// worst first), and a forgotten failure is only tried again. The bound
// below matters too: the optimizer runs on meshes of a few tets (the
// small-mesh alternatives), where a fixed 1 MiB table to clear cost more
// than the rest of the optimization.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/hash_mix.hpp"

namespace partet {

class KeyCache {
 public:
  explicit KeyCache(size_t keys) {
    size_t slots = kMinSlots;
    while (slots < 2 * keys && slots < kMaxSlots) slots *= 2;
    slots_.resize(slots);
  }
  // The value kept for `key`, or null.
  const uint32_t* find(uint64_t key) const {
    const Slot& slot = slots_[index(key)];
    return slot.used && slot.key == key ? &slot.value : nullptr;
  }
  void put(uint64_t key, uint32_t value) { slots_[index(key)] = {key, value, true}; }

 private:
  static constexpr size_t kMinSlots = 64, kMaxSlots = size_t{1} << 16;
  struct Slot {
    uint64_t key = 0;
    uint32_t value = 0;
    bool used = false;
  };
  size_t index(uint64_t key) const { return hash_mix(key) & (slots_.size() - 1); }
  std::vector<Slot> slots_;
};

}  // namespace partet
