// Dropping the vertices no tet uses (left by removals that delete tets):
// the others keep their order; tets, boundary triangles and global ids are
// renumbered to match.
#pragma once

#include <cstddef>

#include "core/tet_mesh.hpp"

namespace partet {

// Returns the number of vertices dropped. Boundary triangles may only use
// vertices that some tet uses.
size_t drop_unused_vertices(TetMesh& mesh);

}  // namespace partet
