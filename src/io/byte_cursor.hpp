// A bounds-checked little-endian reader over the bytes of a binary file.
// Every error names "file: byte N"; a count is checked against the bytes
// left before anything is allocated for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace partet {

class ByteCursor {
 public:
  ByteCursor(std::string_view bytes, std::string file, size_t start = 0)
      : bytes_(bytes), file_(std::move(file)), pos_(start) {}

  size_t offset() const { return pos_; }
  size_t remaining() const { return pos_ <= bytes_.size() ? bytes_.size() - pos_ : 0; }

  // Fails unless `count` items of `item_size` bytes remain.
  void need(uint64_t count, uint64_t item_size, const char* what) const {
    if (item_size != 0 && count > remaining() / item_size)
      fail(std::string("truncated: ") + what + " needs " + std::to_string(count) + " x " +
           std::to_string(item_size) + " bytes, " + std::to_string(remaining()) + " left");
  }

  template <class T>
  T read(const char* what) {
    need(1, sizeof(T), what);
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }

  std::string_view take(size_t n, const char* what) {
    need(n, 1, what);
    std::string_view s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }

  void skip(size_t n, const char* what) { take(n, what); }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_ + ": byte " + std::to_string(pos_) + ": " + message);
  }

 private:
  std::string_view bytes_;
  std::string file_;
  size_t pos_;
};

}  // namespace partet
