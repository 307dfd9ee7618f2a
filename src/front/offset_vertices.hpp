// Gap vertices offset from the surface: a point kOffsetHeight target sizes
// inside each surface vertex, along its normal, where the gap has room.
//
// The leaf centres of gap_vertices.hpp fill the gap where its leaves do;
// where the gap is thin (CAD walls, thin handles: a leaf's centre is too
// near the surface on one side or the other) they leave it empty, and the
// first layer of tets reaches from the surface to the far side or to the
// core. The first layer wants its apexes about 0.82 s above triangles of
// size s; the offset point of vertex v, at 0.8 s_v along the inward
// normal (the sum of its triangles' area normals), is such an apex for
// the triangles around v. It is kept when:
//  - it lies in a boundary or too-close leaf (not in the templated core)
//    and inside the surface (exact ray parity);
//  - every surface triangle is at least `gap` s_v from it (the
//    classification's too-close threshold, octree/classify.hpp, in the
//    vertex's own size: the leaf centres' rule, in the triangles' sizes,
//    dropped most offset points on CAD parts, whose long triangles have
//    large sizes);
//  - no template vertex or leaf centre lies within kOffsetBlock s_v of
//    it (where the lattice already has a point there, it stays the
//    layer), nor a kept offset point of a lower vertex within
//    kOffsetSpacing s_v (concave parts of the surface crowd them).
// Over the 64 r0 and r1 inputs the mean radius ratio of the meshes rose
// 0.6414 -> 0.650 and the mean share of tets under 10 degrees fell (see
// docs/decisions.md, "Offset gap vertices").
//
// Ids: kOffsetVertexId | v for surface vertex v (rank-independent, and
// disjoint from lattice keys, surface ids and the Steiner and optimizer
// ids). Distances in doubles (a placement heuristic); the points have
// exact coordinates from then on. Deterministic: vertex order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "front/gap_vertices.hpp"
#include "front/initial_front.hpp"
#include "octree/octree.hpp"
#include "octree/triangle_bins.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

inline constexpr uint64_t kOffsetVertexId = kSurfaceVertexId | (uint64_t{1} << 60);
inline constexpr double kOffsetHeight = 0.8;
inline constexpr double kOffsetBlock = 0.7;
inline constexpr double kOffsetSpacing = 0.5;

// Appends the offset points of `surface` (with target sizes `vertex_size`,
// and the tree classified from it with threshold `gap`) to `gap_vertices`,
// whose other points, with the template vertices of `front` (the first
// front.core_vertices, before any free vertex is added), block them.
// `bins`: bin_triangles(tree, surface, root) when the caller has it (else
// it is made here). The number appended.
size_t add_offset_vertices(const LinearOctree& tree, const RootCube& root, const SurfaceMesh& surface,
                           const std::vector<double>& vertex_size, double gap, const InitialFront& front,
                           GapVertices& gap_vertices, const LeafTriangles* bins = nullptr);

}  // namespace partet
