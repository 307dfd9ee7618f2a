// `partet INPUT -o OUTPUT`: the meshing pipeline of DESIGN.md, step by step,
// on every rank, with the run report. Returns the process exit code; errors
// agreed on by all ranks are thrown as partet::Error.
#pragma once

#include "core/log.hpp"
#include "parallel/comm.hpp"
#include "pipeline/options.hpp"

namespace partet {

int run_mesh(const MeshOptions& options, const Comm& comm, const Log& log);

}  // namespace partet
