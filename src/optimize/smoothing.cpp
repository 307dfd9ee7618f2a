// smooth_vertex, relax_vertex and least_norm_direction (see smoothing.hpp).
// Lengths are relative to the mean distance from v to its neighbours
// (`scale`), so the steps are scale-free.
#include "optimize/smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/distance.hpp"
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

// The star of v, as vertex quadruples (4 per tet, each having v), with v's
// position replaced by a trial point.
class Star {
 public:
  Star(const TetTopology& topo, uint32_t v, std::span<const uint32_t> quads, StarPoints& points)
      : topo_(topo), v_(v), quads_(quads), n_(quads.size() / 4), points_(points) {
    points_.load(topo, v, quads);
  }
  size_t size() const { return n_; }

  double quality(size_t k, const double* x) const {
    const double* p[4];
    points(k, x, p);
    return tet_quality(p[0], p[1], p[2], p[3]);
  }
  // Quality of star tet k with v at x, and its gradient in x.
  double quality_gradient(size_t k, const double* x, double* gradient) const {
    const double* p[4];
    points(k, x, p);
    const uint32_t* t = &quads_[4 * k];
    const int j = t[0] == v_ ? 0 : t[1] == v_ ? 1 : t[2] == v_ ? 2 : 3;
    return tet_quality_gradient(p, j, gradient);
  }
  // True when every star tet is positive (exact orient3d) with v at x.
  bool positive(const double* x) const {
    points_.place(x);
    return points_.all_positive();
  }
  // True when every star tet's quality with v at x exceeds `bar`; the tets
  // of `first` are tried one by one before the others, measured together:
  // the worst tets are the likeliest to fail. The qualities go to `quality`
  // (complete only when true).
  bool all_above(const double* x, double bar, const std::vector<size_t>& first,
                 std::vector<double>& quality) const {
    for (size_t k : first) {
      quality[k] = this->quality(k, x);
      if (!(quality[k] > bar)) return false;
    }
    qualities(x, quality);
    for (size_t k = 0; k < n_; ++k)
      if (!(quality[k] > bar)) return false;
    return true;
  }
  // Every star tet's quality with v at x, in `quality` (sized).
  void qualities(const double* x, std::vector<double>& quality) const {
    points_.place(x);
    points_.qualities(quality.data());
  }
  // Every star tet's radius ratio with v at x, in `ratio` (sized).
  void radius_ratios(const double* x, std::vector<double>& ratio) const {
    points_.place(x);
    points_.radius_ratios(ratio.data());
  }
  // The circumcentre terms of every star tet with v at x
  // (circumcentre_terms in tet_kernels.hpp): det, then x, y and z, each
  // size() long, in `terms`.
  void circumcentre_terms(const double* x, std::vector<double>& terms) const {
    points_.place(x);
    terms.resize(4 * n_);
    points_.circumcentre_terms(terms.data(), terms.data() + n_, terms.data() + 2 * n_, terms.data() + 3 * n_);
  }
  // Mean distance from x to the other vertices of the star's tets.
  double scale(const double* x) const {
    double sum = 0;
    for (size_t k = 0; k < n_; ++k) {
      const uint32_t* t = &quads_[4 * k];
      for (int i = 0; i < 4; ++i) {
        if (t[i] == v_) continue;
        const double* p = topo_.point(t[i]);
        sum += std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) + (p[2] - x[2]) * (p[2] - x[2]));
      }
    }
    return sum / static_cast<double>(3 * n_);
  }

 private:
  void points(size_t k, const double* x, const double* p[4]) const {
    const uint32_t* t = &quads_[4 * k];
    for (int i = 0; i < 4; ++i) p[i] = t[i] == v_ ? x : topo_.point(t[i]);
  }

  const TetTopology& topo_;
  uint32_t v_;
  std::span<const uint32_t> quads_;
  size_t n_;
  StarPoints& points_;  // the star's corners by coordinate, v's set per trial
};

// The point of segment ab of least norm.
void least_norm_on_segment(const double* a, const double* b, double d[3]) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double len = dot3(ab, ab);
  const double t = len > 0 ? std::clamp(-dot3(a, ab) / len, 0.0, 1.0) : 0.0;
  for (int i = 0; i < 3; ++i) d[i] = a[i] + t * ab[i];
}

