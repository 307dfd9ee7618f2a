// The pipeline's boundary partition step (paper §4.1 step 3), on P > 1
// ranks after the templates: the initial front is built on the ranks owning
// its leaves (make_boundary_front), the boundary leaves are partitioned by
// recursive bisection weighted by their front faces
// (partition_front_leaves), and they move to their new ranks with their
// faces and vertices (migrate_front_part). Reports, per rank, the leaves,
// the work (front faces), the bytes migrated and the time of each phase,
// and the work imbalance (largest over mean) before and after.
#pragma once

#include <vector>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "partition/front_part.hpp"
#include "partition/recursive_bisection.hpp"
#include "pipeline/report.hpp"
#include "surface/surface_mesh.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

struct BoundaryPartition {
  FrontPart front;                    // this rank's share of the front after migration
  std::vector<Separator> separators;  // the cuts that made the partition
};

// Lower-case name of a bisection method: "rob", "rib" or "mrob".
const char* bisection_name(BisectionMethod method);

// Collective: the step on this rank's local view, core part and the whole
// surface; fills `out` and returns the step's counts.
ojson partition_boundary_step(const Comm& comm, const LinearOctree& view, const TemplateCore& core,
                              const RootCube& root, const SurfaceMesh& surface, BisectionMethod method,
                              BoundaryPartition& out);

}  // namespace partet
