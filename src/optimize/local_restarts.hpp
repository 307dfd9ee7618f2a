// Local restarts: the optimizer run again on a band of tets around the
// mesh's worst tet, kept only when that makes the mesh better.
//
// When the optimizer's worst-tet rounds stop, the worst tet is one no
// single change lifts (helmet r2: three surface vertices along the rim,
// nearly collinear, and an interior vertex almost in the rim's plane; every
// flip, insertion and smoothing of it alone makes something worse). What
// the passes reach is not monotone in their number or their order (five
// passes on the whole of helmet r2 give 5.2 degrees where three give
// 1.41), and the same holds for a region: the tets within `layers` rings of
// the worst tet's vertices (band_around), cut out as a part whose outer
// faces stay fixed (mesh_parts.hpp), optimized with options.passes +
// kRestartExtraPasses passes, lift it (helmet r2: 1.41 -> 4.0 degrees over
// 989 tets in 20 ms). The band's optimizer inserts no vertex: with
// insertion helmet r2's band grew from 989 to 1,711 tets whose mean radius
// ratio (0.42) lay under the mesh's (0.74), so the mesh's mean fell and no
// band was kept. So, while the worst tet has an angle under
// kRestartAngle degrees and for at most kMaxRestarts rounds: the band
// around it, for each of kRestartLayers in turn, is optimized again, and
// the first result that makes the whole mesh better replaces the band:
// the band's smallest dihedral angle rises (the rest of the mesh is
// unchanged, so the mesh's cannot drop), and the mesh's share of tets
// under 10 degrees does not grow nor its mean radius ratio drop (computed
// from the sums over the band before and after). A round where no layer
// count helps ends the restarts. On a mesh of at most kSmallRestartTets
// tets the restarts go on while the worst tet is under the quality target
// instead (hedra r2, 686 tets: 27.4 -> 36.5 degrees in 6 ms, where
// Netgen reaches 35.1): a band there is much of the mesh and costs
// milliseconds, where on fandisk r1 (517 k tets) sixteen bands cost 0.25 s
// for the same smallest angle.
//
// Only the band changes; its outer faces, the boundary among them, keep
// their vertices. Deterministic: the worst tet is the lowest tet_quality,
// ties to the lowest index. `mesh.global_ids` must be empty (join_parts).
#pragma once

#include <cstddef>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"

namespace partet {

inline constexpr double kRestartAngle = 10;
inline constexpr size_t kSmallRestartTets = 4096;
inline constexpr int kMaxRestarts = 16;
inline constexpr int kRestartExtraPasses = 2;
inline constexpr int kRestartLayers[] = {2, 1, 3};

struct RestartStats {
  size_t tried = 0;  // bands optimized again
  size_t kept = 0;   // of them, those that replaced their band
};

// `quality` is the mesh's measure on entry (measure_quality) and is kept up
// to date; unused vertices left by collapses in a band are dropped.
RestartStats restart_around_worst(TetMesh& mesh, QualityStats& quality, const OptimizeOptions& options);

}  // namespace partet
