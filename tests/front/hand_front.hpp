// Fronts made by hand over a one-leaf octree, for the front's unit tests.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "front/front.hpp"
#include "front/initial_front.hpp"

namespace partet::test {

struct HandFront {
  LinearOctree tree;
  RootCube root;
  InitialFront initial;
};

// `outward`: closed surfaces' faces oriented outward from the region to
// mesh (as a diagnosed surface); the front faces are their reverses.
inline HandFront hand_front(const std::vector<double>& xyz, const std::vector<uint32_t>& outward) {
  HandFront h;
  h.tree.key = {0};
  h.tree.level = {0};
  h.tree.cls = {LeafClass::kBoundary};
  h.tree.owner = {0};
  double bbox[6] = {xyz[0], xyz[1], xyz[2], xyz[0], xyz[1], xyz[2]};
  for (size_t i = 0; i < xyz.size(); ++i) {
    bbox[i % 3] = std::min(bbox[i % 3], xyz[i]);
    bbox[3 + i % 3] = std::max(bbox[3 + i % 3], xyz[i]);
  }
  h.root = make_root_cube(bbox);
  const size_t n = xyz.size() / 3;
  h.initial.xyz = xyz;
  for (size_t v = 0; v < n; ++v) h.initial.global_ids.push_back(kSurfaceVertexId | v);
  h.initial.vertex_leaf.assign(n, 0);
  for (size_t t = 0; t + 2 < outward.size(); t += 3)
    h.initial.faces.insert(h.initial.faces.end(), {outward[t], outward[t + 2], outward[t + 1]});
  h.initial.surface_faces = h.initial.num_faces();
  std::vector<char> used(n, 0);
  for (uint32_t v : h.initial.faces) used[v] = 1;
  for (uint32_t v = 0; v < n; ++v)
    if (used[v]) h.initial.front_vertices.push_back(v);
  h.initial.leaf_first_front_vertex = {0, static_cast<uint32_t>(h.initial.front_vertices.size())};
  return h;
}

}  // namespace partet::test
