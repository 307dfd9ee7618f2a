// One rank's share of the unmeshed region around the templated core (paper
// §4.1 step 3): the leaves it owns that are left to the advancing front
// (kBoundary and kTooClose), the front faces belonging to them
// (boundary_front.hpp gives the rule) and the vertices those faces use,
// with their global ids and coordinates. The work of a leaf, what the
// boundary partition balances, is the number of its front faces.
//
// Invariants (assemble_front_part establishes them): leaves sorted by key,
// owner = this rank; faces grouped by leaf in leaf order, and within a leaf
// ordered by their vertices' global ids (lexicographic, as oriented);
// vertices exactly those the faces use, ascending by global id. So the part
// depends only on which leaves and faces a rank holds, not on where they
// came from. migrate_front_part moves leaves with everything attached.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "octree/octree.hpp"
#include "parallel/comm.hpp"
#include "parallel/front_migration.hpp"

namespace partet {

struct FrontPart {
  LinearOctree leaves;                    // sorted by key; owner = this rank
  std::vector<uint32_t> leaf_first_face;  // per leaf + 1: the faces of leaf i are [first[i], first[i + 1])
  std::vector<uint32_t> faces;            // 3 vertex indices per face, counterclockwise seen from the unmeshed side
  std::vector<uint64_t> global_ids;       // per vertex, ascending
  std::vector<double> xyz;                // 3 per vertex

  size_t num_faces() const { return faces.size() / 3; }
  size_t num_vertices() const { return global_ids.size(); }
  // The work estimate of leaf i: its number of front faces.
  uint32_t leaf_work(size_t i) const { return leaf_first_face[i + 1] - leaf_first_face[i]; }
};

// The part made of `leaves` (sorted by key, unique) and the faces of `batch`,
// each of which must belong to one of them (InternalError otherwise).
FrontPart assemble_front_part(LinearOctree leaves, const FaceBatch& batch, int rank);

// Collective: leaf i of `part` goes to rank destination[i] with its faces and
// their vertices; returns the part this rank ends with. `bytes`, when given,
// gets the bytes sent to and received from other ranks added.
FrontPart migrate_front_part(const Comm& comm, const FrontPart& part, const std::vector<int32_t>& destination,
                             MigrationBytes* bytes = nullptr);

}  // namespace partet
