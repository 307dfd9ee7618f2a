// The tet kernels (see tet_kernels.hpp): tet_quality.cpp's, check/quality.cpp's
// (TetFrame, radius_ratio_of) and predicates.hpp's orient3d filter, per tet.
#include "optimize/tet_kernels.hpp"

#include <array>
#include <cmath>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

// o_j[k] = measure(the twelve coordinates of tet k's corners)[j], in one
// loop over the columns (the measures are inlined into it).
template <size_t N, class Measure>
void each_tet(const TetColumns& p, size_t n, Measure measure, double* __restrict o0, double* __restrict o1 = nullptr,
              double* __restrict o2 = nullptr, double* __restrict o3 = nullptr) {
  const double* __restrict x0 = p.c[0];
  const double* __restrict y0 = p.c[1];
  const double* __restrict z0 = p.c[2];
  const double* __restrict x1 = p.c[3];
  const double* __restrict y1 = p.c[4];
  const double* __restrict z1 = p.c[5];
  const double* __restrict x2 = p.c[6];
  const double* __restrict y2 = p.c[7];
  const double* __restrict z2 = p.c[8];
  const double* __restrict x3 = p.c[9];
  const double* __restrict y3 = p.c[10];
  const double* __restrict z3 = p.c[11];
  static_assert(N >= 1 && N <= 4, "one to four values per tet");
  for (size_t k = 0; k < n; ++k) {
    const std::array<double, N> values =
        measure(x0[k], y0[k], z0[k], x1[k], y1[k], z1[k], x2[k], y2[k], z2[k], x3[k], y3[k], z3[k]);
    o0[k] = values[0];
    if constexpr (N > 1) o1[k] = values[1];
    if constexpr (N > 2) o2[k] = values[2];
    if constexpr (N > 3) o3[k] = values[3];
  }
}

// From p0: a = p1 - p0, b = p2 - p0, c = p3 - p0, and the normals n1 = b x c,
// n2 = c x a, n3 = a x b of the faces opposite p1, p2, p3 (the set-up both
// measures share, in their own order of operations).
struct Frame {
  double ax, ay, az, bx, by, bz, cx, cy, cz;
  double n1x, n1y, n1z, n2x, n2y, n2z, n3x, n3y, n3z;
};
inline Frame frame(double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2, double z2,
                   double x3, double y3, double z3) {
  Frame f;
  f.ax = x1 - x0, f.ay = y1 - y0, f.az = z1 - z0;
  f.bx = x2 - x0, f.by = y2 - y0, f.bz = z2 - z0;
  f.cx = x3 - x0, f.cy = y3 - y0, f.cz = z3 - z0;
  f.n1x = f.by * f.cz - f.bz * f.cy, f.n1y = f.bz * f.cx - f.bx * f.cz, f.n1z = f.bx * f.cy - f.by * f.cx;
  f.n2x = f.cy * f.az - f.cz * f.ay, f.n2y = f.cz * f.ax - f.cx * f.az, f.n2z = f.cx * f.ay - f.cy * f.ax;
  f.n3x = f.ay * f.bz - f.az * f.by, f.n3y = f.az * f.bx - f.ax * f.bz, f.n3z = f.ax * f.by - f.ay * f.bx;
  return f;
}

}  // namespace

void tet_qualities(const TetColumns& p, size_t n, double* __restrict out) {
  const auto quality = [](double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                          double z2, double x3, double y3, double z3) {
    const Frame t = frame(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3);
    // e = p2 - p1, f = p3 - p1, g = p3 - p2; n0 = f x e.
    const double ex = x2 - x1, ey = y2 - y1, ez = z2 - z1;
    const double fx = x3 - x1, fy = y3 - y1, fz = z3 - z1;
    const double gx = x3 - x2, gy = y3 - y2, gz = z3 - z2;
    const double n0x = fy * ez - fz * ey, n0y = fz * ex - fx * ez, n0z = fx * ey - fy * ex;
    const double d = t.ax * t.n1x + t.ay * t.n1y + t.az * t.n1z;
    const double m0 = n0x * n0x + n0y * n0y + n0z * n0z;
    const double m1 = t.n1x * t.n1x + t.n1y * t.n1y + t.n1z * t.n1z;
    const double m2 = t.n2x * t.n2x + t.n2y * t.n2y + t.n2z * t.n2z;
    const double m3 = t.n3x * t.n3x + t.n3y * t.n3y + t.n3z * t.n3z;
    const double r0 = (t.ax * t.ax + t.ay * t.ay + t.az * t.az) / (m2 * m3);
    const double r1 = (t.bx * t.bx + t.by * t.by + t.bz * t.bz) / (m1 * m3);
    const double r2 = (t.cx * t.cx + t.cy * t.cy + t.cz * t.cz) / (m1 * m2);
    const double r3 = (ex * ex + ey * ey + ez * ez) / (m0 * m3);
    const double r4 = (fx * fx + fy * fy + fz * fz) / (m0 * m2);
    const double r5 = (gx * gx + gy * gy + gz * gz) / (m0 * m1);
    // std::min_element and std::max_element: the first extreme one.
    double low = r0, high = r0;
    low = r1 < low ? r1 : low;
    high = high < r1 ? r1 : high;
    low = r2 < low ? r2 : low;
    high = high < r2 ? r2 : high;
    low = r3 < low ? r3 : low;
    high = high < r3 ? r3 : high;
    low = r4 < low ? r4 : low;
    high = high < r4 ? r4 : high;
    low = r5 < low ? r5 : low;
    high = high < r5 ? r5 : high;
    const double pick = d >= 0 ? low : high;
    const bool faces = (m0 > 0) & (m1 > 0) & (m2 > 0) & (m3 > 0);
    return std::array<double, 1>{faces ? kRegularSineScale * d * std::sqrt(pick) : 0.0};
  };
  each_tet<1>(p, n, quality, out);
}

