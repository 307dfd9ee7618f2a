// Wall-clock and CPU-time stopwatch (CPU time of this process = this rank),
// and the process's peak resident memory.
#pragma once

#include <chrono>
#include <ctime>

namespace partet {

class Stopwatch {
 public:
  Stopwatch() { restart(); }
  void restart() {
    wall0_ = std::chrono::steady_clock::now();
    cpu0_ = cpu_now();
  }
  double wall() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  }
  double cpu() const { return cpu_now() - cpu0_; }

  static double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }

 private:
  std::chrono::steady_clock::time_point wall0_;
  double cpu0_ = 0;
};

// Peak resident set size of this process so far, in MiB.
double peak_rss_mib();

}  // namespace partet
