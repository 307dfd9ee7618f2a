// A mesh held whole on rank 0 cut into one part per rank and sent out:
// the tets split by recursive inertial bisection of their centroids (equal
// tet counts), each part sent to its rank: the distributed optimizer's
// parts (distributed_optimize.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "core/tet_mesh.hpp"
#include "optimize/mesh_parts.hpp"
#include "parallel/comm.hpp"

namespace partet {

// Collective; `mesh` is rank 0's (the other ranks pass an empty one): on
// rank 0, the part of each tet (empty elsewhere).
std::vector<int32_t> partition_tets(const Comm& comm, const TetMesh& mesh);

// Collective: rank 0 sends parts[r] (its mesh, with boundary triangles and
// global ids, and its cut flags) to rank r; every rank returns its own,
// `whole` left empty. Rank 0's own mesh is moved out of parts[0], not
// copied (parts[0].mesh is left empty). The other ranks pass no parts.
MeshPart scatter_parts(const Comm& comm, std::vector<MeshPart>& parts);

// Collective, the way back: every rank's `own` mesh (changed by it) goes
// to rank 0, into parts[r].mesh (rank 0's moved, not copied).
void gather_parts(const Comm& comm, MeshPart& own, std::vector<MeshPart>& parts);

}  // namespace partet
