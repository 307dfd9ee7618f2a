// Log: formatted step lines, notes and live progress on stderr.
#include "core/log.hpp"

#include <unistd.h>

#include <cstdio>

#include "core/timer.hpp"

namespace partet {

Log::Log(int rank, bool quiet, bool verbose)
    : enabled_(!quiet && (rank == 0 || verbose)),
      tty_(isatty(STDERR_FILENO) != 0),
      prefix_(rank == 0 && !verbose ? "" : "[" + std::to_string(rank) + "] ") {}

void Log::step(const std::string& name, double seconds, const std::string& counts) const {
  if (!enabled_) return;
  if (tty_ && last_progress_ >= 0) std::fputs("\r\033[K", stderr);
  last_progress_ = -1;
  std::fprintf(stderr, "%s  %-28s %9.3f s  %s\n", prefix_.c_str(), name.c_str(), seconds, counts.c_str());
}

void Log::note(const std::string& text) const {
  if (!enabled_) return;
  std::fprintf(stderr, "%snote: %s\n", prefix_.c_str(), text.c_str());
}

void Log::progress(const std::string& name, double fraction) const {
  if (!enabled_ || !tty_) return;
  double now = Stopwatch::cpu_now();
  if (last_progress_ >= 0 && now - last_progress_ < 0.1 && fraction < 1.0) return;
  last_progress_ = now;
  std::fprintf(stderr, "\r\033[K%s  %-28s %5.1f%%", prefix_.c_str(), name.c_str(), 100.0 * fraction);
  std::fflush(stderr);
}

}  // namespace partet
