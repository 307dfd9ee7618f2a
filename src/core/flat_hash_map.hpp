// An open-addressing hash map over one flat array of slots (linear probing,
// deletion by backward shift, so no tombstones): 12-16 bytes per slot
// where std::unordered_map spends a 32-48-byte heap node plus a bucket
// pointer per entry, and lookups touch one or two cache lines.
//
// Key must be trivially copyable and equality-comparable; Traits gives
//   static Key empty();                // a key never stored, marks a free slot
//   static uint64_t hash(const Key&);  // well mixed in every bit
// The table grows by doubling when more than 3/4 of its slots are taken
// and never shrinks (clear() keeps the slots). Iteration is not offered:
// callers that need an order keep their own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/error.hpp"

namespace partet {

template <class Key, class Value, class Traits>
class FlatHashMap {
 public:
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // Makes room for n entries without growing.
  void reserve(size_t n) {
    size_t capacity = 16;
    while (capacity * 3 < n * 4) capacity *= 2;
    if (capacity > slots_.size()) rehash(capacity);
  }

  // The value stored under `key`, or nullptr.
  const Value* find(const Key& key) const {
    if (slots_.empty()) return nullptr;
    for (size_t i = home(key);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.key == key) return &s.value;
      if (s.key == Traits::empty()) return nullptr;
    }
  }
  Value* find(const Key& key) { return const_cast<Value*>(static_cast<const FlatHashMap*>(this)->find(key)); }

  // The value stored under `key`, inserted as `initial` when missing.
  Value& get_or_insert(const Key& key, const Value& initial) {
    PARTET_ASSERT(!(key == Traits::empty()), "flat hash map: the empty key cannot be stored");
    if ((size_ + 1) * 4 > slots_.size() * 3) rehash(slots_.empty() ? 16 : 2 * slots_.size());
    size_t i = home(key);
    for (; !(slots_[i].key == Traits::empty()); i = (i + 1) & mask_)
      if (slots_[i].key == key) return slots_[i].value;
    slots_[i].key = key;
    slots_[i].value = initial;
    ++size_;
    return slots_[i].value;
  }

  // Removes `key`; false when it was not there.
  bool erase(const Key& key) {
    if (slots_.empty()) return false;
    size_t i = home(key);
    for (; !(slots_[i].key == key); i = (i + 1) & mask_)
      if (slots_[i].key == Traits::empty()) return false;
    // Backward shift: pull later entries of the probe run into the hole
    // when the hole lies on their way from their home slot.
    for (size_t j = (i + 1) & mask_;; j = (j + 1) & mask_) {
      if (slots_[j].key == Traits::empty()) break;
      const size_t h = home(slots_[j].key);
      const bool hole_on_way = ((j - h) & mask_) >= ((j - i) & mask_);
      if (!hole_on_way) continue;
      slots_[i] = slots_[j];
      i = j;
    }
    slots_[i].key = Traits::empty();
    --size_;
    return true;
  }

  void clear() {
    for (Slot& s : slots_) s.key = Traits::empty();
    size_ = 0;
  }

  // Bytes held by the slot array.
  size_t bytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  struct Slot {
    Key key;
    Value value;
  };

  size_t home(const Key& key) const { return static_cast<size_t>(Traits::hash(key)) & mask_; }

  void rehash(size_t capacity) {
    std::vector<Slot> old(capacity, Slot{Traits::empty(), Value{}});
    old.swap(slots_);
    mask_ = capacity - 1;
    for (const Slot& s : old) {
      if (s.key == Traits::empty()) continue;
      size_t i = home(s.key);
      while (!(slots_[i].key == Traits::empty())) i = (i + 1) & mask_;
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;
  size_t mask_ = 0;
  size_t size_ = 0;
};

}  // namespace partet
