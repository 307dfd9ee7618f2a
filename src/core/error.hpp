// Errors partet reports to users, each with its process exit code:
// input errors (2), meshing that cannot finish (3), internal invariant
// violations (4). Messages name the file, the entities and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace partet {

enum ExitCode : int {
  kExitOk = 0,
  kExitInvalid = 1,   // `partet check`: the mesh is not valid
  kExitInput = 2,     // bad input: unreadable, malformed, not a closed manifold...
  kExitMeshing = 3,   // meshing could not finish
  kExitInternal = 4,  // a broken internal invariant (a bug)
};

class Error : public std::runtime_error {
 public:
  Error(int exit_code, const std::string& message)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(kExitInput, message) {}
};

class MeshingError : public Error {
 public:
  explicit MeshingError(const std::string& message) : Error(kExitMeshing, message) {}
};

class InternalError : public Error {
 public:
  explicit InternalError(const std::string& message) : Error(kExitInternal, message) {}
};

[[noreturn]] void internal_failure(const char* file, int line, const std::string& what);

}  // namespace partet

// Checks an internal invariant; on failure throws InternalError with file:line.
#define PARTET_ASSERT(cond, msg)                                                 \
  do {                                                                           \
    if (!(cond))                                                                 \
      ::partet::internal_failure(__FILE__, __LINE__,                             \
                                 std::string("invariant '" #cond "' broken: ") + \
                                     (msg));                                     \
  } while (0)
