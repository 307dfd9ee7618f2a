// Progress messages on stderr: one line per finished step with its time and
// counts, notes, and a live percentage for long steps when stderr is a
// terminal. Only rank 0 speaks unless verbose; --quiet silences all but errors.
#pragma once

#include <string>

namespace partet {

class Log {
 public:
  Log(int rank, bool quiet, bool verbose);

  bool enabled() const { return enabled_; }
  // "  read surface         0.012 s  12 triangles, 8 vertices"
  void step(const std::string& name, double seconds, const std::string& counts) const;
  void note(const std::string& text) const;
  // Live "name 45%" line, rewritten in place; at most ten updates a second.
  void progress(const std::string& name, double fraction) const;

 private:
  bool enabled_;
  bool tty_;
  std::string prefix_;
  mutable double last_progress_ = -1;
};

}  // namespace partet
