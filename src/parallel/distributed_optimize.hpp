// Quality optimization on P ranks (paper §4.1 steps 11-12) of a mesh held
// whole on rank 0:
//  1. partition: the tets' centroids are split by recursive inertial
//     bisection (partition_points, RIB) into P parts of equal tet counts;
//  2. each rank optimizes its part (optimize_mesh, mesh_parts.hpp): the
//     faces on the cuts are the parts' boundary, so their vertices stay
//     frozen and the parts need no communication while they work; the cut
//     vertices are passed as frozen with set_aside_stuck_on_frozen, so the
//     rounds on a part's worst tet pass over a worst tet stuck on a cut;
//  3. the parts are gathered and joined on rank 0;
//  4. the band: what the parts could not touch (the tets with a vertex on
//     a cut) and the worst of what they left (the tets with a dihedral
//     angle under kBandAngle degrees), grown by one ring of tets, is
//     optimized once more, the rest frozen around it, in at most
//     kBandPasses passes: as the paper's final repartitioning, the band's
//     tets are cut into P shares again (recursive inertial bisection of the
//     band alone, whose cuts cross the first ones: a band along a plane is
//     cut across it), every rank optimizes its share, and rank 0 then the
//     band of the shares (their cuts' vertices and the tets still under
//     kBandAngle, grown by one ring), the band's outside still frozen.
//     On 2 ranks: pinion r2's band 1.99 -> 1.36 s, femur r2 0.54 -> 0.46,
//     the smallest angle up on 12 of 37 r1 and r2 inputs and down on 2
//     (docs/decisions.md, "The band on the ranks");
// On one rank it is optimize_mesh on the whole mesh. The mesh stays valid
// throughout (every part's changes are optimize_mesh's, which keep it
// valid), its boundary triangles and their vertices never change, and the
// result depends on the mesh, the options and P only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"
#include "parallel/comm.hpp"

namespace partet {

// Tets with a dihedral angle under this many degrees after the parts join
// the band, which is optimized in at most kBandPasses passes
// (docs/decisions.md, "The optimizer on the ranks' parts"; 2 ranks, r1):
// with cut vertices only (0 degrees) handle keeps a tet of 0.32 degrees
// and joint one of 0.45 (2.14 and 1.26 with 2 degrees; one rank 1.03 and
// 1.26); 10 degrees and three passes reoptimize most of the CAD parts' bad
// tets, for as much time as the parts took.
constexpr double kBandAngle = 2;
constexpr int kBandPasses = 2;

struct DistributedOptimizeStats {
  OptimizeStats totals;  // counts summed over the parts and the band; before/after of the whole mesh
  std::vector<int64_t> tets_per_rank;  // tets of each rank's part before optimizing
  double split_seconds = 0;            // quality measured, tets partitioned and parts scattered (rank 0)
  std::vector<double> part_seconds;    // wall time of each rank's part
  double join_seconds = 0;             // parts gathered and joined (rank 0)
  size_t band_tets = 0;                // tets of the band (step 4)
  size_t crossing_tets = 0;            // rank 0's last pass over the band's shares
  double band_seconds = 0;             // the band's wall time on rank 0
};

// Collective. `mesh` is whole on rank 0 (empty elsewhere, and left so),
// without global ids. Unused vertices are dropped at the end.
DistributedOptimizeStats optimize_distributed(const Comm& comm, TetMesh& mesh, const OptimizeOptions& options);

}  // namespace partet