// The volume-weighted mean of the circumcentres of the positive tets of
// `star` with v at x (the optimal Delaunay triangulation update of Chen
// and Xu), in out; false when no tet is positive. The terms are the tet
// kernels' (tet_kernels.hpp), summed in star order.
bool odt_point(const Star& star, const double* x, SmoothingScratch& scratch, double out[3]) {
  star.circumcentre_terms(x, scratch.odt_terms);
  const size_t n = star.size();
  const double* det = scratch.odt_terms.data();
  double sum[3] = {0, 0, 0}, volume = 0;
  for (size_t k = 0; k < n; ++k) {
    if (!(det[k] > 0)) continue;
    for (int i = 0; i < 3; ++i) sum[i] += scratch.odt_terms[(1 + i) * n + k];
    volume += det[k];
  }
  if (!(volume > 0)) return false;
  for (int i = 0; i < 3; ++i) out[i] = sum[i] / volume;
  return true;
}

// The ascent of smooth_vertex over `star`, from x (moved in place);
// scratch.quality holds the star's qualities at x on entry and at the
// final x on return. True if x moved.
bool ascend(const Star& star, double x[3], SmoothingScratch& scratch) {
  const size_t n = star.size();
  const double scale = star.scale(x);
  if (!(scale > 0)) return false;
  scratch.trial.resize(n);
  scratch.gradient.resize(3 * n);
  std::vector<size_t>& active = scratch.active;
  bool moved = false;
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
  return moved;
}

}  // namespace

bool smooth_vertex(TetTopology& topo, uint32_t v, SmoothingScratch& scratch) {
  topo.vertex_star(v, scratch.star);
  if (scratch.star.empty()) return false;
  topo.tet_vertices(scratch.star, scratch.quads);
  const Star star(topo, v, scratch.quads, scratch.points);
  scratch.quality.resize(star.size());
  for (size_t k = 0; k < star.size(); ++k) scratch.quality[k] = topo.quality(scratch.star[k]);
  double x[3];
  std::copy_n(topo.point(v), 3, x);
  if (!ascend(star, x, scratch)) return false;
  topo.move_vertex(v, x, scratch.star);
  // The ascent measured the star at x: no tet is measured again.
  for (size_t k = 0; k < star.size(); ++k) topo.keep_quality(scratch.star[k], scratch.quality[k]);
  return true;
}

bool smooth_new_vertex(TetTopology& topo, uint32_t v, std::span<const uint32_t> quads, SmoothingScratch& scratch) {
  const Star star(topo, v, quads, scratch.points);
  if (star.size() == 0) return false;
  double x[3];
  std::copy_n(topo.point(v), 3, x);
  scratch.quality.resize(star.size());
  star.qualities(x, scratch.quality);
  if (!ascend(star, x, scratch)) return false;
  topo.place_vertex(v, x);
  return true;
}

// One to three gradients are the usual case (two on average on femur).
// Up to six, the answer is the origin when it lies in a tet of four of
// them, else the point nearest the origin of the nearest of their
// triangles (three points, or two or one repeated, make a triangle).
// Beyond, Gilbert's algorithm (move towards the vertex most opposed to d),
// which converges slowly: alone, a fifth of its runs took 64 iterations.
void least_norm_direction(const std::vector<double>& gradient, const std::vector<size_t>& active, double d[3]) {
  const size_t n = active.size();
  auto g = [&](size_t i) { return &gradient[3 * active[i]]; };
  // No direction (no move) unless a candidate below is a number: gradients
  // of near-flat tets can overflow to inf or NaN, and no NaN point is
  // nearer the origin than another.
  d[0] = d[1] = d[2] = 0;
  if (n == 0) return;
  if (n == 1) {
    std::copy_n(g(0), 3, d);
    return;
  }
  if (n == 2) return least_norm_on_segment(g(0), g(1), d);
  if (n <= 6) {
    const double origin[3] = {0, 0, 0};
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j)
        for (size_t k = j + 1; k < n; ++k) {
          double p[3];
          closest_point_on_triangle(origin, g(i), g(j), g(k), p);
          if (dot3(p, p) < best) {
            best = dot3(p, p);
            std::copy_n(p, 3, d);
          }
        }
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j)
        for (size_t k = j + 1; k < n; ++k)
          for (size_t l = k + 1; l < n; ++l) {
            const double* a = g(i);
            const double *b = g(j), *c = g(k), *e = g(l);
            const double whole = orient3d_value(a, b, c, e);
            if (whole == 0) continue;
            const double parts[4] = {orient3d_value(origin, b, c, e), orient3d_value(a, origin, c, e),
                                     orient3d_value(a, b, origin, e), orient3d_value(a, b, c, origin)};
            bool inside = true;
            for (double part : parts) inside = inside && part * whole >= 0;
            if (inside) {
              d[0] = d[1] = d[2] = 0;
              return;
            }
          }
    return;
  }
  size_t first = active[0];
  for (size_t k : active)
    if (dot3(&gradient[3 * k], &gradient[3 * k]) < dot3(&gradient[3 * first], &gradient[3 * first])) first = k;
  std::copy_n(&gradient[3 * first], 3, d);
  for (int iteration = 0; iteration < 64; ++iteration) {
    size_t most = active[0];
    for (size_t k : active)
      if (dot3(&gradient[3 * k], d) < dot3(&gradient[3 * most], d)) most = k;
    const double* gm = &gradient[3 * most];
    const double dd = dot3(d, d);
    if (dd - dot3(gm, d) <= 1e-12 * dd) return;
    const double e[3] = {gm[0] - d[0], gm[1] - d[1], gm[2] - d[2]};
    const double t = std::clamp(-dot3(d, e) / dot3(e, e), 0.0, 1.0);
    for (int i = 0; i < 3; ++i) d[i] += t * e[i];
  }
}

