// Out-of-line part of the error types: internal failures carry file:line.
#include "core/error.hpp"

namespace partet {

void internal_failure(const char* file, int line, const std::string& what) {
  throw InternalError(std::string("internal error at ") + file + ":" + std::to_string(line) +
                      ": " + what);
}

}  // namespace partet
