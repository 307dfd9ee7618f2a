// The tet kernels (see tet_kernels.hpp): tet_quality.cpp's, check/quality.cpp's
// (TetFrame, radius_ratio_of) and predicates.hpp's orient3d filter, per tet.
#include "optimize/tet_kernels.hpp"

#include <cmath>

#include "core/predicates.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {

void tet_qualities(const TetColumns& p, size_t n, double* __restrict out) {
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
  for (size_t k = 0; k < n; ++k) {
    // a = p1 - p0, b = p2 - p0, c = p3 - p0, e = p2 - p1, f = p3 - p1, g = p3 - p2.
    const double ax = x1[k] - x0[k], ay = y1[k] - y0[k], az = z1[k] - z0[k];
    const double bx = x2[k] - x0[k], by = y2[k] - y0[k], bz = z2[k] - z0[k];
    const double cx = x3[k] - x0[k], cy = y3[k] - y0[k], cz = z3[k] - z0[k];
    const double ex = x2[k] - x1[k], ey = y2[k] - y1[k], ez = z2[k] - z1[k];
    const double fx = x3[k] - x1[k], fy = y3[k] - y1[k], fz = z3[k] - z1[k];
    const double gx = x3[k] - x2[k], gy = y3[k] - y2[k], gz = z3[k] - z2[k];
    // n0 = f x e, n1 = b x c, n2 = c x a, n3 = a x b.
    const double n0x = fy * ez - fz * ey, n0y = fz * ex - fx * ez, n0z = fx * ey - fy * ex;
    const double n1x = by * cz - bz * cy, n1y = bz * cx - bx * cz, n1z = bx * cy - by * cx;
    const double n2x = cy * az - cz * ay, n2y = cz * ax - cx * az, n2z = cx * ay - cy * ax;
    const double n3x = ay * bz - az * by, n3y = az * bx - ax * bz, n3z = ax * by - ay * bx;
    const double d = ax * n1x + ay * n1y + az * n1z;
    const double m0 = n0x * n0x + n0y * n0y + n0z * n0z;
    const double m1 = n1x * n1x + n1y * n1y + n1z * n1z;
    const double m2 = n2x * n2x + n2y * n2y + n2z * n2z;
    const double m3 = n3x * n3x + n3y * n3y + n3z * n3z;
    const double r0 = (ax * ax + ay * ay + az * az) / (m2 * m3);
    const double r1 = (bx * bx + by * by + bz * bz) / (m1 * m3);
    const double r2 = (cx * cx + cy * cy + cz * cz) / (m1 * m2);
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
    out[k] = faces ? kRegularSineScale * d * std::sqrt(pick) : 0.0;
  }
}

void tet_radius_ratios(const TetColumns& p, size_t n, double* __restrict out) {
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
  for (size_t k = 0; k < n; ++k) {
    const double ax = x1[k] - x0[k], ay = y1[k] - y0[k], az = z1[k] - z0[k];
    const double bx = x2[k] - x0[k], by = y2[k] - y0[k], bz = z2[k] - z0[k];
    const double cx = x3[k] - x0[k], cy = y3[k] - y0[k], cz = z3[k] - z0[k];
    // n0 = (c - a) x (b - a), from the differences as TetFrame has it.
    const double ux = cx - ax, uy = cy - ay, uz = cz - az;
    const double wx = bx - ax, wy = by - ay, wz = bz - az;
    const double n0x = uy * wz - uz * wy, n0y = uz * wx - ux * wz, n0z = ux * wy - uy * wx;
    const double n1x = by * cz - bz * cy, n1y = bz * cx - bx * cz, n1z = bx * cy - by * cx;
    const double n2x = cy * az - cz * ay, n2y = cz * ax - cx * az, n2z = cx * ay - cy * ax;
    const double n3x = ay * bz - az * by, n3y = az * bx - ax * bz, n3z = ax * by - ay * bx;
    const double l0 = std::sqrt(n0x * n0x + n0y * n0y + n0z * n0z);
    const double l1 = std::sqrt(n1x * n1x + n1y * n1y + n1z * n1z);
    const double l2 = std::sqrt(n2x * n2x + n2y * n2y + n2z * n2z);
    const double l3 = std::sqrt(n3x * n3x + n3y * n3y + n3z * n3z);
    const double d = ax * n1x + ay * n1y + az * n1z;
    const double area_sum = l0 + l1 + l2 + l3;
    const double aa = ax * ax + ay * ay + az * az;
    const double bb = bx * bx + by * by + bz * bz;
    const double cc = cx * cx + cy * cy + cz * cz;
    const double ix = bb * n2x + cc * n3x, iy = bb * n2y + cc * n3y, iz = bb * n2z + cc * n3z;
    const double sx = aa * n1x + ix, sy = aa * n1y + iy, sz = aa * n1z + iz;
    const double denominator = area_sum * std::sqrt(sx * sx + sy * sy + sz * sz);
    const double ratio = 6 * d * d / denominator;
    out[k] = (d != 0 && denominator > 0) ? (ratio < 1.0 ? ratio : 1.0) : 0.0;
  }
}

void orient3d_filters(const TetColumns& p, size_t n, double* __restrict out) {
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
  for (size_t k = 0; k < n; ++k) {
    const double ux = x1[k] - x0[k], uy = y1[k] - y0[k], uz = z1[k] - z0[k];
    const double vx = x2[k] - x0[k], vy = y2[k] - y0[k], vz = z2[k] - z0[k];
    const double wx = x3[k] - x0[k], wy = y3[k] - y0[k], wz = z3[k] - z0[k];
    const double p1 = vy * wz, p2 = vz * wy;
    const double p3 = vz * wx, p4 = vx * wz;
    const double p5 = vx * wy, p6 = vy * wx;
    const double det = (ux * (p1 - p2) + uy * (p3 - p4)) + uz * (p5 - p6);
    const double aux = std::fabs(ux), auy = std::fabs(uy), auz = std::fabs(uz);
    const double permanent = (aux * (std::fabs(p1) + std::fabs(p2)) + auy * (std::fabs(p3) + std::fabs(p4))) +
                             auz * (std::fabs(p5) + std::fabs(p6));
    const double bound =
        detail::kOrient3dBound * permanent + (aux + auy + auz + 1) * detail::kUnderflowSlack;
    out[k] = det > bound ? 1.0 : (det < -bound ? -1.0 : 0.0);
  }
}

}  // namespace partet
