// Box against triangle: exact separating-axis intersection test and a
// floating-point distance threshold (see box_triangle.hpp).
#include "octree/box_triangle.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"

namespace partet {

namespace {

// p in [lo, hi], or [lo, hi) on the axes marked in `open` (nullptr: none).
bool point_in_box(const double* p, const double* lo, const double* hi, const bool* open) {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < lo[i] || p[i] > hi[i]) return false;
    if (open && open[i] && p[i] == hi[i]) return false;
  }
  return true;
}

// The 8 corners of box [lo, hi]; corner k takes hi on axis i iff bit i of k.
void box_corners(const double* lo, const double* hi, double corner[8][3]) {
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) corner[k][i] = (k >> i & 1) ? hi[i] : lo[i];
}

// A linear function of the corner with gradient signs g[3] (each -1, 0, +1)
// is largest at the corner taking hi where g > 0 and lo elsewhere, and
// smallest at the opposite corner (any choice where g = 0).
int max_corner(const int* g) { return (g[0] > 0) | (g[1] > 0) << 1 | (g[2] > 0) << 2; }

int sign_of_difference(double a, double b) { return (a > b) - (a < b); }

// The axes kept by the projection dropping `drop`, in orient2d_projected's
// order.
void kept_axes(int drop, int& i, int& j) {
  i = drop == 2 ? 0 : drop + 1;
  j = drop == 0 ? 2 : (drop == 1 ? 0 : 1);
}

// In the projection dropping axis `drop` (kept axes i, j as in
// orient2d_projected), orient2d(p, q, r) is linear in r with gradient
// (-(q_j - p_j), q_i - p_i); true when the box's projection lies strictly on
// the side of line pq given by `side` (+1 or -1), tested at its extreme
// corner only.
// With `open` (see box_meets_triangle_impl), the box's upper faces on the
// open axes are pulled in by an infinitesimal: a corner coordinate taking
// hi where the gradient is negative raises side * orient2d, so a zero
// counts as strictly on the side.
bool box_strictly_on_side(const double* p, const double* q, const double corner[8][3], int drop, int side,
                          const bool* open) {
  int i, j;
  kept_axes(drop, i, j);
  int g[3] = {0, 0, 0};
  g[i] = -sign_of_difference(q[j], p[j]) * side;
  g[j] = sign_of_difference(q[i], p[i]) * side;
  // The corner where side * orient2d is smallest (the dropped axis does not
  // matter); it takes hi exactly where g <= 0.
  const int o = orient2d_projected(p, q, corner[7 ^ max_corner(g)], drop);
  if (o == side) return true;
  return o == 0 && open && ((open[i] && g[i] < 0) || (open[j] && g[j] < 0));
}

double clamp_gap(double v, double lo, double hi) { return v < lo ? lo - v : (v > hi ? v - hi : 0.0); }

double point_box_dist2(const double* p, const double* lo, const double* hi) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double g = clamp_gap(p[i], lo[i], hi[i]);
    d2 += g * g;
  }
  return d2;
}

