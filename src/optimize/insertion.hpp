// Interior vertex insertion around a bad tet (after Klingner and Shewchuk):
// a new vertex is joined to the outer faces of a cavity, in turn
//  1. an edge split: the tets around the edge opposite the tet's largest
//     dihedral angle (when that edge is interior and its ring closes), the
//     vertex at the edge's midpoint, else (the rounded midpoint of a flat
//     ring may see one of its faces from behind) at the deepest point of
//     the ring's kernel (core/kernel_point.hpp). A flat "ear" tet on two
//     surface triangles that meet at a wide angle then becomes two tets,
//     one per surface triangle. This step makes most of the insertions
//     (femur: 1,005 of 1,095) and took the share of tets under 10 degrees
//     below the best peer's on 30 of 32 corpus inputs instead of 24. It
//     comes first: tried first, step 2 lost 99 % of its smoothing trials
//     and made 2.5 % of the insertions for a third of their time (handle,
//     couplingdown, femur, rotor, spool, pinion); with the split first the
//     smallest angle rose on six corpus inputs (sphere966 18.3 -> 20.0
//     degrees, knot1 22.8 -> 23.5) and fell on none by more than 0.05, and
//     on their r1 refinements moved both ways (spool 0.11 -> 0.33, pipe
//     1.5 -> 2.0; rotor 0.97 -> 0.21, cactus 18.7 -> 13.3), at or above the
//     best peer's on 26 of 32 either way;
//  2. the tet with its face neighbours, the vertex at the tet's centroid,
//     else at the deepest point of that cavity's kernel;
//  3. for the mesh's worst tet (kWorstFirst), and for a sliver whose
//     widest angle sits on a boundary edge (the flat ear over two nearly
//     coplanar surface triangles has two angles of 180 degrees, one at the
//     surface edge), every other edge of the tet whose ring closes, split
//     as in step 1, in local vertex order (fandisk's smallest angle 16.9 ->
//     23.3 degrees, eight 6.0 -> 8.1, femur 0.60 -> 0.85 for the worst
//     tet; refined surfaces, whose split triangles are coplanar up to
//     rounding, lost their flat ears with the sliver rule and the kernel
//     point: femur r1 5.8e-14 -> 0.62 degrees, eight r1 0 -> 4.7);
//  4. the tets around the tet's four vertices, the vertex at the deepest
//     point of their kernel: what a flat tet on four surface vertices (over
//     two nearly coplanar surface triangles) needs, whose centroid lies on
//     the surface and whose neighbours leave little room (tried only when
//     the four vertices are on the boundary: an interior one would lie
//     inside this cavity and vanish; the check cut handle's insertion
//     time by a third, and made from TetTopology::on_boundary, without
//     the four star walks, another 6 % of handle r1's run);
//  5. for the mesh's worst tet, each of its corners on the boundary: the
//     corner's star, the vertex a quarter, 1/16, 1/64 or 1/256 of the way
//     from the corner to the deepest point of the star's kernel. A cap (an
//     input triangle with an angle near 180 degrees: its obtuse corner a
//     height h above its long edge) gives every tet on it an angle of about
//     h over half that edge when the tet's apex is far from the corner; a
//     vertex a few h from it leaves the cap's tet moderate angles and the
//     tets on the corner's other surface triangles about its distance over
//     their size (u r1, two caps of 179.85 degrees: 0.0675 -> 0.40
//     degrees, where TetGen -q and Gmsh HXT leave 0.0675 and Netgen 0.0684;
//     over the 64 r0 and r1 inputs the smallest angle rose on 14, lever r1
//     0.020 -> 0.268, joint r0 1.16 -> 1.80, pinion r1 1.36 -> 1.80, and
//     fell on 2 where the passes diverge, fandisk r1 25.67 -> 25.59). It
//     comes after step 6, whose grown cavities lift a flat sheet at once
//     (tried before it, it spent the rounds on the sheet's tets one by
//     one). Trading a tet under 1 degree, it brings slivers (u r1: 0.69 ->
//     4.0 % of the tets under 10 degrees; the peers 26-64 %);
//  6. with the frozen flags (for the mesh's worst tet), a cavity grown
//     from the tet and its face neighbours toward a point with room: the
//     deepest point of its kernel, the cavity taking in the tets behind
//     the faces that hold that point down, then, for a tet on the
//     boundary, a point fixed at a regular tet's height above each of its
//     boundary faces (for a tet under 1 degree with no boundary face: on
//     either side of its largest face), the cavity taking in the tets
//     behind the faces that point sees from behind or at a worse quality
//     than the cavity's worst, for up to 48 rounds and 384 tets (a sheet
//     of flat tets on a planar part of a thrice-refined surface needs
//     that many); free vertices the cavity swallows vanish (left unused, as
//     collapse.hpp leaves them). The fixed cavities of steps 1-4 stay thin
//     on a flat patch of surface with flat tets stacked on it (helmet r1:
//     0.028 -> 3.8 degrees, part r1 0.006 -> 1.19, elephant r1 11.7 ->
//     13.9, fandisk r1 19.0 -> 22.8; cross 26.9 -> 36.9, ellipsoid 20.5 ->
//     28.9, elephant 11.9 -> 20.1, handle 0.99 -> 2.83);
//  7. only for a tet with no neighbour: the tet alone, the vertex at its
//     centroid (as a fallback after 1-4 it succeeded on no corpus input
//     but lever, and its trials cost 5 % of the optimizer's time).
// A cavity of steps 1, 2 and 4 is not tried at all when no point could
// beat its worst tet (cone_bound.hpp: at an edge between two outer faces
// the cones split the cavity's angle); the bound skipped 45 % of handle
// r1's cavities, never one that would have succeeded on the quick sets
// (same meshes). A kernel point is tried only when its cone already beats
// the cavity. The new vertex is then smoothed in its would-be star before
// any tet changes (smooth_new_vertex, smoothing.hpp), and the insertion is
// made only if the worst new tet beats the worst tet of the cavity and
// either the total shortfall (sum of bar - quality over the tets below bar =
// min(target, quality of 20 degrees)) does not grow, so that one bad tet is
// not traded for many mediocre ones, or the worst tet of the cavity has an
// angle under 10 degrees and no new tet does (a sliver traded for a few
// mediocre tets is a gain). Otherwise the trial's vertex is dropped and
// nothing has changed. Every new tet is positive by exact orient3d (the
// cavity is star-shaped from the point).
// The cavity's outer faces, boundary faces among them, stay as they are,
// and a cavity with a vertex on none of them (which would vanish) is not
// used, but in step 6 when the vertex is free.
//
// New vertices get global id kOptimizerVertexId | (vertex index) when the
// mesh has global ids: bit 63 and bit 61 set, disjoint from lattice keys
// (bit 63 clear), surface ids (index below 2^32) and front Steiner ids
// (bit 62 set).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "optimize/failed_splits.hpp"
#include "optimize/smoothing.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

