// A map from 64-bit keys to 32-bit values in a fixed number of slots: each
// key lives in the one slot its hash picks, and a newer key takes the slot
// of an older one. Its memory is bounded whatever the mesh's size (1 MiB),
// which suits what the optimizer remembers of its recent failures: the
// work that asks about them again comes soon after (the tets of one block
// of slots, worst first), and a forgotten failure is only tried again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/hash_mix.hpp"

namespace partet {

class KeyCache {
 public:
  KeyCache() : slots_(kSlots) {}
  // The value kept for `key`, or null.
  const uint32_t* find(uint64_t key) const {
    const Slot& slot = slots_[index(key)];
    return slot.used && slot.key == key ? &slot.value : nullptr;
  }
  void put(uint64_t key, uint32_t value) { slots_[index(key)] = {key, value, true}; }

 private:
  static constexpr size_t kSlots = size_t{1} << 16;
  struct Slot {
    uint64_t key = 0;
    uint32_t value = 0;
    bool used = false;
  };
  static size_t index(uint64_t key) { return hash_mix(key) & (kSlots - 1); }
  std::vector<Slot> slots_;
};

}  // namespace partet
