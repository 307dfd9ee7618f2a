// Joint smoothing: several free vertices moved together to raise the worst
// tet_quality of the tets around them. One vertex at a time (smooth_vertex)
// stops where its star's worst tets balance; when the mesh's worst tets tie
// across neighbouring vertices (each vertex's best place depends on where
// the others are), no single move raises them, though a move of all of
// them can. The ascent is smooth_vertex's in 3m dimensions: the analytic
// gradients of the active (near-worst) tets with respect to every moving
// vertex, the direction of least norm in their convex hull (Gilbert's
// iterations), a step halved until the region's worst quality strictly
// improves and every region tet is positive by exact orient3d.
#pragma once

#include <cstdint>
#include <vector>

#include "optimize/tet_topology.hpp"

namespace partet {

// The vertices a joint move of tet `worst` takes: its corners that are not
// `frozen` (one flag per vertex; those beyond are free), then, breadth
// first, the free corners of the tets within `band` of its quality in
// the stars of those taken, at most `cap` in all.
void tied_vertices(const TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen, double band,
                   size_t cap, std::vector<uint32_t>& vertices);

// The tets of the stars of `vertices`, ascending, each once.
void joint_region(const TetTopology& topo, const std::vector<uint32_t>& vertices, std::vector<uint32_t>& region);

// Moves `vertices` (free: not on the boundary, not frozen; each once)
// together when that raises the worst quality of `region`
// (joint_region(vertices)); true if they moved.
bool smooth_jointly(TetTopology& topo, const std::vector<uint32_t>& vertices, const std::vector<uint32_t>& region);

}  // namespace partet
