// Runs one step of work on every rank and makes every rank agree on its
// outcome: if any rank throws, all ranks throw the same error (the message of
// the lowest failing rank, with its exit code), so no rank is left waiting in
// a later collective call and the job ends with one clear message.
#pragma once

#include <functional>

#include "parallel/comm.hpp"

namespace partet {

void collective_step(const Comm& comm, const std::function<void()>& work);

}  // namespace partet
