// Point-to-triangle closest point and distance in doubles (Voronoi regions,
// after Ericson, Real-Time Collision Detection §5.1.5), for size, spacing
// and search-direction heuristics only: geometric decisions use the exact
// predicates. TriangleBoxReach rejects far points before the distance.
#pragma once

#include <algorithm>
#include <cmath>

namespace partet {

// The point of triangle abc closest to p, in q (a for a degenerate
// triangle whose closest point is inside).
inline void closest_point_on_triangle(const double* p, const double* a, const double* b, const double* c, double* q) {
  auto sub = [](const double* x, const double* y, double* r) {
    for (int k = 0; k < 3; ++k) r[k] = x[k] - y[k];
  };
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  double ab[3], ac[3], ap[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  auto at = [&](double v, double w) {  // a + v ab + w ac
    for (int k = 0; k < 3; ++k) q[k] = a[k] + v * ab[k] + w * ac[k];
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  double bp[3], cp[3];
  sub(p, b, bp);
  sub(p, c, cp);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  if (d1 <= 0 && d2 <= 0) {
    at(0, 0);
  } else if (d3 >= 0 && d4 <= d3) {
    at(1, 0);
  } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    at(d1 / (d1 - d3), 0);
  } else if (d6 >= 0 && d5 <= d6) {
    at(0, 1);
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    at(0, d2 / (d2 - d6));
  } else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    at(1 - w, w);
  } else {
    const double denom = va + vb + vc;
    if (!(denom != 0)) {
      at(0, 0);
    } else {
      at(vb / denom, vc / denom);
    }
  }
}

inline double squared_point_triangle_distance(const double* p, const double* a, const double* b, const double* c) {
  double q[3];
  closest_point_on_triangle(p, a, b, c, q);
  const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

// A cheap rejection before squared_point_triangle_distance: whether a
// point lies farther than `reach` from triangle abc's bounding box, by a
// margin of 1e-9 of the coordinates' size, far above that distance's
// rounding, so that the distance would come out at least reach too.
class TriangleBoxReach {
 public:
  TriangleBoxReach(const double* a, const double* b, const double* c, double reach) {
    double scale = reach;
    for (int k = 0; k < 3; ++k) {
      box_[k] = std::min({a[k], b[k], c[k]});
      box_[k + 3] = std::max({a[k], b[k], c[k]});
      scale = std::max({scale, std::fabs(box_[k]), std::fabs(box_[k + 3])});
    }
    const double far = reach + 1e-9 * scale;
    far2_ = far * far;
  }
  bool excludes(const double* p) const {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = std::max({box_[k] - p[k], p[k] - box_[k + 3], 0.0});
      d2 += d * d;
    }
    return d2 > far2_;
  }

 private:
  double box_[6];  // min xyz, max xyz
  double far2_;
};

}  // namespace partet
