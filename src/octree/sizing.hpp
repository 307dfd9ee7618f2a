// Target sizes from the surface mesh: a target edge length per surface
// vertex (the mean length of its incident edges, then the user controls),
// turned into an octree level and located on the grid. These (grid point,
// level) pairs are the input of build_octree.
//
// Level rounding: level = round-to-nearest of log2(D / d) (D = root edge,
// d = target), clamped to [1, max_level]. Leaf edges are D / 2^level, so
// rounding in log space to the nearest level keeps the leaf edge within a
// factor sqrt(2) of the target either way (ties, exactly at a factor sqrt(2),
// go to the finer level); rounding down (coarser) or up (finer) would allow a
// factor 2 on one side.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "octree/octree.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct SizingOptions {
  double max_size = std::numeric_limits<double>::infinity();  // no target above it
  double size_factor = 1;                                     // scales every target
  int max_level = kMaxLevel;  // deepest level asked for, clamped to [1, kMaxLevel]
};

struct VertexSizing {
  std::vector<double> size;     // per vertex: target edge length, options applied
  std::vector<uint8_t> level;   // per vertex: octree level of that target
  std::vector<uint32_t> grid;   // 3 per vertex: grid cell containing the vertex
};

// Mean length of the edges incident to each vertex (0 for a vertex in no
// triangle). Each triangle contributes its two edges at the vertex; on a
// closed manifold surface every edge is in two triangles, so this is the
// mean over the distinct incident edges.
std::vector<double> mean_incident_edge_length(const SurfaceMesh& surface);

// Level of target size d in a root cube of edge D (see the file comment).
// max_level is clamped to [1, kMaxLevel] first.
int size_to_level(double d, double D, int max_level);

// Grid cell containing point p: floor((p - origin) / unit), clamped to the
// root cube [0, kGridSize - 1]^3.
void grid_cell(const RootCube& root, const double* p, uint32_t* g);

// Sizes, levels and grid cells of every surface vertex. Throws InputError
// when size_factor or max_size is not positive.
VertexSizing size_vertices(const SurfaceMesh& surface, const RootCube& root, const SizingOptions& options);

}  // namespace partet
