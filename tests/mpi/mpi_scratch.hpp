// A scratch directory shared by the ranks of an MPI test.
#pragma once

#include <filesystem>
#include <string>

#include "parallel/comm.hpp"

namespace partet::test {

// /tmp/partet_mpi_<name>_<rank count>, emptied and made by rank 0; every
// rank waits for it.
inline std::string shared_dir(const Comm& comm, const std::string& name) {
  const std::string dir = "/tmp/partet_mpi_" + name + "_" + std::to_string(comm.size());
  if (comm.rank() == 0) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  comm.barrier();
  return dir;
}

}  // namespace partet::test
