// Writing a distributed mesh: with .pvtu every rank writes its own piece
// (`stem_<rank>.vtu`) and rank 0 the index; with a one-file format the parts
// are gathered on rank 0, joined (shared vertices merged) and written there,
// unless rank 0 holds the whole mesh (the other parts empty), which it then
// writes as it is. A mesh whole on rank 0 goes to a .pvtu of one piece per
// rank written by rank 0 alone (write_whole_as_pieces).
// Collective; failures are agreed on by all ranks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/tet_mesh.hpp"
#include "io/mesh_file.hpp"
#include "parallel/comm.hpp"

namespace partet {

void write_distributed_mesh(const TetMesh& part, const std::string& path, const WriteOptions& options,
                            const Comm& comm);

// Rank 0's whole mesh (no global ids; the other ranks pass an empty one)
// written to the .pvtu `path` as comm.size() pieces, all by rank 0: piece
// r holds the r-th of P runs of consecutive tets of equal size (within
// one) and the vertices they use, in the whole mesh's order, each with its
// whole-mesh index as global id (a .vtu piece holds no boundary
// triangles). Cutting the mesh by inertial bisection and sending the
// pieces out to be written took longer than writing them all here
// (docs/decisions.md, "A whole mesh's pieces written by rank 0"). Returns
// the pieces' tet counts on rank 0 (empty elsewhere).
std::vector<int64_t> write_whole_as_pieces(const TetMesh& whole, const std::string& path, const WriteOptions& options,
                                           const Comm& comm);

// Flat byte image of a part (for gathering) and back.
std::string serialize_part(const TetMesh& part);
TetMesh deserialize_part(const std::string& bytes);

}  // namespace partet
