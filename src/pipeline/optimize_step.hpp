// The pipeline's quality optimization step (paper §4.1 steps 11-12) on the
// mesh the face removals made, whole on rank 0: optimize_distributed (on
// one rank, optimize_mesh on the whole mesh) and the step's report counts:
// quality before and after, what the optimizer did, where its time went
// and, on P > 1 ranks, the tets of each rank's part and of the band.
#pragma once

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"
#include "parallel/comm.hpp"
#include "pipeline/report.hpp"

namespace partet {

// Collective. `after` gets the whole mesh's quality after (on rank 0); the
// counts are rank 0's (empty elsewhere).
ojson optimize_step(const Comm& comm, TetMesh& mesh, const OptimizeOptions& options, QualityStats& after);

}  // namespace partet
