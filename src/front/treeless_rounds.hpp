// One attempt of the tree-less face removals (treeless_removal.hpp, steps
// 1-5 and the rounds' stop rules) with one TreelessStrategy, on the state
// it is given; remove_faces_treeless runs the attempts and the rescue
// between them.
#pragma once

#include "core/tet_mesh.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/treeless_removal.hpp"
#include "octree/octree.hpp"

namespace partet {

// The counts of the attempt (faces_left_by_attempt left empty).
TreelessCounts run_treeless_rounds(Front& front, LinearOctree& tree, const RootCube& root, TetMesh& out,
                                   const RemovalOptions& options, RemovalMemo& memo, TreelessStrategy strategy);

}  // namespace partet
