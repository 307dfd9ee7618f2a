// What the validator says about one kind of problem: how many offenders and
// a description of the first few, with tet ids, vertex ids and exact
// coordinates, turned into a single report line. Also the texts naming tets,
// tet faces and mesh vertices that those descriptions use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/tet_mesh.hpp"

namespace partet {

class ProblemKind {
 public:
  // `what` follows the count: "tets are inverted (orient3d < 0)".
  explicit ProblemKind(std::string what) : what_(std::move(what)) {}

  // Counts one offender; true when it is among the first few, which the
  // caller then describes with describe().
  bool note() { return ++count_ <= kDescribed; }
  void describe(std::string text) { cases_.push_back(std::move(text)); }
  size_t count() const { return count_; }

  // "<count> <what>: <case>; <case> (and N more)", appended when count > 0.
  void report(std::vector<std::string>& lines) const;

  static constexpr size_t kDescribed = 5;

 private:
  std::string what_;
  size_t count_ = 0;
  std::vector<std::string> cases_;
};

// "vertex 7 (x, y, z)"
std::string mesh_vertex_text(const TetMesh& mesh, uint32_t v);
// "tet 5 [0 1 3 7] (x, y, z) (x, y, z) (x, y, z) (x, y, z)"; a vertex index
// out of range shows as "out of range" instead of its coordinates.
std::string tet_text(const TetMesh& mesh, size_t t);
// "[0 3 1] (x, y, z) (x, y, z) (x, y, z)" for three mesh vertices.
std::string triangle_text(const TetMesh& mesh, const uint32_t* v);

}  // namespace partet
