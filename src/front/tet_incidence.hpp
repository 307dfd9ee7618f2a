// Tets by vertex over a growing TetMesh, for the removals that delete tets:
// which live tet lies behind a front face. The tets present at
// construction are indexed in a compressed array (one pass, no per-vertex
// allocation); tets appended later are indexed on demand (index_new) in a
// per-vertex map. Deleted tets stay in the mesh, flagged dead, until
// drop_dead_tets removes them.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/tet_mesh.hpp"

namespace partet {

constexpr uint32_t kNoTet = UINT32_MAX;

class TetIncidence {
 public:
  explicit TetIncidence(const TetMesh& mesh);

  // Indexes the tets appended to the mesh since the last call.
  void index_new(const TetMesh& mesh);
  void kill(uint32_t t) {
    if (!dead_[t]) ++num_dead_;
    dead_[t] = 1;
  }
  bool dead(uint32_t t) const { return dead_[t] != 0; }
  size_t num_dead() const { return num_dead_; }

  // The live tet with face {a, b, c} whose fourth vertex d lies on the
  // negative side, orient3d(a, b, c, d) < 0 (behind a front face (a, b, c),
  // which looks into the unmeshed side); kNoTet when there is none (the
  // face is a surface triangle). Exact.
  uint32_t tet_behind(const TetMesh& mesh, uint32_t a, uint32_t b, uint32_t c) const;

  // Removes the dead tets from the mesh (keeping the others' order) and
  // resets the index to the mesh as it is then.
  void drop_dead_tets(TetMesh& mesh);

 private:
  void build(const TetMesh& mesh);

  std::vector<uint32_t> first_;  // per vertex + 1, into tets_of_
  std::vector<uint32_t> tets_of_;
  size_t indexed_ = 0;  // tets [0, indexed_) are indexed
  size_t built_ = 0;    // tets [0, built_) are in the compressed array
  std::unordered_map<uint32_t, std::vector<uint32_t>> later_;
  std::vector<uint8_t> dead_;
  size_t num_dead_ = 0;
};

}  // namespace partet
