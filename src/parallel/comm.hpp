// A thin wrapper over one MPI communicator: every MPI call goes through it
// and is checked (a failing call throws InternalError naming the call).
// MpiSession owns MPI_Init/MPI_Finalize for the process. Started without a
// launcher, partet does not initialise MPI at all (an OpenMPI singleton
// start costs half a second): Comm is then one rank and its collectives are
// the identity. PARTET_FORCE_MPI=1 initialises MPI anyway.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace partet {

class MpiSession {
 public:
  // Initialises MPI when launched by mpirun/mpiexec (or forced).
  MpiSession(int* argc, char*** argv);
  // True when this process was started by an MPI launcher.
  static bool launched();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

// The longest pause between tests of Comm::idle_barrier, in microseconds.
inline constexpr long kIdlePauseMicros = 500;

class Comm {
 public:
  explicit Comm(MPI_Comm comm);
  // MPI_COMM_WORLD, or one serial rank when MPI is not initialised.
  static Comm world();

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm raw() const { return comm_; }

  void barrier() const;
  // A barrier whose waiting ranks sleep (MPI_Ibarrier tested with growing
  // pauses, up to kIdlePauseMicros) instead of spinning in MPI's progress
  // loop: for the ends of steps where some ranks wait while others work.
  void idle_barrier() const;
  int64_t max(int64_t v) const;
  int64_t sum(int64_t v) const;
  double max(double v) const;
  double sum(double v) const;
  // Every rank's value, on every rank.
  std::vector<double> all_gather(double v) const;
  std::vector<int64_t> all_gather(int64_t v) const;
  // Element-wise over ranks, in place: every rank ends with the same array.
  void sum(int64_t* values, size_t n) const;
  void min(double* values, size_t n) const;
  void max(double* values, size_t n) const;
  // Personalised exchange: `send` holds the bytes for rank 0, then rank 1...,
  // send_bytes[d] of them for rank d (size() entries). Returns the bytes
  // received, concatenated in source rank order; recv_bytes[s] is how many
  // came from rank s. No 2 GiB limit: large messages go in chunks.
  std::vector<char> all_to_all(const std::vector<char>& send, const std::vector<int64_t>& send_bytes,
                               std::vector<int64_t>& recv_bytes) const;
  void broadcast(std::string& s, int root) const;
  // Every rank's bytes, in rank order, on `root` (empty elsewhere).
  std::vector<std::string> gather(const std::string& bytes, int root) const;
  // Every rank's bytes, in rank order, on every rank.
  std::vector<std::string> all_gather(const std::string& bytes) const;

  // Ends every rank of the job with `code` (used when ranks cannot agree).
  [[noreturn]] void abort(int code) const;

 private:
  MPI_Comm comm_;
  bool serial_ = false;  // no MPI: one rank, collectives are the identity
  int rank_ = 0;
  int size_ = 1;
};

// Throws InternalError "MPI call <what> failed: <MPI error string>" unless ok.
void check_mpi(int code, const char* what);

}  // namespace partet
