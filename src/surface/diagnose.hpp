// Surface diagnosis before any meshing: refuses what cannot bound a volume
// (InputError, exit 2, naming the file, the entities and the problem, with
// counts and the first few cases) and prepares the rest: drops unused
// vertices and orients every shell (outer shells outward, cavity shells into
// their cavity), with a note for each change.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace partet {

struct SurfaceSummary {
  size_t vertices = 0;
  size_t triangles = 0;
  size_t edges = 0;
  size_t shells = 0;
  size_t cavities = 0;          // shells enclosed by an odd number of others
  size_t reoriented = 0;        // triangles whose orientation was reversed
  size_t unused_vertices = 0;   // dropped
  double volume = 0;            // enclosed volume
  double bbox[6] = {0, 0, 0, 0, 0, 0};
  double seconds_self_intersections = 0;
  std::vector<std::string> notes;
};

// In order: finite coordinates; unused vertices (dropped); then, reported
// together, degenerate triangles (repeated vertex or exactly collinear),
// duplicate triangles, open edges, non-manifold edges and vertices, and
// self-intersections (exact; checked when the triangles are sound, even on
// an open surface); then shell orientation (non-orientable refused) and
// nesting.
// `progress`, when given, is told the fraction done after each check.
SurfaceSummary diagnose_surface(SurfaceMesh& surface, const std::string& file,
                                const std::function<void(double)>& progress = {});

}  // namespace partet
