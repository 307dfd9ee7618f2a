// The ghost layers of a distributed octree: the leaves of other ranks that a
// rank needs to look at its own leaves' neighbourhoods (the manifold-core
// pass and the face rule of templates).
//
// Layer 1: the leaves of other ranks touching (sharing a face, an edge or a
// corner with) a leaf of this rank; every lattice point of an own leaf lies
// in an own or layer-1 leaf. Layer 2: the leaves of other ranks touching a
// layer-1 leaf, so that the neighbourhood of a layer-1 leaf is complete too
// (templates/leaf_neighbourhood.hpp looks at the leaves touching the leaf it
// visits). Found with two exchanges: each rank sends the leaves touching
// another rank's range octants to that rank (layer 1); then each rank asks
// the ranks whose ranges touch its layer-1 leaves for their leaves touching
// them (layer 2).
//
// The local view is the complete octree of this rank's leaves, the two
// layers, and placeholder octants (key_ranges.hpp) everywhere else. Owners
// there say what a leaf is for: this rank (own leaves), another rank
// (layer 1, their owner), or kContextOwner (layer 2 and placeholders, which
// are only looked at; placeholders are kOutside).
#pragma once

#include <cstddef>
#include <cstdint>

#include "octree/distributed_build.hpp"

namespace partet {

constexpr int32_t kContextOwner = -1;

struct GhostCounts {
  size_t layer1 = 0, layer2 = 0;
};

// Collective: `tree` is complete over all ranks, 2:1 balanced and classified.
LinearOctree ghost_view(const Comm& comm, const DistributedOctree& tree, GhostCounts* counts = nullptr);

}  // namespace partet
