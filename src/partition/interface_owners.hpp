// The interfaces the distributed face removals leave between the ranks, and
// new owners for the leaves that spread them over the ranks (paper §4.1
// steps 5-9). After a round of removals on the ranks, the faces still on
// the front whose removal neighbourhood (removal_neighbourhood) reaches
// leaves of two or more ranks could be removed by none of them: they lie
// along the cuts between the ranks' regions (the face interfaces), and
// where cuts meet (edge and vertex interfaces). Cutting the space again by
// recursive inertial bisection of those faces' centroids gives each rank
// an equal share of them, and since they lie near the old cuts the new
// cuts cross the old ones: what the next round leaves is what lies near
// where old and new cuts meet, a set of lower dimension (the paper's face,
// then edge, then vertex interfaces).
#pragma once

#include <cstdint>
#include <vector>

#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "octree/octree.hpp"
#include "parallel/comm.hpp"

namespace partet {

struct InterfaceFaces {
  std::vector<uint32_t> faces;  // alive faces, ascending
  std::vector<int32_t> lowest;  // per face: the lowest owner over its neighbourhood
};

// The alive faces of `front` whose neighbourhood leaves (as the removals
// gather them with `options`) have two or more owners in `tree.owner`.
InterfaceFaces interface_faces(const Front& front, const LinearOctree& tree, const RootCube& root,
                               const RemovalOptions& options);

// Collective; `front`, `tree`, `faces` and `contributor` the same on every
// rank (as sets: face slots may be numbered differently). Sets tree.owner
// on every rank, identically: every leaf goes to the rank on whose side of
// the separators its centre lies, the separators cutting the faces'
// centroids into comm.size() equal shares by inertial bisection. Face i is
// passed to the bisection by rank contributor[i] only (for interfaces: its
// lowest owner).
void reown_leaves_by_faces(const Comm& comm, const Front& front, const std::vector<uint32_t>& faces,
                           const std::vector<int32_t>& contributor, const RootCube& root, LinearOctree& tree);

}  // namespace partet
