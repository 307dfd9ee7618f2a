// insert_vertex (see insertion.hpp). A trial is applied for real (replace)
// so that smoothing sees the new star, and undone by the reverse replace.
#include "optimize/insertion.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

// The shortfall is measured below min(target, this angle in degrees): with
// the full target, a new vertex never pays off; with none, one bad tet is
// traded for a dozen barely better ones.
constexpr double kShortfallAngle = 20;

double quality_of(const TetTopology& topo, const uint32_t* v) {
  return tet_quality(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3]));
}

// Inserts a vertex at p into `cavity` if that pays (see insertion.hpp).
bool try_cavity(TetTopology& topo, const std::vector<uint32_t>& cavity, const double* p, double bar,
                SmoothingScratch& scratch) {
  std::vector<uint32_t> old_tets, new_tets, created;
  double old_quality = std::numeric_limits<double>::infinity();
  double old_deficit = 0, new_deficit = 0;  // sum of max(0, bar - quality)
  for (uint32_t t : cavity) {
    old_tets.insert(old_tets.end(), topo.tet(t), topo.tet(t) + 4);
    const double q = quality_of(topo, topo.tet(t));
    old_quality = std::min(old_quality, q);
    old_deficit += std::max(0.0, bar - q);
  }
  const uint32_t v = topo.add_vertex(p, kOptimizerVertexId | topo.num_vertices());
  // Each outer face is coned to v: its tet with the opposite vertex replaced.
  for (uint32_t t : cavity) {
    for (int f = 0; f < 4; ++f) {
      const uint32_t other = topo.twin(4 * t + f);
      if (other != TetTopology::kNone && std::find(cavity.begin(), cavity.end(), other / 4) != cavity.end()) continue;
      uint32_t tet[4];
      std::copy_n(topo.tet(t), 4, tet);
      tet[f] = v;
      if (orient3d(topo.point(tet[0]), topo.point(tet[1]), topo.point(tet[2]), topo.point(tet[3])) <= 0) {
        topo.remove_last_vertex();
        return false;
      }
      new_tets.insert(new_tets.end(), tet, tet + 4);
    }
  }
  // A vertex inside the cavity (on no outer face) would vanish: not here.
  for (uint32_t u : old_tets) {
    if (std::find(new_tets.begin(), new_tets.end(), u) == new_tets.end()) {
      topo.remove_last_vertex();
      return false;
    }
  }
  topo.replace(cavity, new_tets, created);
  smooth_vertex(topo, v, scratch);
  double new_quality = std::numeric_limits<double>::infinity();
  for (uint32_t t : created) {
    const double q = quality_of(topo, topo.tet(t));
    new_quality = std::min(new_quality, q);
    new_deficit += std::max(0.0, bar - q);
  }
  if (new_quality > old_quality && new_deficit <= old_deficit) return true;
  std::vector<uint32_t> restored;
  topo.replace(created, old_tets, restored);
  topo.remove_last_vertex();
  return false;
}

}  // namespace

double insertion_bar(double target) { return std::min(target, quality_of_angle(kShortfallAngle)); }

bool insert_vertex(TetTopology& topo, uint32_t t, double target, SmoothingScratch& scratch) {
  const uint32_t* v = topo.tet(t);
  double centroid[3];
  for (int i = 0; i < 3; ++i)
    centroid[i] = (topo.point(v[0])[i] + topo.point(v[1])[i] + topo.point(v[2])[i] + topo.point(v[3])[i]) / 4;
  const double bar = insertion_bar(target);
  std::vector<uint32_t> cavity = {t};
  for (int f = 0; f < 4; ++f)
    if (topo.twin(4 * t + f) != TetTopology::kNone) cavity.push_back(topo.twin(4 * t + f) / 4);
  if (cavity.size() > 1 && try_cavity(topo, cavity, centroid, bar, scratch)) return true;
  return try_cavity(topo, {t}, centroid, bar, scratch);
}

}  // namespace partet
