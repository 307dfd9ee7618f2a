// Self-intersection search for triangle surfaces: every pair of triangles
// that meet other than in the vertices and edges they share by id, found
// with a bounding-volume hierarchy and decided by exact tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace partet {

struct TrianglePair {
  uint32_t a, b;  // a < b
  bool operator==(const TrianglePair&) const = default;
};

// Pairs of triangles of `surface` that meet other than in shared vertices or
// edges (surface_triangles_conflict), sorted by (a, b). The search stops once
// `limit` pairs are found and returns the first `limit` of those in (a, b)
// order; which pairs those are depends only on the surface, so the result is
// deterministic (but with a limit it need not be the `limit` smallest pairs
// overall). limit == 0 returns nothing.
// Precondition: no degenerate triangles (exactly collinear vertices), no
// NaN or infinite coordinates, vertex indices in range.
std::vector<TrianglePair> find_self_intersections(const SurfaceMesh& surface, size_t limit);

}  // namespace partet
