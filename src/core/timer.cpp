// Peak resident memory from getrusage (Linux reports kilobytes).
#include "core/timer.hpp"

#include <sys/resource.h>

namespace partet {

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace partet
