// migrate_bytes: a stable counting sort of the records by destination rank,
// one personalised exchange, and the source rank of every received record.
#include "parallel/migrate.hpp"

#include <string>

#include "core/error.hpp"

namespace partet {

void throw_migrate_size_mismatch() {
  throw InternalError("migrate: values.size() must be destination.size() * per_record");
}

std::vector<char> migrate_bytes(const Comm& comm, const int32_t* destination, const void* records, size_t n,
                                size_t record_bytes, std::vector<int32_t>* sources) {
  const size_t p = static_cast<size_t>(comm.size());
  std::vector<int64_t> send_bytes(p, 0);
  for (size_t i = 0; i < n; ++i) {
    int32_t d = destination[i];
    if (d < 0 || static_cast<size_t>(d) >= p)
      throw InternalError("migrate: record " + std::to_string(i) + " has destination " + std::to_string(d) +
                          ", not a rank of " + std::to_string(p));
    send_bytes[static_cast<size_t>(d)] += static_cast<int64_t>(record_bytes);
  }
  // Records keep their relative order within each destination.
  std::vector<size_t> write_at(p, 0);
  for (size_t r = 1; r < p; ++r) write_at[r] = write_at[r - 1] + static_cast<size_t>(send_bytes[r - 1]);
  std::vector<char> send(n * record_bytes);
  const char* in = static_cast<const char*>(records);
  for (size_t i = 0; i < n; ++i) {
    size_t& at = write_at[static_cast<size_t>(destination[i])];
    std::memcpy(send.data() + at, in + i * record_bytes, record_bytes);
    at += record_bytes;
  }
  std::vector<int64_t> recv_bytes;
  std::vector<char> recv = comm.all_to_all(send, send_bytes, recv_bytes);
  if (sources != nullptr) {
    sources->clear();
    if (record_bytes > 0) {
      sources->reserve(recv.size() / record_bytes);
      for (size_t r = 0; r < p; ++r)
        sources->insert(sources->end(), static_cast<size_t>(recv_bytes[r]) / record_bytes, static_cast<int32_t>(r));
    }
  }
  return recv;
}

}  // namespace partet
