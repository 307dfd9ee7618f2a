// Points in messages: "(x, y, z)" with each coordinate in its shortest
// form that reads back to the same double (exact, and short where it can be).
#pragma once

#include <charconv>
#include <string>

namespace partet {

inline std::string real_text(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline std::string point_text(const double* p) {
  return "(" + real_text(p[0]) + ", " + real_text(p[1]) + ", " + real_text(p[2]) + ")";
}

}  // namespace partet