bool relax_vertex(TetTopology& topo, uint32_t v, std::span<const uint32_t> tets, std::span<const uint32_t> around,
                  SmoothingScratch& scratch, double floor) {
  if (tets.empty()) return false;
  topo.tet_vertices(tets, scratch.quads);
  const Star star(topo, v, scratch.quads, scratch.points);
  const size_t n = tets.size();
  double centroid[3] = {0, 0, 0};
  for (uint32_t u : around)
    for (int i = 0; i < 3; ++i) centroid[i] += topo.point(u)[i] / static_cast<double>(around.size());
  // Tets under 10 degrees count as slivers: their number may not grow.
  const double sliver = quality_of_angle(10);
  double worst = std::numeric_limits<double>::infinity();
  int slivers = 0;
  for (size_t k = 0; k < n; ++k) {
    const double q = topo.quality(tets[k]);
    worst = std::min(worst, q);
    slivers += q < sliver;
  }
  worst = std::min(worst, floor);  // the least quality a trial may leave
  scratch.trial.resize(n);
  scratch.trial_ratio.resize(n);
  const double* x = topo.point(v);
  // The star's radius ratio sum at x.
  double sum = 0;
  for (size_t k = 0; k < n; ++k) sum += topo.radius_ratio(tets[k]);
  double odt[3];
  const bool has_odt = odt_point(star, x, scratch, odt);
  const double* targets[2] = {odt, centroid};
  // The radius ratios first: most refused trials raise no radius ratio
  // (femur r1: 156,000 of 189,000), and then no quality is measured; then
  // the qualities (all at once: StarPoints), then exact orientation.
  for (int i = has_odt ? 0 : 1; i < 2; ++i)
    for (const double step : {1.0, 0.5, 0.25}) {
      const double* target = targets[i];
      const double y[3] = {x[0] + step * (target[0] - x[0]), x[1] + step * (target[1] - x[1]),
                           x[2] + step * (target[2] - x[2])};
      star.radius_ratios(y, scratch.trial_ratio);
      double trial_sum = 0;
      for (size_t k = 0; k < n; ++k) trial_sum += scratch.trial_ratio[k];
      if (!(trial_sum > sum)) continue;
      star.qualities(y, scratch.trial);
      int trial_slivers = 0;
      bool keeps = true;
      for (size_t k = 0; k < n && keeps; ++k) {
        keeps = scratch.trial[k] >= worst;
        trial_slivers += scratch.trial[k] < sliver;
      }
      if (!keeps || trial_slivers > slivers || !star.positive(y)) continue;
      topo.move_vertex(v, y, tets);
      // The star's measures at y are the trial's: no tet is measured again.
      for (size_t k = 0; k < n; ++k) topo.keep_measures(tets[k], scratch.trial[k], scratch.trial_ratio[k]);
      return true;
    }
  return false;
}

}  // namespace partet
