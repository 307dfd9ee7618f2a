// The run report: every pipeline step timed per rank (wall and CPU), its
// counts, peak memory per rank; logged as one line per step on stderr and
// written as JSON with --report. Steps are collective: every rank runs them.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "core/log.hpp"
#include "parallel/comm.hpp"

namespace partet {

using ojson = nlohmann::ordered_json;

class RunReport {
 public:
  RunReport(const Comm& comm, const Log& log);

  void set(const std::string& key, ojson value) { root_[key] = std::move(value); }

  // Runs `work` on every rank as step `name`: times it, agrees on errors
  // (collective_step), gathers each rank's wall and CPU time, and logs the
  // step with the counts `work` returned (rank 0's).
  void run_step(const std::string& name, const std::function<ojson()>& work);

  // Completes the report with the outcome and per-rank peak memory
  // (collective), and returns it.
  const ojson& finish(int exit_code, const std::string& message);

  // Writes the report to `path` (rank 0 only; atomic).
  void write(const std::string& path) const;

  const ojson& json() const { return root_; }

 private:
  const Comm& comm_;
  const Log& log_;
  ojson root_;
  double wall_total_ = 0;
};

// "12 triangles, 8 vertices" from {"triangles": 12, "vertices": 8}.
std::string format_counts(const ojson& counts);

}  // namespace partet
