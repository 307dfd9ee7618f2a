// collective_step: agree on success or on the first rank's error.
#include "parallel/collective_step.hpp"

#include <exception>
#include <new>
#include <string>

#include "core/error.hpp"

namespace partet {

void collective_step(const Comm& comm, const std::function<void()>& work) {
  int code = 0;
  std::string message;
  try {
    work();
  } catch (const Error& e) {
    code = e.exit_code();
    message = e.what();
  } catch (const std::bad_alloc&) {
    code = kExitInternal;
    message = "out of memory";
  } catch (const std::exception& e) {
    code = kExitInternal;
    message = std::string("internal error: ") + e.what();
  }
  // Ranks done first sleep while the others work (spinning in MPI's
  // progress loop, a waiting rank burned its core through rank 0's serial
  // steps).
  comm.idle_barrier();
  // The lowest failing rank speaks for all.
  int64_t speaker = comm.max(code != 0 ? static_cast<int64_t>(comm.size() - comm.rank()) : 0);
  if (speaker == 0) return;
  int root = comm.size() - static_cast<int>(speaker);
  std::string text = std::to_string(code) + "\n" + message;
  comm.broadcast(text, root);
  size_t nl = text.find('\n');
  int agreed = std::stoi(text.substr(0, nl));
  std::string what = text.substr(nl + 1);
  if (comm.size() > 1 && root != 0) what = "rank " + std::to_string(root) + ": " + what;
  throw Error(agreed, what);
}

}  // namespace partet
