// Quality optimization of a finished, valid tet mesh, with its boundary
// untouched: passes of topological improvement (2-3 flips, and edge removal
// with its 3-2 and 4-4 special cases, see flips.hpp) on the tets below the
// quality target (block of slots by block, worst first in each: locality),
// then (in every pass but the last of two or more) interior vertex insertion
// where it pays (insertion.hpp), else vertex collapse where that pays
// (collapse.hpp), then optimization-based smoothing (smoothing.hpp) of the
// free vertices of the tets still below the target or 30 degrees; after the
// passes, a sweep of multi-face removals, rounds on the worst tet, a sweep
// of needle splits (needle_split.hpp) and two sweeps of radius-ratio
// relaxation (relax_vertex), which adds no sliver and lowers a star's worst
// tet only down to 20 degrees or the mesh's smallest angle, whichever is
// larger (optimize.cpp, kRelaxFloorAngle).
//
// Frozen vertices never move: those of boundary faces (faces of exactly one
// tet), those of `mesh.tris`, and those the caller flags (e.g. the vertices
// a rank boundary shares). Boundary faces keep their three vertices and
// their side. Inserted vertices are appended to xyz (and to global_ids
// when the mesh has them); collapsed ones (collapse.hpp) and those a grown
// cavity takes in (insertion.hpp, step 6) stay in xyz with no tet, so
// existing indices stay; callers drop the unused ones
// (drop_unused_vertices) when they need a compact mesh. Every change keeps every tet
// positive by exact orient3d and strictly raises the worst quality of the
// tets it replaces or moves (a relaxation raises the radius ratios and
// keeps the mesh's smallest angle); a pass has a bounded amount of work and there
// are at most `passes` passes. Deterministic: no hashing order, no threads,
// no randomness.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"

namespace partet {

struct OptimizeOptions {
  int passes = 3;  // 0: measure only
  // Tets whose dihedral angles all lie in [target, 180 - target] degrees
  // are left as they are; the optimizer works on the others.
  double quality_target_deg = 40;
  // Passes after the first work on the tets under lower angles
  // (optimize.cpp, kLaterPassAngles); false: every pass at the target.
  bool lower_later_targets = true;
  bool insert_vertices = true;  // appends vertices to xyz (and global_ids)
  bool collapse_vertices = true;  // leaves collapsed vertices unused in xyz
  // In the worst-tet rounds, when nothing else moves the worst tet, smooth
  // the free vertices around its own first.
  bool smooth_around_worst = true;
  // In the worst-tet rounds, when that fails too, move the free vertices of
  // the near-worst tets around it together (joint_smoothing.hpp).
  bool smooth_jointly = true;
  // In the worst-tet rounds, try a vertex near each boundary corner of the
  // worst tet, in the corner's star (insertion.hpp, step 5: caps).
  bool corner_vertices = true;
  // In the worst-tet rounds, when the insertion's fixed cavities fail,
  // grow one toward room (insertion.hpp, step 6).
  bool grow_cavities = true;
  // In the worst-tet rounds, when a tet under 1 degree resists all that,
  // lift the free vertices of the nearly flat tets around it together off
  // their plane (sheet_lift.hpp).
  bool lift_sheets = true;
  bool multi_face_sweep = true;  // multi-face removals after the passes
  int relaxation_sweeps = 2;     // radius-ratio relaxation sweeps at the end
  // Tets under this radius ratio have their longest interior edge split
  // where that pays (needle_split.hpp), before the relaxation; 0 for none.
  // 0.4 raised the mean radius ratio a little more (r1 0.637 -> 0.641) for
  // 2 % more CPU, mostly trials on smooth inputs that are refused.
  double needle_radius_ratio = 0.3;
  // Rounds on the mesh's worst tet after the passes (flip, insert, smooth
  // while it is below the target and something changes); 0 for none.
  int worst_tet_rounds = 64;
  // In those rounds, a worst tet that cannot be changed and has a vertex
  // the caller froze is set aside, and the rounds go on with the next worst
  // (else they end there). The distributed optimizer's parts use it, with
  // their cut vertices frozen: a part's worst tet often lies on a cut it
  // cannot move, and ending there would leave its other bad tets as the
  // passes left them.
  bool set_aside_stuck_on_frozen = false;
  // Then (unless worst_tet_rounds is 0), while the worst tet has an angle
  // under 1 degree, up to this many rounds more: each may lift one tet of
  // a sheet of flat tets (joint r3 when targets were taken by shape: 89
  // tets under 1e-6 degrees, 64 rounds left it at 9e-7 degrees; lever:
  // 0.29 -> 0.55 degrees).
  int flat_tet_rounds = 1024;
};

struct OptimizeStats {
  QualityStats before, after;
  size_t flips_23 = 0;
  size_t flips_32 = 0;
  size_t flips_44 = 0;
  size_t edge_removals = 0;  // edges with rings of 5 to 7 tets
  size_t multi_face_removals = 0;  // polygons of 2 to 5 sandwiched faces
  size_t vertices_inserted = 0;
  size_t vertices_collapsed = 0;
  size_t vertices_removed = 0;  // free vertices a grown cavity took in (insertion.hpp, step 6)
  size_t vertices_moved = 0;
  size_t vertices_relaxed = 0;  // moves of the radius-ratio relaxation
  size_t sheets_lifted = 0;     // lift_sheet moves in the worst-tet rounds
  size_t needles_split = 0;     // edges split by split_needles
  int passes = 0;  // passes run
  double seconds = 0;
  // Wall seconds of the parts, summed over the passes; `measure` is the
  // quality before and after.
  double topology_seconds = 0, insertion_seconds = 0, smoothing_seconds = 0, relaxation_seconds = 0,
         measure_seconds = 0;
};

// `frozen`, when given, has one flag per vertex (non-zero: frozen).
OptimizeStats optimize_mesh(TetMesh& mesh, const OptimizeOptions& options,
                            const std::vector<uint8_t>* frozen = nullptr);

}  // namespace partet
