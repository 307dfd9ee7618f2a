// collapse_vertex (see collapse.hpp): every free vertex of the tet, every
// neighbour, the cones checked and measured before anything changes; one
// replace() for the collapse that wins. Nearly every neighbour fails on a
// cone no better than the star's worst (99.5 % on handle r1): the cones are
// screened in the order likeliest to meet that cone first, and only a
// neighbour whose cones all pass is measured, in star order.
#include "optimize/collapse.hpp"

#include <algorithm>
#include <limits>
#include <utility>

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

// The tet of star tet s with v replaced by w.
void cone_of(const TetTopology& topo, uint32_t s, uint32_t v, uint32_t w, uint32_t* cone) {
  const uint32_t* tet = topo.tet(s);
  std::copy_n(tet, 4, cone);
  cone[local_index(tet, v)] = w;
}

// Screens the cones from w over v's star (`star`), the tets having w
// skipped: false at the first whose quality is not above `beat` or that is
// not positive. The tet that failed last goes first (it fails again for
// more than half the neighbours on CAD parts), then the tets of
// `by_quality` ((old quality, star index), ascending: the worst first
// halve the tests to the first failure).
// The qualities of the cones go to `quality`, by star index (complete
// only when true).
bool cones_beat(const TetTopology& topo, const std::vector<uint32_t>& star,
                const std::vector<std::pair<double, size_t>>& by_quality, uint32_t v, uint32_t w, double beat,
                size_t& last_failed, std::vector<double>& quality) {
  auto passes = [&](size_t i) {
    uint32_t cone[4];
    cone_of(topo, star[i], v, w, cone);
    const double* p[4] = {topo.point(cone[0]), topo.point(cone[1]), topo.point(cone[2]), topo.point(cone[3])};
    quality[i] = tet_quality(p[0], p[1], p[2], p[3]);
    return quality[i] > beat && orient3d(p[0], p[1], p[2], p[3]) > 0;
  };
  const size_t first = last_failed;
  if (first < star.size() && local_index(topo.tet(star[first]), w) < 0 && !passes(first)) return false;
  for (const auto& entry : by_quality) {
    const size_t i = entry.second;
    if (i == first || local_index(topo.tet(star[i]), w) >= 0) continue;
    if (!passes(i)) {
      last_failed = i;
      return false;
    }
  }
  return true;
}

}  // namespace

bool collapse_vertex(TetTopology& topo, uint32_t t, const std::vector<uint8_t>& frozen, double bar,
                     InsertionRule rule, RefusedCollapses* refused) {
  const double ten = quality_of_angle(kSliverAngle);
  Collapse best;
  std::vector<uint32_t> star, neighbours, quads, old_quads;
  std::vector<std::pair<double, size_t>> by_quality;
  std::vector<double> cone_quality;
  uint32_t corners[4];
  std::copy_n(topo.tet(t), 4, corners);
  uint32_t tried[4];  // the free corners measured
  int tried_count = 0;
  for (uint32_t v : corners) {
    if (v >= frozen.size() || frozen[v] || topo.on_boundary(v) || (refused && refused->known(topo, v))) continue;
    tried[tried_count++] = v;
    topo.vertex_star(v, star);
    double old_quality = std::numeric_limits<double>::infinity(), old_deficit = 0;
    int old_slivers = 0;
    for (uint32_t s : star) {
      const double q = topo.quality(s);
      old_quality = std::min(old_quality, q);
      old_deficit += std::max(0.0, bar - q);
      old_slivers += q < ten;
    }
    topo.star_neighbours(v, star, neighbours);
    by_quality.clear();
    for (size_t i = 0; i < star.size(); ++i) by_quality.emplace_back(topo.quality(star[i]), i);
    std::sort(by_quality.begin(), by_quality.end());
    cone_quality.resize(star.size());
    size_t last_failed = star.size();
    for (uint32_t w : neighbours) {
      // Only a collapse beating the star's worst and the best so far counts.
      const double beat = std::max(old_quality, best.quality);
      if (!cones_beat(topo, star, by_quality, v, w, beat, last_failed, cone_quality)) continue;
      double new_quality = std::numeric_limits<double>::infinity(), new_deficit = 0;
      int new_slivers = 0;
      quads.clear();
      for (size_t i = 0; i < star.size(); ++i) {
        if (local_index(topo.tet(star[i]), w) >= 0) continue;
        const double q = cone_quality[i];
        new_quality = std::min(new_quality, q);
        new_deficit += std::max(0.0, bar - q);
        new_slivers += q < ten;
        uint32_t cone[4];
        cone_of(topo, star[i], v, w, cone);
        quads.insert(quads.end(), cone, cone + 4);
      }
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
  if (best.star.empty()) {
    // Every vertex was measured against its own star's worst alone.
    if (refused)
      for (int i = 0; i < tried_count; ++i) refused->add(topo, tried[i]);
    return false;
  }
  std::vector<uint32_t> created;
  topo.replace(best.star, best.quads, created);
  return true;
}

}  // namespace partet
