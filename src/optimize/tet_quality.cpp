// tet_quality and its gradient (see tet_quality.hpp): four face normals,
// six squared edge lengths, one square root; the gradient differentiates
// q = K d |e| / sqrt(m_a m_b) for the edge e that gives q. tet_quality
// keeps its own straight-line copy of the shared set-up: through a common
// helper the optimizer's topology and smoothing steps ran 45 % slower (femur).
#include "optimize/tet_quality.hpp"

#include <algorithm>

#include "optimize/tet_edges.hpp"

namespace partet {
namespace {

struct V3 {
  double x, y, z;
};
V3 sub(const double* p, const double* q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
V3 cross(V3 u, V3 v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double dot(V3 u, V3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
V3 scaled(V3 u, double s) { return {u.x * s, u.y * s, u.z * s}; }
V3 plus(V3 u, V3 v) { return {u.x + v.x, u.y + v.y, u.z + v.z}; }


}  // namespace

double tet_quality(const double* p0, const double* p1, const double* p2, const double* p3) {
  const V3 a = sub(p1, p0), b = sub(p2, p0), c = sub(p3, p0);
  const V3 bma = sub(p2, p1), cma = sub(p3, p1), cmb = sub(p3, p2);
  // n_k: normal of the face opposite p_k.
  const V3 n0 = cross(cma, bma), n1 = cross(b, c), n2 = cross(c, a), n3 = cross(a, b);
  const double d = dot(a, n1);  // 6 V, signed
  const double m0 = dot(n0, n0), m1 = dot(n1, n1), m2 = dot(n2, n2), m3 = dot(n3, n3);
  if (!(m0 > 0 && m1 > 0 && m2 > 0 && m3 > 0)) return 0;
  // Squared sine / D^2 per edge; edge ij lies on the faces opposite the two
  // other vertices k, l.
  const double ratios[6] = {
      dot(a, a) / (m2 * m3),      // edge 01: faces 2, 3
      dot(b, b) / (m1 * m3),      // edge 02: faces 1, 3
      dot(c, c) / (m1 * m2),      // edge 03: faces 1, 2
      dot(bma, bma) / (m0 * m3),  // edge 12: faces 0, 3
      dot(cma, cma) / (m0 * m2),  // edge 13: faces 0, 2
      dot(cmb, cmb) / (m0 * m1),  // edge 23: faces 0, 1
  };
  const double pick = d >= 0 ? *std::min_element(ratios, ratios + 6) : *std::max_element(ratios, ratios + 6);
  return kRegularSineScale * d * std::sqrt(pick);
}

double tet_quality_gradient(const double* const p[4], int j, double gradient[3]) {
  const V3 a = sub(p[1], p[0]), b = sub(p[2], p[0]), c = sub(p[3], p[0]);
  const V3 bma = sub(p[2], p[1]), cma = sub(p[3], p[1]), cmb = sub(p[3], p[2]);
  const V3 n[4] = {cross(cma, bma), cross(b, c), cross(c, a), cross(a, b)};
  const double d = dot(a, n[1]);
  const double m[4] = {dot(n[0], n[0]), dot(n[1], n[1]), dot(n[2], n[2]), dot(n[3], n[3])};
  gradient[0] = gradient[1] = gradient[2] = 0;
  if (!(m[0] > 0 && m[1] > 0 && m[2] > 0 && m[3] > 0)) return 0;
  const V3 edges[6] = {a, b, c, bma, cma, cmb};
  int pick = 0;
  double ratio = 0;
  for (int e = 0; e < 6; ++e) {
    const double r = dot(edges[e], edges[e]) / (m[kTetEdgeFaces[e][0]] * m[kTetEdgeFaces[e][1]]);
    if (e == 0 || (d >= 0 ? r < ratio : r > ratio)) {
      ratio = r;
      pick = e;
    }
  }
  const double root = std::sqrt(ratio);
  const double q = kRegularSineScale * d * root;
  // d(6V)/dp_j: the normal of the face opposite p_j, towards p_j.
  const V3 grad_d = j == 0 ? scaled(plus(plus(n[1], n[2]), n[3]), -1) : n[j];
  V3 log_grad = {0, 0, 0};  // d(ln |e| - ln m_a / 2 - ln m_b / 2)/dp_j
  const int u = kTetEdges[pick][0], w = kTetEdges[pick][1];
  if (u == j || w == j) {
    const V3 e = sub(p[j], p[u == j ? w : u]);
    log_grad = scaled(e, 1 / dot(e, e));
  }
  for (int f : kTetEdgeFaces[pick]) {
    if (f == j) continue;  // the face opposite p_j does not move
    // Face f's other two vertices y, z: m = |(y - x) x (z - x)|^2 has
    // gradient 2 (y - z) x n in x = p_j, n = (y - x) x (z - x).
    int y = -1, z = -1;
    for (int i = 0; i < 4; ++i)
      if (i != f && i != j) (y < 0 ? y : z) = i;
    const V3 face_normal = cross(sub(p[y], p[j]), sub(p[z], p[j]));
    log_grad = plus(log_grad, scaled(cross(sub(p[y], p[z]), face_normal), -1 / m[f]));
  }
  const V3 g = plus(scaled(grad_d, kRegularSineScale * root), scaled(log_grad, q));
  gradient[0] = g.x;
  gradient[1] = g.y;
  gradient[2] = g.z;
  return q;
}

}  // namespace partet
