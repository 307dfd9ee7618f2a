// joint_region and smooth_jointly (see joint_smoothing.hpp). Lengths are
// relative to the region's mean edge length, so the steps are scale-free.
#include "optimize/joint_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

constexpr int kMaxSteps = 32;             // ascent steps per call
constexpr int kHalvings = 10;             // line-search halvings per step
constexpr double kActiveBand = 1e-3;      // tets this close to the worst are active
constexpr double kMaxMove = 0.25;         // longest vertex step, in mean edge lengths
constexpr int kGilbertIterations = 1024;  // for the least-norm direction

double dot(const double* u, const double* w, size_t n) {
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += u[i] * w[i];
  return sum;
}

// The point of least norm in the convex hull of `count` vectors of
// dimension n (rows of `rows`), by Gilbert's iterations, in d.
void least_norm_point(const std::vector<double>& rows, size_t count, size_t n, std::vector<double>& d) {
  size_t first = 0;
  for (size_t k = 1; k < count; ++k)
    if (dot(&rows[k * n], &rows[k * n], n) < dot(&rows[first * n], &rows[first * n], n)) first = k;
  d.assign(rows.begin() + static_cast<std::ptrdiff_t>(first * n),
           rows.begin() + static_cast<std::ptrdiff_t>((first + 1) * n));
  std::vector<double> e(n);
  for (int iteration = 0; iteration < kGilbertIterations; ++iteration) {
    size_t most = 0;
    double lowest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < count; ++k) {
      const double s = dot(&rows[k * n], d.data(), n);
      if (s < lowest) {
        lowest = s;
        most = k;
      }
    }
    const double dd = dot(d.data(), d.data(), n);
    if (dd - lowest <= 1e-12 * dd) return;
    for (size_t i = 0; i < n; ++i) e[i] = rows[most * n + i] - d[i];
    const double ee = dot(e.data(), e.data(), n);
    if (!(ee > 0)) return;
    const double t = std::clamp(-dot(d.data(), e.data(), n) / ee, 0.0, 1.0);
    for (size_t i = 0; i < n; ++i) d[i] += t * e[i];
  }
}

}  // namespace

void tied_vertices(const TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen, double band,
                   size_t cap, std::vector<uint32_t>& vertices) {
  const auto take = [&](uint32_t v) {
    if (vertices.size() < cap && !(v < frozen.size() && frozen[v]) &&
        std::find(vertices.begin(), vertices.end(), v) == vertices.end())
      vertices.push_back(v);
  };
  vertices.clear();
  for (int k = 0; k < 4; ++k) take(topo.tet(worst)[k]);
  const double bar = topo.quality(worst) + band;
  std::vector<uint32_t> star;
  for (size_t i = 0; i < vertices.size(); ++i) {
    topo.vertex_star(vertices[i], star);
    for (uint32_t t : star)
      if (topo.quality(t) <= bar)
        for (int k = 0; k < 4; ++k) take(topo.tet(t)[k]);
  }
}

void joint_region(const TetTopology& topo, const std::vector<uint32_t>& vertices, std::vector<uint32_t>& region) {
  region.clear();
  std::vector<uint32_t> star;
  for (uint32_t v : vertices) {
    topo.vertex_star(v, star);
    region.insert(region.end(), star.begin(), star.end());
  }
  std::sort(region.begin(), region.end());
  region.erase(std::unique(region.begin(), region.end()), region.end());
}

bool smooth_jointly(TetTopology& topo, const std::vector<uint32_t>& vertices, const std::vector<uint32_t>& region) {
  const size_t m = vertices.size(), r = region.size(), n = 3 * m;
  if (m == 0 || r == 0) return false;
  // Per region tet and corner, the moving vertex's slot, or -1.
  std::vector<int> slot(4 * r, -1);
  double scale = 0;
  for (size_t k = 0; k < r; ++k) {
    const uint32_t* t = topo.tet(region[k]);
    for (int i = 0; i < 4; ++i) {
      const auto it = std::find(vertices.begin(), vertices.end(), t[i]);
      if (it != vertices.end()) slot[4 * k + i] = static_cast<int>(it - vertices.begin());
      for (int j = i + 1; j < 4; ++j) {
        const double *a = topo.point(t[i]), *b = topo.point(t[j]);
        scale += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
      }
    }
  }
  scale /= static_cast<double>(6 * r);
  if (!(scale > 0)) return false;
  std::vector<double> x(n), y(n);
  for (size_t s = 0; s < m; ++s) std::copy_n(topo.point(vertices[s]), 3, &x[3 * s]);
  const auto corners = [&](size_t k, const std::vector<double>& at, const double* p[4]) {
    const uint32_t* t = topo.tet(region[k]);
    for (int i = 0; i < 4; ++i) p[i] = slot[4 * k + i] >= 0 ? &at[3 * static_cast<size_t>(slot[4 * k + i])] : topo.point(t[i]);
  };
  std::vector<double> quality(r), trial(r), rows, d;
  for (size_t k = 0; k < r; ++k) quality[k] = topo.quality(region[k]);
  bool moved = false;
  for (int step = 0; step < kMaxSteps; ++step) {
    const double worst = *std::min_element(quality.begin(), quality.end());
    rows.clear();
    size_t active = 0;
    for (size_t k = 0; k < r; ++k) {
      if (quality[k] > worst + kActiveBand) continue;
      rows.resize(rows.size() + n, 0.0);
      double* row = &rows[active * n];
      const double* p[4];
      corners(k, x, p);
      for (int i = 0; i < 4; ++i)
        if (slot[4 * k + i] >= 0) tet_quality_gradient(p, i, row + 3 * slot[4 * k + i]);
      ++active;
    }
    least_norm_point(rows, active, n, d);
    double longest = 0;
    for (size_t s = 0; s < m; ++s) longest = std::max(longest, std::sqrt(dot(&d[3 * s], &d[3 * s], 3)));
    if (!(longest * scale > 1e-9)) break;
    bool ascends = true;
    for (size_t k = 0; k < active && ascends; ++k) ascends = dot(&rows[k * n], d.data(), n) > 0;
    if (!ascends) break;
    double alpha = kMaxMove * scale / longest;
    bool improved = false;
    for (int halving = 0; halving < kHalvings && !improved; ++halving, alpha /= 2) {
      for (size_t i = 0; i < n; ++i) y[i] = x[i] + alpha * d[i];
      bool above = true;
      for (size_t k = 0; k < r && above; ++k) {
        const double* p[4];
        corners(k, y, p);
        trial[k] = tet_quality(p[0], p[1], p[2], p[3]);
        above = trial[k] > worst;
      }
      for (size_t k = 0; k < r && above; ++k) {
        const double* p[4];
        corners(k, y, p);
        above = orient3d(p[0], p[1], p[2], p[3]) > 0;
      }
      if (!above) continue;
      x.swap(y);
      quality.swap(trial);
      improved = true;
    }
    if (!improved) break;
    moved = true;
  }
  if (moved)
    for (size_t s = 0; s < m; ++s) topo.move_vertex(vertices[s], &x[3 * s]);
  return moved;
}

}  // namespace partet
