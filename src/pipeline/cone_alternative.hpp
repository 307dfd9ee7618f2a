// The cone alternative for small surfaces. A closed surface that one
// interior point q sees whole (every input triangle faces q: it is
// star-shaped from q) is filled exactly by the tets joining each triangle to
// q. On a coarse convex body that cone, optimized, beats what the octree
// and the front make there (icosahedron refined once, 80 triangles: 80 tets
// and 58 degrees, against 1,244 tets and 34 degrees), because the body is
// thinner than the octants the surface's edge lengths ask for. On a finer
// surface the cone's tets become needles, so it is tried only on surfaces of
// at most kConeTriangles triangles, where it costs a few milliseconds, and
// only when the mesh is optimized (it serves the optimizer's measures;
// --no-optimize keeps the front's mesh as made).
//
// q is the triangles' deepest kernel point (core/kernel_point.hpp); every
// cone tet is checked positive with exact orient3d. With all tets positive
// and the surface closed and embedded (the diagnosis checked it), every
// point of the body is covered once: the cone is a valid mesh whose
// boundary is exactly the input triangles.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "check/quality.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/optimize.hpp"

namespace partet {

constexpr size_t kConeTriangles = 1000;

// The cone of mesh.tris (oriented outward) to their deepest kernel point,
// in `cone` (the mesh's vertices that the triangles use, then q, as the last
// vertex); false when no point sees every triangle.
bool cone_mesh(const TetMesh& mesh, TetMesh& cone);

// When mesh.tris has at most kConeTriangles triangles and a cone: the cone,
// optimized with `options`, replaces `mesh` (whose quality is `quality`, as
// optimize_mesh measured it; updated when replaced) when it is at least as
// good in smallest dihedral angle, share of tets under 10 degrees and mean
// radius ratio, and better in one (keep_better_alternative). Returns what
// was tried, for the run report.
nlohmann::ordered_json try_cone_alternative(TetMesh& mesh, QualityStats& quality,
                                            const OptimizeOptions& options);

}  // namespace partet
