// tet_quality (see tet_quality.hpp): four face normals, six squared edge
// lengths, one square root.
#include "optimize/tet_quality.hpp"

#include <algorithm>

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

}  // namespace partet
