// Tets by vertex with later additions and dead flags (see tet_incidence.hpp).
#include "front/tet_incidence.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/predicates.hpp"

namespace partet {

TetIncidence::TetIncidence(const TetMesh& mesh) { build(mesh); }

void TetIncidence::build(const TetMesh& mesh) {
  PARTET_ASSERT(mesh.num_tets() < kNoTet, "too many tets");
  const size_t nv = mesh.num_vertices();
  first_.assign(nv + 1, 0);
  for (uint32_t v : mesh.tets) ++first_[v + 1];
  for (size_t v = 0; v < nv; ++v) first_[v + 1] += first_[v];
  tets_of_.resize(mesh.tets.size());
  std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
  for (size_t t = 0; t < mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i) tets_of_[fill[mesh.tets[4 * t + i]]++] = static_cast<uint32_t>(t);
  built_ = indexed_ = mesh.num_tets();
  later_.clear();
  dead_.assign(mesh.num_tets(), 0);
  num_dead_ = 0;
}

void TetIncidence::index_new(const TetMesh& mesh) {
  PARTET_ASSERT(mesh.num_tets() < kNoTet, "too many tets");
  for (size_t t = indexed_; t < mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i) later_[mesh.tets[4 * t + i]].push_back(static_cast<uint32_t>(t));
  indexed_ = mesh.num_tets();
  dead_.resize(indexed_, 0);
}

uint32_t TetIncidence::tet_behind(const TetMesh& mesh, uint32_t a, uint32_t b, uint32_t c) const {
  auto behind = [&](uint32_t t) {
    if (dead_[t]) return false;
    const uint32_t* q = &mesh.tets[4 * size_t{t}];
    uint32_t other = kNoTet;
    int shared = 0;
    for (int i = 0; i < 4; ++i) {
      if (q[i] == a || q[i] == b || q[i] == c)
        ++shared;
      else
        other = q[i];
    }
    return shared == 3 && orient3d(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(other)) < 0;
  };
  if (a + size_t{1} < first_.size())
    for (uint32_t i = first_[a]; i < first_[a + 1]; ++i)
      if (behind(tets_of_[i])) return tets_of_[i];
  auto it = later_.find(a);
  if (it != later_.end())
    for (uint32_t t : it->second)
      if (behind(t)) return t;
  return kNoTet;
}

void TetIncidence::drop_dead_tets(TetMesh& mesh) {
  size_t kept = 0;
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    if (t < dead_.size() && dead_[t]) continue;
    std::copy_n(&mesh.tets[4 * t], 4, &mesh.tets[4 * kept]);
    ++kept;
  }
  mesh.tets.resize(4 * kept);
  build(mesh);
}

}  // namespace partet
