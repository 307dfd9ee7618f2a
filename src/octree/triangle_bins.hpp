// The surface triangles binned into the leaves they meet: for each leaf, the
// triangles whose closed triangle meets its closed box (exact test), as
// compressed rows. Built per triangle from a range query over the
// triangle's bounding box, in tree order for locality. The spatial index of
// classification (boundary leaves are the non-empty rows) and of anything
// that needs the triangles near a leaf.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct LeafTriangles {
  std::vector<uint32_t> first;      // per leaf, plus one: leaf i has tris[first[i] .. first[i + 1])
  std::vector<uint32_t> tris;       // triangle ids, ascending within a leaf
  std::vector<uint8_t> coarsest;    // per triangle: the lowest level among the leaves it meets

  size_t count(size_t leaf) const { return first[leaf + 1] - first[leaf]; }
};

// Triangle ids sorted by the Morton key of the grid cell at the low corner
// of their bounding box (ties by id): neighbouring triangles then visit
// neighbouring leaves.
std::vector<uint32_t> triangles_in_tree_order(const SurfaceMesh& surface, const RootCube& root);

// Precondition: `tree` is complete and covers the surface.
LeafTriangles bin_triangles(const LinearOctree& tree, const SurfaceMesh& surface, const RootCube& root);

}  // namespace partet
