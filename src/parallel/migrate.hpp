// Migration of fixed-size records between ranks (one alltoallv of bytes).
// Contract: collective over `comm`; record i (record_bytes bytes at
// records + i * record_bytes) goes to rank destination[i], which must be in
// [0, comm.size()). Every rank ends with exactly the records destined to it,
// ordered by source rank, then by their order on the source rank, so the
// result is deterministic. Records are copied as bytes: trivially copyable
// data only. With one rank the records come back unchanged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "parallel/comm.hpp"

namespace partet {

// The received records as bytes; `sources`, when given, receives the source
// rank of each received record.
std::vector<char> migrate_bytes(const Comm& comm, const int32_t* destination, const void* records, size_t n,
                                size_t record_bytes, std::vector<int32_t>* sources = nullptr);

[[noreturn]] void throw_migrate_size_mismatch();

// Typed form: a record is `per_record` consecutive values of T (for example
// three doubles per point), so values.size() == destination.size() * per_record.
template <class T>
std::vector<T> migrate(const Comm& comm, const std::vector<int32_t>& destination, const std::vector<T>& values,
                       size_t per_record = 1, std::vector<int32_t>* sources = nullptr) {
  static_assert(std::is_trivially_copyable_v<T>, "migrate copies records as bytes");
  const size_t record_bytes = per_record * sizeof(T);
  if (values.size() != destination.size() * per_record) throw_migrate_size_mismatch();
  std::vector<char> bytes =
      migrate_bytes(comm, destination.data(), values.data(), destination.size(), record_bytes, sources);
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

}  // namespace partet
