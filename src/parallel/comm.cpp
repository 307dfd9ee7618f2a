// Comm and MpiSession: checked MPI calls on one communicator.
#include "parallel/comm.hpp"

#include <cstdlib>
#include <string>

#include "core/error.hpp"

namespace partet {

void check_mpi(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(code, text, &len);
  throw InternalError(std::string("MPI call ") + what + " failed: " + std::string(text, static_cast<size_t>(len)));
}

bool MpiSession::launched() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(var) != nullptr) return true;
  const char* force = std::getenv("PARTET_FORCE_MPI");
  return force != nullptr && std::string(force) == "1";
}

MpiSession::MpiSession(int* argc, char*** argv) {
  if (!launched()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) check_mpi(MPI_Init(argc, argv), "MPI_Init");
  check_mpi(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
}

MpiSession::~MpiSession() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Finalize();
}

Comm::Comm(MPI_Comm comm) : comm_(comm) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  serial_ = !initialized || comm == MPI_COMM_NULL;
  if (serial_) return;
  check_mpi(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  check_mpi(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

Comm Comm::world() { return Comm(MPI_COMM_WORLD); }

void Comm::barrier() const {
  if (serial_) return;
  check_mpi(MPI_Barrier(comm_), "MPI_Barrier");
}

int64_t Comm::max(int64_t v) const {
  if (serial_) return v;
  int64_t r = 0;
  check_mpi(MPI_Allreduce(&v, &r, 1, MPI_INT64_T, MPI_MAX, comm_), "MPI_Allreduce(max)");
  return r;
}

int64_t Comm::sum(int64_t v) const {
  if (serial_) return v;
  int64_t r = 0;
  check_mpi(MPI_Allreduce(&v, &r, 1, MPI_INT64_T, MPI_SUM, comm_), "MPI_Allreduce(sum)");
  return r;
}

double Comm::max(double v) const {
  if (serial_) return v;
  double r = 0;
  check_mpi(MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce(max)");
  return r;
}

double Comm::sum(double v) const {
  if (serial_) return v;
  double r = 0;
  check_mpi(MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_SUM, comm_), "MPI_Allreduce(sum)");
  return r;
}

std::vector<double> Comm::all_gather(double v) const {
  if (serial_) return {v};
  std::vector<double> r(static_cast<size_t>(size_));
  check_mpi(MPI_Allgather(&v, 1, MPI_DOUBLE, r.data(), 1, MPI_DOUBLE, comm_), "MPI_Allgather");
  return r;
}

std::vector<int64_t> Comm::all_gather(int64_t v) const {
  if (serial_) return {v};
  std::vector<int64_t> r(static_cast<size_t>(size_));
  check_mpi(MPI_Allgather(&v, 1, MPI_INT64_T, r.data(), 1, MPI_INT64_T, comm_), "MPI_Allgather");
  return r;
}

void Comm::broadcast(std::string& s, int root) const {
  if (serial_) return;
  int64_t n = static_cast<int64_t>(s.size());
  check_mpi(MPI_Bcast(&n, 1, MPI_INT64_T, root, comm_), "MPI_Bcast(size)");
  s.resize(static_cast<size_t>(n));
  if (n > 0) check_mpi(MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, comm_), "MPI_Bcast");
}

std::vector<std::string> Comm::gather(const std::string& bytes, int root) const {
  if (serial_) return {bytes};
  int64_t n = static_cast<int64_t>(bytes.size());
  std::vector<int64_t> sizes(static_cast<size_t>(size_));
  check_mpi(MPI_Gather(&n, 1, MPI_INT64_T, sizes.data(), 1, MPI_INT64_T, root, comm_), "MPI_Gather(size)");
  std::vector<std::string> out;
  if (rank_ == root) {
    out.resize(static_cast<size_t>(size_));
    for (int r = 0; r < size_; ++r) out[static_cast<size_t>(r)].resize(static_cast<size_t>(sizes[static_cast<size_t>(r)]));
  }
  // Point-to-point per rank: no 2 GiB limit on the total, one message each.
  constexpr int kTag = 7301;
  if (rank_ == root) {
    out[static_cast<size_t>(root)] = bytes;
    for (int r = 0; r < size_; ++r) {
      if (r == root) continue;
      std::string& buf = out[static_cast<size_t>(r)];
      check_mpi(MPI_Recv(buf.data(), static_cast<int>(buf.size()), MPI_CHAR, r, kTag, comm_, MPI_STATUS_IGNORE),
                "MPI_Recv");
    }
  } else {
    check_mpi(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, root, kTag, comm_), "MPI_Send");
  }
  return out;
}

void Comm::abort(int code) const {
  if (!serial_) MPI_Abort(comm_, code);
  std::exit(code);
}

}  // namespace partet
