// Flat byte images of arrays, for the messages between ranks: each array
// as its element count (8 bytes) then its elements' bytes. Reading checks
// every count against the bytes left (InternalError on a truncated image:
// the images are made by partet itself, never read from a user's file).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace partet {

template <class T>
void put_array(std::string& out, const T* data, size_t n) {
  const uint64_t count = n;
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  if (n > 0) out.append(reinterpret_cast<const char*>(data), n * sizeof(T));
}

template <class T>
void put_array(std::string& out, const std::vector<T>& v) {
  put_array(out, v.data(), v.size());
}

// The array at `pos`, which moves past it.
template <class T>
std::vector<T> get_array(const std::string& in, size_t& pos) {
  uint64_t n = 0;
  PARTET_ASSERT(pos + sizeof n <= in.size(), "truncated byte image");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  PARTET_ASSERT(n <= (in.size() - pos) / sizeof(T), "truncated byte image");
  std::vector<T> v(n);
  if (n > 0) std::memcpy(v.data(), in.data() + pos, n * sizeof(T));
  pos += n * sizeof(T);
  return v;
}

// Appends the array at `pos` to `out` (one copy), and moves past it.
template <class T>
void append_array(const std::string& in, size_t& pos, std::vector<T>& out) {
  uint64_t n = 0;
  PARTET_ASSERT(pos + sizeof n <= in.size(), "truncated byte image");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  PARTET_ASSERT(n <= (in.size() - pos) / sizeof(T), "truncated byte image");
  const size_t before = out.size();
  out.resize(before + n);
  if (n > 0) std::memcpy(out.data() + before, in.data() + pos, n * sizeof(T));
  pos += n * sizeof(T);
}

}  // namespace partet
