// A thin wrapper over one MPI communicator: every MPI call goes through it
// and is checked (a failing call throws InternalError naming the call).
// MpiSession owns MPI_Init/MPI_Finalize for the process.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace partet {

class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

class Comm {
 public:
  explicit Comm(MPI_Comm comm);
  static Comm world();

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm raw() const { return comm_; }

  void barrier() const;
  int64_t max(int64_t v) const;
  int64_t sum(int64_t v) const;
  double max(double v) const;
  double sum(double v) const;
  // Every rank's value, on every rank.
  std::vector<double> all_gather(double v) const;
  std::vector<int64_t> all_gather(int64_t v) const;
  void broadcast(std::string& s, int root) const;
  // Every rank's bytes, in rank order, on `root` (empty elsewhere).
  std::vector<std::string> gather(const std::string& bytes, int root) const;

  // Ends every rank of the job with `code` (used when ranks cannot agree).
  [[noreturn]] void abort(int code) const;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

// Throws InternalError "MPI call <what> failed: <MPI error string>" unless ok.
void check_mpi(int code, const char* what);

}  // namespace partet
