// partition_boundary_step: the three phases timed apart, and their counts
// per rank.
#include "pipeline/partition_step.hpp"

#include <utility>

#include "core/timer.hpp"
#include "partition/boundary_front.hpp"
#include "partition/boundary_partition.hpp"

namespace partet {

const char* bisection_name(BisectionMethod method) {
  switch (method) {
    case BisectionMethod::kRob: return "rob";
    case BisectionMethod::kRib: return "rib";
    case BisectionMethod::kMrob: break;
  }
  return "mrob";
}

ojson partition_boundary_step(const Comm& comm, const LinearOctree& view, const TemplateCore& core,
                              const RootCube& root, const SurfaceMesh& surface, BisectionMethod method,
                              BoundaryPartition& out) {
  Stopwatch watch;
  MigrationBytes exchanged;
  const FrontPart before = make_boundary_front(comm, view, core, root, surface, &exchanged);
  const double front_s = watch.wall();
  const double imbalance_before = work_imbalance(comm, before);

  watch.restart();
  PartitionResult cut = partition_front_leaves(comm, before, root, method);
  const double bisection_s = watch.wall();

  watch.restart();
  MigrationBytes migrated;
  out.front = migrate_front_part(comm, before, cut.destination, &migrated);
  out.separators = std::move(cut.separators);
  const double migration_s = watch.wall();

  const int64_t leaves = static_cast<int64_t>(out.front.leaves.size());
  const int64_t faces = static_cast<int64_t>(out.front.num_faces());
  ojson c;
  c["method"] = bisection_name(method);
  c["leaves"] = comm.sum(leaves);
  c["front faces"] = comm.sum(faces);
  c["imbalance before"] = imbalance_before;
  c["imbalance"] = work_imbalance(comm, out.front);
  c["leaves per rank"] = comm.all_gather(leaves);
  c["work per rank"] = comm.all_gather(faces);
  c["vertices per rank"] = comm.all_gather(static_cast<int64_t>(out.front.num_vertices()));
  c["bytes migrated per rank"] = comm.all_gather(migrated.sent);
  c["bytes received per rank"] = comm.all_gather(migrated.received);
  c["front exchange bytes per rank"] = comm.all_gather(exchanged.sent);
  c["front s per rank"] = comm.all_gather(front_s);
  c["bisection s per rank"] = comm.all_gather(bisection_s);
  c["migration s per rank"] = comm.all_gather(migration_s);
  return c;
}

}  // namespace partet