void tet_radius_ratios(const TetColumns& p, size_t n, double* __restrict out) {
  const auto radius_ratio = [](double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                               double z2, double x3, double y3, double z3) {
    const Frame t = frame(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3);
    // n0 = (c - a) x (b - a), from the differences as TetFrame has it.
    const double ux = t.cx - t.ax, uy = t.cy - t.ay, uz = t.cz - t.az;
    const double wx = t.bx - t.ax, wy = t.by - t.ay, wz = t.bz - t.az;
    const double n0x = uy * wz - uz * wy, n0y = uz * wx - ux * wz, n0z = ux * wy - uy * wx;
    const double l0 = std::sqrt(n0x * n0x + n0y * n0y + n0z * n0z);
    const double l1 = std::sqrt(t.n1x * t.n1x + t.n1y * t.n1y + t.n1z * t.n1z);
    const double l2 = std::sqrt(t.n2x * t.n2x + t.n2y * t.n2y + t.n2z * t.n2z);
    const double l3 = std::sqrt(t.n3x * t.n3x + t.n3y * t.n3y + t.n3z * t.n3z);
    const double d = t.ax * t.n1x + t.ay * t.n1y + t.az * t.n1z;
    const double area_sum = l0 + l1 + l2 + l3;
    const double aa = t.ax * t.ax + t.ay * t.ay + t.az * t.az;
    const double bb = t.bx * t.bx + t.by * t.by + t.bz * t.bz;
    const double cc = t.cx * t.cx + t.cy * t.cy + t.cz * t.cz;
    const double ix = bb * t.n2x + cc * t.n3x, iy = bb * t.n2y + cc * t.n3y, iz = bb * t.n2z + cc * t.n3z;
    const double sx = aa * t.n1x + ix, sy = aa * t.n1y + iy, sz = aa * t.n1z + iz;
    const double denominator = area_sum * std::sqrt(sx * sx + sy * sy + sz * sz);
    const double ratio = 6 * d * d / denominator;
    return std::array<double, 1>{(d != 0 && denominator > 0) ? (ratio < 1.0 ? ratio : 1.0) : 0.0};
  };
  each_tet<1>(p, n, radius_ratio, out);
}

void orient3d_filters(const TetColumns& p, size_t n, double* __restrict out) {
  const auto filter = [](double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                         double z2, double x3, double y3, double z3) {
    const double ux = x1 - x0, uy = y1 - y0, uz = z1 - z0;
    const double vx = x2 - x0, vy = y2 - y0, vz = z2 - z0;
    const double wx = x3 - x0, wy = y3 - y0, wz = z3 - z0;
    const double p1 = vy * wz, p2 = vz * wy;
    const double p3 = vz * wx, p4 = vx * wz;
    const double p5 = vx * wy, p6 = vy * wx;
    const double det = (ux * (p1 - p2) + uy * (p3 - p4)) + uz * (p5 - p6);
    const double aux = std::fabs(ux), auy = std::fabs(uy), auz = std::fabs(uz);
    const double permanent = (aux * (std::fabs(p1) + std::fabs(p2)) + auy * (std::fabs(p3) + std::fabs(p4))) +
                             auz * (std::fabs(p5) + std::fabs(p6));
    const double bound = detail::kOrient3dBound * permanent + (aux + auy + auz + 1) * detail::kUnderflowSlack;
    return std::array<double, 1>{det > bound ? 1.0 : (det < -bound ? -1.0 : 0.0)};
  };
  each_tet<1>(p, n, filter, out);
}

void circumcentre_terms(const TetColumns& p, size_t n, double* det, double* x, double* y, double* z) {
  const auto terms = [](double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                        double z2, double x3, double y3, double z3) {
    // e_j = p_{j+1} - p0; circumcentre - p0 = (|e0|^2 e1 x e2 + |e1|^2 e2 x e0 + |e2|^2 e0 x e1) / (2 det).
    const double ax = x1 - x0, ay = y1 - y0, az = z1 - z0;  // e0
    const double bx = x2 - x0, by = y2 - y0, bz = z2 - z0;  // e1
    const double cx = x3 - x0, cy = y3 - y0, cz = z3 - z0;  // e2
    const double ux = by * cz - bz * cy, uy = bz * cx - bx * cz, uz = bx * cy - by * cx;  // e1 x e2
    const double vx = cy * az - cz * ay, vy = cz * ax - cx * az, vz = cx * ay - cy * ax;  // e2 x e0
    const double wx = ay * bz - az * by, wy = az * bx - ax * bz, wz = ax * by - ay * bx;  // e0 x e1
    const double d = ax * ux + ay * uy + az * uz;
    const double la = ax * ax + ay * ay + az * az, lb = bx * bx + by * by + bz * bz, lc = cx * cx + cy * cy + cz * cz;
    std::array<double, 4> out{d, 0, 0, 0};
    out[1] = d * (x0 + (la * ux + lb * vx + lc * wx) / (2 * d));
    out[2] = d * (y0 + (la * uy + lb * vy + lc * wy) / (2 * d));
    out[3] = d * (z0 + (la * uz + lb * vz + lc * wz) / (2 * d));
    return out;
  };
  each_tet<4>(p, n, terms, det, x, y, z);
}

}  // namespace partet
