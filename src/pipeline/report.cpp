// RunReport: per-step, per-rank timings and counts as JSON.
#include "pipeline/report.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/file_bytes.hpp"
#include "parallel/collective_step.hpp"

namespace partet {

RunReport::RunReport(const Comm& comm, const Log& log) : comm_(comm), log_(log) {
  root_["partet_version"] = PARTET_VERSION;
  root_["ranks"] = comm.size();
  root_["steps"] = ojson::array();
}

void RunReport::run_step(const std::string& name, const std::function<ojson()>& work) {
  Stopwatch watch;
  ojson counts = ojson::object();
  std::string failure;
  int failure_code = 0;
  try {
    collective_step(comm_, [&] { counts = work(); });
  } catch (const Error& e) {
    failure = e.what();
    failure_code = e.exit_code();
    counts = ojson::object();
  }
  double wall = watch.wall();
  double cpu = watch.cpu();
  ojson step;
  step["name"] = name;
  step["wall_s"] = comm_.all_gather(wall);
  step["cpu_s"] = comm_.all_gather(cpu);
  step["peak_rss_mib"] = comm_.all_gather(peak_rss_mib());
  step["counts"] = counts;
  if (!failure.empty()) step["error"] = failure;
  root_["steps"].push_back(step);
  double wall_max = comm_.max(wall);
  wall_total_ += wall_max;
  // Every rank holds the same agreed error: all rethrow it together.
  if (failure_code != 0) throw Error(failure_code, failure);
  log_.step(name, wall_max, format_counts(counts));
}

const ojson& RunReport::finish(int exit_code, const std::string& message) {
  root_["exit_code"] = exit_code;
  if (!message.empty()) root_["message"] = message;
  root_["wall_s"] = wall_total_;
  root_["peak_rss_mib"] = comm_.all_gather(peak_rss_mib());
  return root_;
}

void RunReport::write(const std::string& path) const {
  if (comm_.rank() != 0) return;
  write_file_atomic(path, root_.dump(2) + "\n");
}

std::string format_counts(const ojson& counts) {
  std::string out;
  for (auto it = counts.begin(); it != counts.end(); ++it) {
    if (!out.empty()) out += ", ";
    if (it.value().is_string()) {
      out += it.key() + " " + it.value().get<std::string>();
    } else if (it.value().is_number_float()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6g", it.value().get<double>());
      out += it.key() + " " + buf;
    } else {
      out += it.value().dump() + " " + it.key();
    }
  }
  return out;
}

}  // namespace partet