double dot(const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

void sub(const double* u, const double* v, double* w) {
  w[0] = u[0] - v[0];
  w[1] = u[1] - v[1];
  w[2] = u[2] - v[2];
}

double dist2(const double* u, const double* v) {
  double w[3];
  sub(u, v, w);
  return dot(w, w);
}

// Squared distance from p to triangle abc (closest point by Voronoi
// regions, Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle_dist2(const double* p, const double* a, const double* b, const double* c) {
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dot(ap, ap);
  sub(p, b, bp);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dot(bp, bp);
  const double vc = d1 * d4 - d3 * d2;
  double x[3];
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    for (int i = 0; i < 3; ++i) x[i] = a[i] + v * ab[i];
    return dist2(p, x);
  }
  sub(p, c, cp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dot(cp, cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    for (int i = 0; i < 3; ++i) x[i] = a[i] + w * ac[i];
    return dist2(p, x);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    for (int i = 0; i < 3; ++i) x[i] = b[i] + w * (c[i] - b[i]);
    return dist2(p, x);
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  for (int i = 0; i < 3; ++i) x[i] = a[i] + ab[i] * v + ac[i] * w;
  return dist2(p, x);
}

// Squared distance between segments p1q1 and p2q2 (Ericson 5.1.9).
double segment_segment_dist2(const double* p1, const double* q1, const double* p2, const double* q2) {
  double d1[3], d2[3], r[3];
  sub(q1, p1, d1);
  sub(q2, p2, d2);
  sub(p1, p2, r);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return dot(r, r);
  if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  double x1[3], x2[3];
  for (int i = 0; i < 3; ++i) {
    x1[i] = p1[i] + d1[i] * s;
    x2[i] = p2[i] + d2[i] * t;
  }
  return dist2(x1, x2);
}

// The separating-axis test in doubles with error bounds: -1 when the plane
// normal or an edge axis separates the box and the triangle by more than
// the rounding error, +1 when every axis (box axes strictly) shows an
// overlap larger than it, 0 when unsure (touching or nearly so: the exact
// test decides). Overlap beyond the error on all 13 axes means the closed
// sets meet, and so do the box with its upper faces pulled in by an
// infinitesimal. Bounds: with M the largest coordinate magnitude and D the
// largest edge component, an edge-axis projection is off by under 2^-47 M D
// and a normal projection by under 2^-46 M D^2 (a few roundings per
// product); 2^-40 leaves a wide margin. Magnitudes where a product could
// underflow or overflow and break those relative bounds are left to the
// exact test.
int separation_filter(const double* lo, const double* hi, const TriangleBoxTest::Parts& t) {
  const double* a = t.v[0];
  const double* const* v = t.v;
  const double (*e)[3] = t.e;
  double m = t.m;
  for (int i = 0; i < 3; ++i) m = std::max({m, std::fabs(lo[i]), std::fabs(hi[i])});
  const double d = t.d;
  if (d < 0x1p-500 || m > 0x1p500) return 0;
  bool meets = true;
  // Box axes: strict overlap (the bounding-box test has already rejected
  // the disjoint cases).
  for (int i = 0; i < 3; ++i) meets = meets && t.thi[i] > lo[i] && t.tlo[i] < hi[i];
  double centre[3], half[3], dc[3];
  for (int i = 0; i < 3; ++i) {
    centre[i] = 0.5 * (lo[i] + hi[i]);
    half[i] = 0.5 * (hi[i] - lo[i]);
    dc[i] = centre[i] - a[i];
  }
  // The plane normal: the box's projection is centred at n.(centre - a)
  // with radius sum |n_i| half_i; the triangle projects to 0.
  const double* n = t.n;
  const double plane_error = 0x1p-40 * m * d * d;
  const double offset = std::fabs(dot(n, dc));
  const double radius = std::fabs(n[0]) * half[0] + std::fabs(n[1]) * half[1] + std::fabs(n[2]) * half[2];
  if (offset - radius > plane_error) return -1;
  meets = meets && radius - offset > plane_error;
  // Edge k crossed with box axis x_i: axis components (kept axes j, l of
  // the projection dropping i) are (-e_l, e_j) up to sign.
  const double edge_error = 0x1p-40 * m * d;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      const double aj = -e[k][l], al = e[k][j];
      if (aj == 0 && al == 0) continue;  // the edge is along x_i: no axis
      double plo = 0, phi = 0;  // the triangle's projection, relative to a
      for (int w = 1; w < 3; ++w) {
        const double p = aj * (v[w][j] - a[j]) + al * (v[w][l] - a[l]);
        plo = std::min(plo, p);
        phi = std::max(phi, p);
      }
      const double mid = aj * dc[j] + al * dc[l];
      const double r = std::fabs(aj) * half[j] + std::fabs(al) * half[l];
      const double gap = std::max(plo - (mid + r), (mid - r) - phi);
      if (gap > edge_error) return -1;
      meets = meets && -gap > edge_error;
    }
  }
  return meets ? 1 : 0;
}

