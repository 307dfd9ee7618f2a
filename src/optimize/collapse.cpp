// collapse_vertex (see collapse.hpp): every free vertex of the tet, every
// neighbour, the cones checked and measured before anything changes; one
// replace() for the collapse that wins.
#include "optimize/collapse.hpp"

#include <algorithm>
#include <limits>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

// A tet with an angle under this many degrees counts as a sliver (as for
// insertion).
constexpr double kSliverAngle = 10;

struct Collapse {
  double quality = -std::numeric_limits<double>::infinity();  // new worst
  std::vector<uint32_t> star;   // v's star: the tets replaced
  std::vector<uint32_t> quads;  // the new tets
};

}  // namespace

bool collapse_vertex(TetTopology& topo, uint32_t t, const std::vector<uint8_t>& frozen, double bar,
                     InsertionRule rule) {
  const double ten = quality_of_angle(kSliverAngle);
  Collapse best;
  std::vector<uint32_t> star, neighbours, quads, old_quads;
  uint32_t corners[4];
  std::copy_n(topo.tet(t), 4, corners);
  for (uint32_t v : corners) {
    if (v >= frozen.size() || frozen[v]) continue;
    topo.vertex_star(v, star);
    if (on_open_face(topo, v, star)) continue;
    double old_quality = std::numeric_limits<double>::infinity(), old_deficit = 0;
    int old_slivers = 0;
    for (uint32_t s : star) {
      const double q = topo.quality(s);
      old_quality = std::min(old_quality, q);
      old_deficit += std::max(0.0, bar - q);
      old_slivers += q < ten;
    }
    topo.star_neighbours(v, star, neighbours);
    for (uint32_t w : neighbours) {
      // Only a collapse beating the star's worst and the best so far counts.
      const double beat = std::max(old_quality, best.quality);
      double new_quality = std::numeric_limits<double>::infinity(), new_deficit = 0;
      int new_slivers = 0;
      quads.clear();
      bool valid = true;
      for (uint32_t s : star) {
        const uint32_t* tet = topo.tet(s);
        if (local_index(tet, w) >= 0) continue;
        uint32_t cone[4];
        std::copy_n(tet, 4, cone);
        cone[local_index(tet, v)] = w;
        const double* p[4] = {topo.point(cone[0]), topo.point(cone[1]), topo.point(cone[2]), topo.point(cone[3])};
        const double q = tet_quality(p[0], p[1], p[2], p[3]);
        if (!(q > beat) || orient3d(p[0], p[1], p[2], p[3]) <= 0) {
          valid = false;
          break;
        }
        new_quality = std::min(new_quality, q);
        new_deficit += std::max(0.0, bar - q);
        new_slivers += q < ten;
        quads.insert(quads.end(), cone, cone + 4);
      }
      if (!valid) continue;
      if (rule == InsertionRule::kShortfall) {
        if (new_deficit > old_deficit || new_slivers > old_slivers) continue;
      } else {
        topo.tet_vertices(star, old_quads);
        if (!min_angle_no_worse(topo, old_quads, quads)) continue;
      }
      best.quality = new_quality;
      best.star = star;
      best.quads = quads;
    }
  }
  if (best.star.empty()) return false;
  std::vector<uint32_t> created;
  topo.replace(best.star, best.quads, created);
  return true;
}

}  // namespace partet
