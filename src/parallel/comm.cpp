// Comm and MpiSession: checked MPI calls on one communicator.
#include "parallel/comm.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

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

void Comm::idle_barrier() const {
  if (serial_ || size_ == 1) return;
  MPI_Request request;
  check_mpi(MPI_Ibarrier(comm_, &request), "MPI_Ibarrier");
  int done = 0;
  for (long pause = 1;; pause = std::min(2 * pause, kIdlePauseMicros)) {
    check_mpi(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done) return;
    std::this_thread::sleep_for(std::chrono::microseconds(pause));
  }
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

namespace {

// MPI counts are int: reduce long arrays in pieces.
constexpr size_t kReduceChunk = size_t{1} << 28;

void reduce_in_place(MPI_Comm comm, void* values, size_t n, MPI_Datatype type, size_t type_bytes, MPI_Op op,
                     const char* what) {
  char* bytes = static_cast<char*>(values);
  for (size_t begin = 0; begin < n; begin += kReduceChunk) {
    size_t count = std::min(kReduceChunk, n - begin);
    check_mpi(MPI_Allreduce(MPI_IN_PLACE, bytes + begin * type_bytes, static_cast<int>(count), type, op, comm), what);
  }
}

}  // namespace

void Comm::sum(int64_t* values, size_t n) const {
  if (serial_) return;
  reduce_in_place(comm_, values, n, MPI_INT64_T, sizeof(int64_t), MPI_SUM, "MPI_Allreduce(sum array)");
}

void Comm::min(double* values, size_t n) const {
  if (serial_) return;
  reduce_in_place(comm_, values, n, MPI_DOUBLE, sizeof(double), MPI_MIN, "MPI_Allreduce(min array)");
}

void Comm::max(double* values, size_t n) const {
  if (serial_) return;
  reduce_in_place(comm_, values, n, MPI_DOUBLE, sizeof(double), MPI_MAX, "MPI_Allreduce(max array)");
}

std::vector<char> Comm::all_to_all(const std::vector<char>& send, const std::vector<int64_t>& send_bytes,
                                   std::vector<int64_t>& recv_bytes) const {
  const size_t p = static_cast<size_t>(size_);
  if (send_bytes.size() != p) throw InternalError("Comm::all_to_all: one byte count per rank expected");
  int64_t send_total = 0;
  for (int64_t b : send_bytes) send_total += b;
  if (send_total != static_cast<int64_t>(send.size()))
    throw InternalError("Comm::all_to_all: byte counts do not add up");
  if (serial_) {
    recv_bytes = send_bytes;
    return send;
  }
  recv_bytes.assign(p, 0);
  check_mpi(MPI_Alltoall(send_bytes.data(), 1, MPI_INT64_T, recv_bytes.data(), 1, MPI_INT64_T, comm_),
            "MPI_Alltoall(counts)");
  int64_t total = 0;
  for (int64_t b : recv_bytes) total += b;
  std::vector<char> recv(static_cast<size_t>(total));
  // One message per chunk of at most 1 GiB; MPI keeps the chunks of a pair in order.
  constexpr int64_t kChunk = int64_t{1} << 30;
  constexpr int kTag = 7400;
  std::vector<MPI_Request> requests;
  int64_t recv_at = 0, send_at = 0;
  for (size_t r = 0; r < p; ++r) {
    for (int64_t at = 0; at < recv_bytes[r]; at += kChunk) {
      int count = static_cast<int>(std::min(kChunk, recv_bytes[r] - at));
      requests.emplace_back();
      check_mpi(MPI_Irecv(recv.data() + recv_at + at, count, MPI_CHAR, static_cast<int>(r), kTag, comm_,
                          &requests.back()),
                "MPI_Irecv");
    }
    recv_at += recv_bytes[r];
  }
  for (size_t r = 0; r < p; ++r) {
    for (int64_t at = 0; at < send_bytes[r]; at += kChunk) {
      int count = static_cast<int>(std::min(kChunk, send_bytes[r] - at));
      requests.emplace_back();
      check_mpi(MPI_Isend(send.data() + send_at + at, count, MPI_CHAR, static_cast<int>(r), kTag, comm_,
                          &requests.back()),
                "MPI_Isend");
    }
    send_at += send_bytes[r];
  }
  check_mpi(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  return recv;
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

std::vector<std::string> Comm::all_gather(const std::string& bytes) const {
  if (serial_) return {bytes};
  const std::vector<int64_t> sizes = all_gather(static_cast<int64_t>(bytes.size()));
  std::string all;
  if (rank_ == 0)
    for (const std::string& part : gather(bytes, 0)) all += part;
  else
    gather(bytes, 0);
  broadcast(all, 0);
  std::vector<std::string> out;
  size_t at = 0;
  for (int64_t n : sizes) {
    out.push_back(all.substr(at, static_cast<size_t>(n)));
    at += static_cast<size_t>(n);
  }
  return out;
}

void Comm::abort(int code) const {
  if (!serial_) MPI_Abort(comm_, code);
  std::exit(code);
}

}  // namespace partet
