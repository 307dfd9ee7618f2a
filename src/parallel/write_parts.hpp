// Writing a distributed mesh: with .pvtu every rank writes its own piece
// (`stem_<rank>.vtu`) and rank 0 the index; with a one-file format the parts
// are gathered on rank 0, joined (shared vertices merged) and written there,
// unless rank 0 holds the whole mesh (the other parts empty), which it then
// writes as it is.
// Collective; failures are agreed on by all ranks.
#pragma once

#include <string>

#include "core/tet_mesh.hpp"
#include "io/mesh_file.hpp"
#include "parallel/comm.hpp"

namespace partet {

void write_distributed_mesh(const TetMesh& part, const std::string& path, const WriteOptions& options,
                            const Comm& comm);

// Flat byte image of a part (for gathering) and back.
std::string serialize_part(const TetMesh& part);
TetMesh deserialize_part(const std::string& bytes);

}  // namespace partet
