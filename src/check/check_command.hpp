// `partet check MESH [--surface SURFACE] [--json]`: validates a volume mesh
// (and its boundary against the surface) and prints the verdict and quality.
// Exit code 0 valid, 1 invalid; unreadable input throws InputError (2).
#pragma once

#include <string>

namespace partet {

struct CheckOptions {
  std::string mesh;
  std::string surface;  // empty: no boundary comparison
  bool json = false;    // JSON on stdout instead of text
};

int run_check(const CheckOptions& options);

}  // namespace partet
