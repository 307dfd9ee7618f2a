// Appending numbers to a text buffer for the text mesh writers: reals with 17
// significant digits (like printf "%.17g", so every double reads back
// bit-exact, "inf"/"nan" included) and unsigned integers. No locale, no
// allocation beyond the buffer's growth.
#pragma once

#include <charconv>
#include <cstdint>
#include <string>

namespace partet {

inline void append_real(std::string& out, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 17);
  out.append(buf, r.ptr);
}

inline void append_uint(std::string& out, uint64_t v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, r.ptr);
}

}  // namespace partet