inline constexpr uint64_t kOptimizerVertexId = (uint64_t{1} << 63) | (uint64_t{1} << 61);

// The shortfall bar for a quality target: only tets below it are offered a
// vertex (an insertion must lower the shortfall, which they carry).
double insertion_bar(double target);

// Tries the cavities of tet t in turn; true when a vertex was inserted.
// When an insertion pays: kShortfall as above; kWorstFirst (for the mesh's
// worst tet) when the worst tet improves and min_angle_no_worse holds, or
// when that tet had an angle under 1 degree: the worst tet's rise then
// pays for more slivers among the new tets (a flat tet between surface
// vertices on a thin wall, whose ring gives tets of 0.4 degrees where it
// had one of 0: joint 0.32 -> 1.16 degrees, t13 0 -> 1.09, u 0.07 -> 1.05,
// part r1 0 -> 1.42, rotor r1 0.17 -> 0.97); under 5 degrees, one more
// sliver may come with a rising smallest angle, three when that angle at
// least doubles (with step 6: eight r1 2.5 -> 11.1 degrees, its slivers
// 14 -> 0; part 2.0 -> 3.4, femur 1.2 -> 2.9, couplingdown r1 1.3 -> 3.0;
// joint's share of slivers, 57 % on a thin plate, stays under the best
// peer's, which more slivers per trade broke).
enum class InsertionRule { kShortfall, kWorstFirst };

// The smallest dihedral angle of some tets (radians) and how many have one
// under 10 degrees. The quality measure also counts angles near 180
// degrees, so a change it calls better can still lower the smallest angle.
struct AngleSummary {
  double smallest = std::numeric_limits<double>::infinity();
  int slivers = 0;
  // With `extra_slivers` more slivers allowed.
  bool no_worse_than(const AngleSummary& old, int extra_slivers = 0) const {
    return smallest >= old.smallest && slivers <= old.slivers + extra_slivers;
  }
};
// Over tets given as vertex quadruples of `topo`'s points.
AngleSummary summarize_angles(const TetTopology& topo, std::span<const uint32_t> tets);
// New tets against old ones: summarize_angles no worse.
bool min_angle_no_worse(const TetTopology& topo, std::span<const uint32_t> old_tets,
                        std::span<const uint32_t> new_tets);

// Step 6's input and tally: the frozen flags (one per vertex; those beyond
// them are free) and the free vertices its cavities took in.
struct CavityGrowth {
  const std::vector<uint8_t>& frozen;
  size_t vertices_removed = 0;
};

// `near_corners` enables step 5, `growth` step 6. With `failed_splits`
// (kept by the caller for one rule and target), the edge splits of steps
// 1 and 3 it knows are skipped and those refused are added.
bool insert_vertex(TetTopology& topo, uint32_t t, double target, SmoothingScratch& scratch,
                   InsertionRule rule = InsertionRule::kShortfall, CavityGrowth* growth = nullptr,
                   bool near_corners = false, FailedSplits* failed_splits = nullptr);

}  // namespace partet
