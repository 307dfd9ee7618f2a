// Face matching of a tet mesh: groups the 4 faces of every tet by their
// sorted vertex triple and checks each group. Face code 4*t + f names the
// face of tet t opposite its local vertex f; kOutwardFace[f]
// (core/tet_mesh.hpp) lists that face's local vertices so that, for a
// positive tet, its normal points away from the tet.
// Faces are bucketed by their smallest vertex (a counting sort into one
// flat array) and sorted within each bucket on the other two vertices
// packed in 64 bits: memory is one uint32 per face, time near-linear.
// Contract: `state` has one entry per tet; tets with kOutOfRange take no
// part; geometry is judged only between tets of known orientation sign.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "check/problem_log.hpp"
#include "core/tet_mesh.hpp"

namespace partet {

// The exact orientation of a tet, or why it has none.
enum class TetState : int8_t {
  kPositive,    // orient3d > 0
  kNegative,    // orient3d < 0
  kFlat,        // orient3d == 0
  kNonFinite,   // a vertex has a NaN or infinite coordinate
  kOutOfRange,  // a vertex index is out of range
};

// The mesh vertices of face `code`, outward oriented.
inline void outward_face(const TetMesh& mesh, uint32_t code, uint32_t out[3]) {
  const uint32_t* v = &mesh.tets[4 * (code / 4)];
  for (int i = 0; i < 3; ++i) out[i] = v[kOutwardFace[code % 4][i]];
}

struct FaceProblems {
  ProblemKind crowded{"faces are shared by more than two tets"};
  ProblemKind same_side{"pairs of tets lie on the same side of their shared face"};
  ProblemKind duplicate{"pairs of tets are duplicates (same four vertices)"};
};

struct FaceMatch {
  std::vector<uint32_t> boundary;  // codes of the faces used by exactly one tet
  size_t interior = 0;             // faces used by exactly two tets
};

FaceMatch match_tet_faces(const TetMesh& mesh, const std::vector<TetState>& state,
                          FaceProblems& problems);

}  // namespace partet
