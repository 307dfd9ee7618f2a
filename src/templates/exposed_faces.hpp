// The exposed triangles of an interior leaf's template: a triangle of the
// leaf's face is exposed when the leaf just across it, at the triangle's
// quadrant, is not interior (or there is none), which face_rule.hpp shows
// is exact. Shared by the serial initial front and the per-rank front of
// the boundary partition, so both decide exposure the same way.
#pragma once

#include <cstddef>
#include <cstdint>

#include "octree/octree.hpp"
#include "templates/face_rule.hpp"
#include "templates/leaf_neighbourhood.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

// Calls visit(across, tet) for each exposed triangle of interior leaf i of
// `tree`, in template order: `across` is the leaf across it (kAbsentLeaf
// past the root cube) and `tet` the core tet (a, c, b, centre) whose outer
// face is the triangle (a, b, c), oriented away from the leaf.
template <class Visit>
void for_each_exposed_face(const LinearOctree& tree, const TemplateCore& core, size_t i, Visit&& visit) {
  const uint32_t* tets = core.mesh.tets.data();
  uint64_t tet = core.leaf_first_tet[i];
  for (int f = 0; f < kLeafFaces; ++f) {
    const FaceTriangulation& t = face_triangulation(f, core.face_case[kLeafFaces * i + f]);
    // Across quadrant 0: a neighbour of this leaf's size or larger covers
    // the whole face.
    uint32_t across[4];
    across[0] = leaf_across(tree, i, f, 0);
    const bool one_neighbour = across[0] == kAbsentLeaf || tree.level[across[0]] <= tree.level[i];
    if (one_neighbour && across[0] != kAbsentLeaf && tree.cls[across[0]] == LeafClass::kInterior) {
      tet += face_tets(tree, i, f, core.face_case[kLeafFaces * i + f]);
      continue;
    }
    for (int q = 1; q < 4; ++q) across[q] = one_neighbour ? across[0] : leaf_across(tree, i, f, q);
    for (int k = 0; k < t.count; ++k, ++tet) {
      const uint32_t other = across[t.tri[k].quadrant];
      if (other != kAbsentLeaf && tree.cls[other] == LeafClass::kInterior) continue;
      visit(other, tets + 4 * tet);
    }
  }
}

}  // namespace partet
