// principal_axes: per slot bounding box (exact min/max), 20-bit coordinates
// in it, weighted first and second moments accumulated in 128-bit integers
// and summed over the ranks as 32-bit limbs (each limb sum fits an int64 for
// any rank count below 2^31), then the covariance and its Jacobi eigenvector.
#include "partition/inertia.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace partet {
namespace {

using u128 = unsigned __int128;

constexpr double kLevels = double((1 << 20) - 1);  // quantised coordinates in [0, 2^20 - 1]
constexpr int kLimbs = 4;                          // 4 x 32 bits hold a 128-bit moment
constexpr int kMoments = 9;                        // x, y, z, xx, yy, zz, xy, xz, yz
constexpr size_t kWords = 1 + kMoments * kLimbs;   // weight sum, then the moments' limbs

// The matrix index pairs of the second moments, in cov[] order after x, y, z.
constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

long double to_long_double(u128 v) {
  return static_cast<long double>(static_cast<uint64_t>(v >> 64)) * 18446744073709551616.0L +
         static_cast<long double>(static_cast<uint64_t>(v));
}

// Bounding boxes per slot: {min x, min y, min z, -max x, -max y, -max z}.
std::vector<double> slot_boxes(const Comm& comm, const double* xyz, const int32_t* slot, size_t n, size_t slots) {
  std::vector<double> box(slots * 6, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; ++i) {
    if (slot[i] < 0) continue;
    double* b = &box[static_cast<size_t>(slot[i]) * 6];
    for (int k = 0; k < 3; ++k) {
      b[k] = std::min(b[k], xyz[3 * i + k]);
      b[3 + k] = std::min(b[3 + k], -xyz[3 * i + k]);
    }
  }
  comm.min(box.data(), box.size());
  return box;
}

}  // namespace

bool principal_axis_of_covariance(const double cov[6], double axis[3]) {
  double a[3][3] = {{cov[0], cov[3], cov[4]}, {cov[3], cov[1], cov[5]}, {cov[4], cov[5], cov[2]}};
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    if (a[0][1] == 0 && a[0][2] == 0 && a[1][2] == 0) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0) continue;
        double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a = a J: columns p and q
          double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a = J^T a: rows p and q
          double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        a[p][q] = a[q][p] = 0;
        for (int k = 0; k < 3; ++k) {  // v = v J
          double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (a[k][k] > a[best][best]) best = k;
  if (!(a[best][best] > 0)) {
    axis[0] = axis[1] = axis[2] = 0;
    return false;
  }
  double norm = std::sqrt(v[0][best] * v[0][best] + v[1][best] * v[1][best] + v[2][best] * v[2][best]);
  for (int k = 0; k < 3; ++k) axis[k] = v[k][best] / norm;
  double sign = axis[closest_coordinate_axis(axis)] < 0 ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k) axis[k] = axis[k] * sign + 0.0;  // + 0.0: no negative zeros
  return true;
}

int closest_coordinate_axis(const double axis[3]) {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(axis[k]) > std::fabs(axis[best])) best = k;
  return best;
}

InertiaAxes principal_axes(const Comm& comm, const double* xyz, const uint64_t* weight, const int32_t* slot,
                           size_t n, size_t slots) {
  std::vector<double> box = slot_boxes(comm, xyz, slot, n, slots);
  std::vector<double> extent(slots * 3, 0.0);
  for (size_t s = 0; s < slots; ++s)
    for (int k = 0; k < 3; ++k)
      if (box[s * 6 + k] <= -box[s * 6 + 3 + k]) extent[s * 3 + k] = -box[s * 6 + 3 + k] - box[s * 6 + k];

  std::vector<uint64_t> weight_sum(slots, 0);
  std::vector<u128> moment(slots * kMoments, 0);
  for (size_t i = 0; i < n; ++i) {
    if (slot[i] < 0) continue;
    size_t s = static_cast<size_t>(slot[i]);
    u128 q[3];
    for (int k = 0; k < 3; ++k) {
      double e = extent[s * 3 + k];
      double t = e > 0 ? (xyz[3 * i + k] - box[s * 6 + k]) / e : 0.0;
      q[k] = static_cast<u128>(std::llround(std::clamp(t, 0.0, 1.0) * kLevels));
    }
    u128 w = weight[i];
    weight_sum[s] += weight[i];
    u128* m = &moment[s * kMoments];
    for (int k = 0; k < 3; ++k) m[k] += w * q[k];
    for (int j = 0; j < 6; ++j) m[3 + j] += w * q[kPairs[j][0]] * q[kPairs[j][1]];
  }

  std::vector<int64_t> words(slots * kWords, 0);
  for (size_t s = 0; s < slots; ++s) {
    int64_t* w = &words[s * kWords];
    w[0] = static_cast<int64_t>(weight_sum[s]);
    for (int j = 0; j < kMoments; ++j)
      for (int l = 0; l < kLimbs; ++l)
        w[1 + j * kLimbs + l] = static_cast<int64_t>(static_cast<uint64_t>(moment[s * kMoments + j] >> (32 * l)) &
                                                     0xffffffffu);
  }
  comm.sum(words.data(), words.size());

  InertiaAxes out;
  out.axis.assign(slots * 3, 0.0);
  out.valid.assign(slots, 0);
  for (size_t s = 0; s < slots; ++s) {
    const int64_t* w = &words[s * kWords];
    if (w[0] == 0) continue;
    long double total = static_cast<long double>(w[0]);
    long double mean[kMoments];
    for (int j = 0; j < kMoments; ++j) {
      u128 v = 0;
      for (int l = 0; l < kLimbs; ++l) v += static_cast<u128>(static_cast<uint64_t>(w[1 + j * kLimbs + l])) << (32 * l);
      mean[j] = to_long_double(v) / total;
    }
    // Covariance in quantised units, then scaled back to coordinates.
    double cov[6];
    for (int j = 0; j < 6; ++j) {
      int a = kPairs[j][0], b = kPairs[j][1];
      long double c = mean[3 + j] - mean[a] * mean[b];
      long double scale = static_cast<long double>(extent[s * 3 + a]) * extent[s * 3 + b] / (kLevels * kLevels);
      cov[j] = static_cast<double>(c * scale);
    }
    out.valid[s] = principal_axis_of_covariance(cov, &out.axis[s * 3]) ? 1 : 0;
  }
  return out;
}

}  // namespace partet