// The separating-axis test of box_triangle.hpp. `open` (nullptr: none)
// marks the axes whose upper face is left out of the box: the box is then
// [lo, hi - eps] on those axes for an infinitesimal eps > 0, which meets the
// triangle exactly when [lo, hi) does. Every quantity tested is linear in
// eps, so a test reads the constant term and, where it is zero, the sign
// of the eps term: upper bounds become strict, and a corner predicate that
// is zero decides by which of its coordinates take a pulled-in hi.
bool box_meets_triangle_impl(const double* lo, const double* hi, const bool* open, const TriangleBoxTest::Parts& t) {
  for (int i = 0; i < 3; ++i)
    if (t.thi[i] < lo[i] || t.tlo[i] > hi[i] || (open && open[i] && t.tlo[i] == hi[i])) return false;
  const double *a = t.v[0], *b = t.v[1], *c = t.v[2];
  if (point_in_box(a, lo, hi, open) || point_in_box(b, lo, hi, open) || point_in_box(c, lo, hi, open)) return true;
  const int filtered = separation_filter(lo, hi, t);
  if (filtered != 0) return filtered > 0;
  double corner[8][3];
  box_corners(lo, hi, corner);
  // normal[k]: sign of component k of (b - a) x (c - a), which is also the
  // orientation of the triangle projected along axis k.
  int normal[3];
  for (int k = 0; k < 3; ++k) normal[k] = orient2d_projected(a, b, c, k);
  // The triangle's plane: orient3d(a, b, c, d) grows along the normal. The
  // top corner takes hi where normal > 0 (pulling those in lowers it), the
  // bottom one where normal <= 0 (pulling in raises it where normal < 0).
  const int top = max_corner(normal);
  const int bottom = 7 ^ top;
  bool top_drops = false, bottom_rises = false;
  for (int k = 0; k < 3 && open; ++k) {
    top_drops = top_drops || (open[k] && normal[k] > 0);
    bottom_rises = bottom_rises || (open[k] && normal[k] < 0);
  }
  const int o_top = orient3d(a, b, c, corner[top]);
  if (o_top < 0 || (o_top == 0 && top_drops)) return false;
  const int o_bottom = orient3d(a, b, c, corner[bottom]);
  if (o_bottom > 0 || (o_bottom == 0 && bottom_rises)) return false;
  const double* v[3] = {a, b, c};
  for (int drop = 0; drop < 3; ++drop) {
    int i, j;
    kept_axes(drop, i, j);
    for (int e = 0; e < 3; ++e) {
      const double* p = v[e];
      const double* q = v[(e + 1) % 3];
      if (p[i] == q[i] && p[j] == q[j]) continue;  // the edge projects to a point: no axis
      if (normal[drop] != 0) {
        // The triangle is on side normal[drop] of each of its edges.
        if (box_strictly_on_side(p, q, corner, drop, -normal[drop], open)) return false;
      } else if (box_strictly_on_side(p, q, corner, drop, 1, open) ||
                 box_strictly_on_side(p, q, corner, drop, -1, open)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

TriangleBoxTest::TriangleBoxTest(const double* a, const double* b, const double* c) {
  parts_.v[0] = a;
  parts_.v[1] = b;
  parts_.v[2] = c;
  parts_.m = parts_.d = 0;
  for (int k = 0; k < 3; ++k) {
    sub(parts_.v[(k + 1) % 3], parts_.v[k], parts_.e[k]);
    for (int i = 0; i < 3; ++i) {
      parts_.m = std::max(parts_.m, std::fabs(parts_.v[k][i]));
      parts_.d = std::max(parts_.d, std::fabs(parts_.e[k][i]));
    }
  }
  for (int i = 0; i < 3; ++i) {
    parts_.tlo[i] = std::min({a[i], b[i], c[i]});
    parts_.thi[i] = std::max({a[i], b[i], c[i]});
  }
  const double(*e)[3] = parts_.e;
  parts_.n[0] = e[0][1] * (-e[2][2]) - e[0][2] * (-e[2][1]);
  parts_.n[1] = e[0][2] * (-e[2][0]) - e[0][0] * (-e[2][2]);
  parts_.n[2] = e[0][0] * (-e[2][1]) - e[0][1] * (-e[2][0]);
}

bool TriangleBoxTest::meets(const double* lo, const double* hi) const {
  return box_meets_triangle_impl(lo, hi, nullptr, parts_);
}

bool TriangleBoxTest::meets_half_open(const double* lo, const double* hi, const bool* open) const {
  return box_meets_triangle_impl(lo, hi, open, parts_);
}

bool box_meets_triangle(const double* lo, const double* hi, const double* a, const double* b, const double* c) {
  return TriangleBoxTest(a, b, c).meets(lo, hi);
}

bool box_meets_triangle_half_open(const double* lo, const double* hi, const bool* open, const double* a,
                                  const double* b, const double* c) {
  return TriangleBoxTest(a, b, c).meets_half_open(lo, hi, open);
}

bool box_triangle_closer_than(const double* lo, const double* hi, const double* a, const double* b,
                              const double* c, double r) {
  const double r2 = r * r;
  // Lower bound: distance between the box and the triangle's bounding box.
  double gap2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double tlo = std::min({a[i], b[i], c[i]}), thi = std::max({a[i], b[i], c[i]});
    const double g = tlo > hi[i] ? tlo - hi[i] : (lo[i] > thi ? lo[i] - thi : 0.0);
    gap2 += g * g;
  }
  if (gap2 >= r2) return false;
  // Upper bound: a triangle vertex near the box.
  if (point_box_dist2(a, lo, hi) < r2 || point_box_dist2(b, lo, hi) < r2 || point_box_dist2(c, lo, hi) < r2)
    return true;
  // Lower bound: distance between the box and the triangle's plane.
  double ab[3], ac[3], n[3];
  sub(b, a, ab);
  sub(c, a, ac);
  n[0] = ab[1] * ac[2] - ab[2] * ac[1];
  n[1] = ab[2] * ac[0] - ab[0] * ac[2];
  n[2] = ab[0] * ac[1] - ab[1] * ac[0];
  const double len = std::sqrt(dot(n, n));
  double centre_offset = 0, reach = 0;
  for (int i = 0; i < 3; ++i) {
    centre_offset += n[i] * (0.5 * (lo[i] + hi[i]) - a[i]);
    reach += 0.5 * (hi[i] - lo[i]) * std::fabs(n[i]);
  }
  if (std::fabs(centre_offset) - reach >= r * len) return false;
  // Lower bounds: separation along the in-plane normals n x e of the edges
  // (the triangle lies behind each edge's line within its plane).
  const double* v[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const double* p = v[e];
    const double* q = v[(e + 1) % 3];
    double edge[3], m[3];
    sub(q, p, edge);
    m[0] = n[1] * edge[2] - n[2] * edge[1];
    m[1] = n[2] * edge[0] - n[0] * edge[2];
    m[2] = n[0] * edge[1] - n[1] * edge[0];
    double offset = 0, spread = 0;
    for (int i = 0; i < 3; ++i) {
      offset += m[i] * (0.5 * (lo[i] + hi[i]) - p[i]);
      spread += 0.5 * (hi[i] - lo[i]) * std::fabs(m[i]);
    }
    // Orient m away from the opposite vertex.
    double w[3];
    sub(v[(e + 2) % 3], p, w);
    if (dot(m, w) > 0) offset = -offset;
    if (offset - spread >= r * std::sqrt(dot(m, m))) return false;
  }
  // Exact features (in floating point): box corners against the triangle,
  // box edges against triangle edges.
  double corner[8][3];
  box_corners(lo, hi, corner);
  for (int k = 0; k < 8; ++k)
    if (point_triangle_dist2(corner[k], a, b, c) < r2) return true;
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < 8; ++k) {
      if (k >> axis & 1) continue;
      const double* p = corner[k];
      const double* q = corner[k | (1 << axis)];
      for (int e = 0; e < 3; ++e)
        if (segment_segment_dist2(p, q, v[e], v[(e + 1) % 3]) < r2) return true;
    }
  }
  return false;
}

}  // namespace partet
