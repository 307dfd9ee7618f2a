// One attempt of the meshing pipeline (mesh_once, mesh_command.cpp) and
// what run_mesh (run_mesh.cpp) learns when it leaves front faces.
#pragma once

#include "core/log.hpp"
#include "parallel/comm.hpp"
#include "pipeline/options.hpp"

namespace partet {

// One attempt of run_mesh (see there): whether the Delaunay fill runs and
// which tree-less strategies; the tree is the options' (min_core 0: the
// first tree, not refined for a thin core).
struct MeshAttempt {
  bool fill = true;          // the Delaunay fill, where the options and the input have it
  bool once = false;         // one tree-less start: short growth, the default going on from a few faces
                             // (nothing without tree-less removals)
  bool short_growth = true;  // short growth first (false: it failed on this tree and fill already)
  bool shape_order = false;  // targets best shape first
  // On P > 1 ranks, the tree-supported removals on rank 0 alone, as on one
  // rank (tree_removal_step.hpp), with no boundary partition and the tree
  // and core gathered on rank 0 only: every attempt unless the options put
  // the removals on the ranks (MeshOptions::removals_on_ranks), and every
  // retry, so that the tree-less removals get one rank's front (the ranks'
  // front for stress seed 5193 without the fill left short growth 1,078
  // faces; one rank's closes).
  bool removals_on_root = false;
  bool last = false;         // faces left end the run (exit 3); so do they without tree-less removals
                             // on a tree not refined for a thin core
  const char* report_key = nullptr;  // set true in the report, for the attempts after the first
};

// Thrown on every rank when an attempt that is not the last leaves front
// faces: whether its tree was refined for a thin core and whether the
// Delaunay fill ran, which decide the attempts that follow.
struct FrontLeftOpen {
  bool refined = false;
  bool filled = false;
};

// The pipeline once, with `attempt`'s choices: returns the exit code, or
// throws FrontLeftOpen on every rank when the front did not close and the
// attempt is not the last (partet::Error for an error all ranks agree on).
int mesh_once(const MeshOptions& options, const Comm& comm, const Log& log, const MeshAttempt& attempt);

}  // namespace partet
