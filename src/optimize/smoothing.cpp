// smooth_vertex (see smoothing.hpp). Lengths are relative to the mean
// distance from v to its neighbours (`scale`), so the steps are scale-free.
#include "optimize/smoothing.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

constexpr int kMaxSteps = 8;           // ascent steps per call
constexpr int kHalvings = 6;           // line-search halvings per step
constexpr double kActiveBand = 1e-3;   // tets this close to the worst are active
constexpr double kModelBand = 0.1;     // tets this close to the worst are modelled for the first step
constexpr double kMaxMove = 0.5;       // longest step, in units of scale

double dot3(const double* u, const double* w) { return u[0] * w[0] + u[1] * w[1] + u[2] * w[2]; }

// The star of v with v's position replaced by a trial point.
class Star {
 public:
  Star(const TetTopology& topo, uint32_t v, const std::vector<uint32_t>& tets) : topo_(topo), v_(v), tets_(tets) {}

  double quality(size_t k, const double* x) const {
    const double* p[4];
    points(k, x, p);
    return tet_quality(p[0], p[1], p[2], p[3]);
  }
  // Quality of star tet k with v at x, and its gradient in x.
  double quality_gradient(size_t k, const double* x, double* gradient) const {
    const double* p[4];
    points(k, x, p);
    const uint32_t* t = topo_.tet(tets_[k]);
    const int j = t[0] == v_ ? 0 : t[1] == v_ ? 1 : t[2] == v_ ? 2 : 3;
    return tet_quality_gradient(p, j, gradient);
  }
  bool positive(const double* x) const {
    for (size_t k = 0; k < tets_.size(); ++k) {
      const double* p[4];
      points(k, x, p);
      if (orient3d(p[0], p[1], p[2], p[3]) <= 0) return false;
    }
    return true;
  }
  // True when every star tet's quality with v at x exceeds `bar`; stops at
  // the first that does not, trying the tets of `first` (ascending) before
  // the others: the worst tets are the likeliest to fail. The qualities go
  // to `quality` (complete only when true).
  bool all_above(const double* x, double bar, const std::vector<size_t>& first,
                 std::vector<double>& quality) const {
    for (size_t k : first) {
      quality[k] = this->quality(k, x);
      if (!(quality[k] > bar)) return false;
    }
    size_t next_first = 0;
    for (size_t k = 0; k < tets_.size(); ++k) {
      if (next_first < first.size() && first[next_first] == k) {
        ++next_first;
        continue;
      }
      quality[k] = this->quality(k, x);
      if (!(quality[k] > bar)) return false;
    }
    return true;
  }
  // Mean distance from x to the other vertices of the star's tets.
  double scale(const double* x) const {
    double sum = 0;
    for (size_t k = 0; k < tets_.size(); ++k) {
      const uint32_t* t = topo_.tet(tets_[k]);
      for (int i = 0; i < 4; ++i) {
        if (t[i] == v_) continue;
        const double* p = topo_.point(t[i]);
        sum += std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) + (p[2] - x[2]) * (p[2] - x[2]));
      }
    }
    return sum / static_cast<double>(3 * tets_.size());
  }

 private:
  void points(size_t k, const double* x, const double* p[4]) const {
    const uint32_t* t = topo_.tet(tets_[k]);
    for (int i = 0; i < 4; ++i) p[i] = t[i] == v_ ? x : topo_.point(t[i]);
  }

  const TetTopology& topo_;
  uint32_t v_;
  const std::vector<uint32_t>& tets_;
};

// The point of least norm in the convex hull of the gradients of `active`
// (Gilbert's algorithm: move towards the vertex most opposed to d).
void least_norm_direction(const std::vector<double>& gradient, const std::vector<size_t>& active, double d[3]) {
  size_t first = active[0];
  for (size_t k : active)
    if (dot3(&gradient[3 * k], &gradient[3 * k]) < dot3(&gradient[3 * first], &gradient[3 * first])) first = k;
  std::copy_n(&gradient[3 * first], 3, d);
  for (int iteration = 0; iteration < 64; ++iteration) {
    size_t most = active[0];
    for (size_t k : active)
      if (dot3(&gradient[3 * k], d) < dot3(&gradient[3 * most], d)) most = k;
    const double* g = &gradient[3 * most];
    const double dd = dot3(d, d);
    if (dd - dot3(g, d) <= 1e-12 * dd) return;
    const double e[3] = {g[0] - d[0], g[1] - d[1], g[2] - d[2]};
    const double t = std::clamp(-dot3(d, e) / dot3(e, e), 0.0, 1.0);
    for (int i = 0; i < 3; ++i) d[i] += t * e[i];
  }
}

}  // namespace

bool smooth_vertex(TetTopology& topo, uint32_t v, SmoothingScratch& scratch) {
  topo.vertex_star(v, scratch.star);
  if (scratch.star.empty()) return false;
  const Star star(topo, v, scratch.star);
  const size_t n = scratch.star.size();
  double x[3];
  std::copy_n(topo.point(v), 3, x);
  const double scale = star.scale(x);
  if (!(scale > 0)) return false;
  scratch.quality.resize(n);
  scratch.trial.resize(n);
  scratch.gradient.resize(3 * n);
  std::vector<size_t>& active = scratch.active;
  bool moved = false;

  for (size_t k = 0; k < n; ++k) scratch.quality[k] = topo.quality(scratch.star[k]);
  for (int step = 0; step < kMaxSteps; ++step) {
    // scratch.quality holds the star's qualities at x.
    const double worst = *std::min_element(scratch.quality.begin(), scratch.quality.end());
    for (size_t k = 0; k < n; ++k)
      if (scratch.quality[k] <= worst + kModelBand) star.quality_gradient(k, x, &scratch.gradient[3 * k]);
    active.clear();
    for (size_t k = 0; k < n; ++k)
      if (scratch.quality[k] <= worst + kActiveBand) active.push_back(k);
    double d[3];
    least_norm_direction(scratch.gradient, active, d);
    const double norm = std::sqrt(dot3(d, d));
    if (!(norm * scale > 1e-9)) break;

    // First step: where the linear model of a non-active tet meets the worst.
    double rate = dot3(&scratch.gradient[3 * active[0]], d);
    for (size_t k : active) rate = std::min(rate, dot3(&scratch.gradient[3 * k], d));
    double alpha = kMaxMove * scale / norm;
    for (size_t k = 0; k < n; ++k) {
      if (scratch.quality[k] <= worst + kActiveBand || scratch.quality[k] > worst + kModelBand) continue;
      const double rate_k = dot3(&scratch.gradient[3 * k], d);
      if (rate_k < rate)
        alpha = std::min(alpha, (scratch.quality[k] - worst) / (rate - rate_k));
    }

    bool improved = false;
    for (int halving = 0; halving < kHalvings && !improved; ++halving, alpha /= 2) {
      const double y[3] = {x[0] + alpha * d[0], x[1] + alpha * d[1], x[2] + alpha * d[2]};
      if (star.all_above(y, worst, active, scratch.trial) && star.positive(y)) {
        scratch.quality.swap(scratch.trial);
        std::copy_n(y, 3, x);
        improved = true;
      }
    }
    if (!improved) break;
    moved = true;
  }
  if (moved) topo.move_vertex(v, x);
  return moved;
}

}  // namespace partet
