// lift_sheet (see sheet_lift.hpp): the linear program's rows are the tets
// around the sheet (t minus the gain of their determinant over their sine
// scale at most that quotient now), then the bounds on the displacements,
// each split into an upward and a downward part so that zero is feasible.
#include "optimize/sheet_lift.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/linear_program.hpp"
#include "core/predicates.hpp"
#include "optimize/insertion.hpp"
#include "optimize/joint_smoothing.hpp"
#include "optimize/tet_quality.hpp"

namespace partet {
namespace {

constexpr size_t kMaxVertices = 64;
constexpr double kMaxMove = 0.5;  // longest displacement, in mean edge lengths at the vertex
constexpr double kFractions[] = {1.0, 0.5, 0.25};

double distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The cross product of two edges of the face of tet p opposite corner f
// (its normal, as long as twice its area).
void face_cross(const double* const p[4], int f, double c[3]) {
  const double* q[3] = {nullptr, nullptr, nullptr};
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != f) q[n++] = p[k];
  const double u[3] = {q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]};
  const double w[3] = {q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2]};
  c[0] = u[1] * w[2] - u[2] * w[1];
  c[1] = u[2] * w[0] - u[0] * w[2];
  c[2] = u[0] * w[1] - u[1] * w[0];
}

double norm(const double c[3]) { return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]); }

// The unit normal of the largest face of tet t; false when every face has
// no area in doubles.
bool largest_face_normal(const TetTopology& topo, uint32_t t, double normal[3]) {
  const uint32_t* v = topo.tet(t);
  const double* p[4] = {topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3])};
  double largest = 0;
  std::fill_n(normal, 3, 0.0);
  for (int f = 0; f < 4; ++f) {
    double c[3];
    face_cross(p, f, c);
    if (norm(c) > largest) {
      largest = norm(c);
      std::copy_n(c, 3, normal);
    }
  }
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  for (int i = 0; i < 3; ++i) normal[i] /= largest;
  return true;
}

// D / sine_scale(p), D = orient3d_value(p) (six times the volume), is the
// smallest sine of p's dihedral angles: the angle at edge e between faces
// i and j has sine D l_e / (4 A_i A_j) (l_e its length, A the areas).
// Infinity when a face or an edge has no size in doubles.
double sine_scale(const double* const p[4]) {
  double area[4];
  for (int f = 0; f < 4; ++f) {
    double c[3];
    face_cross(p, f, c);
    area[f] = norm(c) / 2;
  }
  double scale = 0;
  for (int j = 0; j < 4; ++j)
    for (int l = j + 1; l < 4; ++l) {
      // The faces at edge jl are those opposite the other two corners.
      int other[2] = {0, 0}, n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != j && k != l) other[n++] = k;
      const double length = distance(p[j], p[l]);
      if (!(length > 0)) return std::numeric_limits<double>::infinity();
      scale = std::max(scale, 4 * area[other[0]] * area[other[1]] / length);
    }
  return scale > 0 ? scale : std::numeric_limits<double>::infinity();
}

bool all_positive(const TetTopology& topo, const std::vector<uint32_t>& region) {
  for (uint32_t t : region) {
    const uint32_t* v = topo.tet(t);
    if (orient3d(topo.point(v[0]), topo.point(v[1]), topo.point(v[2]), topo.point(v[3])) <= 0) return false;
  }
  return true;
}

}  // namespace

bool lift_sheet(TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen) {
  const double flat = quality_of_angle(kSheetAngle);
  const double worst_quality = topo.quality(worst);
  if (!(worst_quality < flat)) return false;
  std::vector<uint32_t> vertices, region, quads;
  tied_vertices(topo, worst, frozen, flat - worst_quality, kMaxVertices, vertices);
  double normal[3] = {0, 0, 0};
  if (vertices.empty() || !largest_face_normal(topo, worst, normal)) return false;
  joint_region(topo, vertices, region);

  const size_t k = vertices.size(), r = region.size(), columns = 2 * k + 1, rows = r + 2 * k + 1;
  std::vector<double> a(rows * columns, 0.0), b(rows, 0.0), c(columns, 0.0);
  std::vector<double> edge_sum(k, 0.0);
  std::vector<int> edge_count(k, 0);
  c[2 * k] = 1;  // maximise t
  double now = 0;  // the smallest scaled determinant before the move
  for (size_t i = 0; i < r; ++i) {
    const uint32_t* t = topo.tet(region[i]);
    const double* p[4] = {topo.point(t[0]), topo.point(t[1]), topo.point(t[2]), topo.point(t[3])};
    int slot[4];
    for (int j = 0; j < 4; ++j) {
      const auto it = std::find(vertices.begin(), vertices.end(), t[j]);
      slot[j] = it == vertices.end() ? -1 : static_cast<int>(it - vertices.begin());
    }
    for (int j = 0; j < 4; ++j) {
      if (slot[j] < 0) continue;
      for (int l = 0; l < 4; ++l)
        if (l != j) {
          edge_sum[static_cast<size_t>(slot[j])] += distance(p[j], p[l]);
          ++edge_count[static_cast<size_t>(slot[j])];
        }
    }
    const double scale = sine_scale(p);
    const double now_i = orient3d_value(p[0], p[1], p[2], p[3]);
    if (!(now_i > 0) || !std::isfinite(scale)) return false;
    b[i] = now_i / scale;
    now = i == 0 ? b[i] : std::min(now, b[i]);
    double* row = &a[i * columns];
    row[2 * k] = 1;
    for (int j = 0; j < 4; ++j) {
      if (slot[j] < 0) continue;
      const double moved[3] = {p[j][0] + normal[0], p[j][1] + normal[1], p[j][2] + normal[2]};
      const double* q[4] = {p[0], p[1], p[2], p[3]};
      q[j] = moved;
      const double gain = (orient3d_value(q[0], q[1], q[2], q[3]) - now_i) / scale;
      row[2 * static_cast<size_t>(slot[j])] -= gain;
      row[2 * static_cast<size_t>(slot[j]) + 1] += gain;
    }
  }
  for (size_t s = 0; s < k; ++s) {
    const double reach = edge_count[s] > 0 ? kMaxMove * edge_sum[s] / edge_count[s] : 0;
    a[(r + 2 * s) * columns + 2 * s] = 1;
    b[r + 2 * s] = reach;
    a[(r + 2 * s + 1) * columns + 2 * s + 1] = 1;
    b[r + 2 * s + 1] = reach;
  }
  a[(rows - 1) * columns + 2 * k] = 1;
  b[rows - 1] = 1;  // t is a sine
  const LpResult lp = maximise_lp(a, b, c);
  if (lp.status != LpStatus::kOptimal || !(lp.objective > now)) return false;

  topo.tet_vertices(region, quads);
  const AngleSummary before = summarize_angles(topo, quads);
  std::vector<double> old_positions(3 * k);
  for (size_t s = 0; s < k; ++s) std::copy_n(topo.point(vertices[s]), 3, &old_positions[3 * s]);
  for (const double fraction : kFractions) {
    for (size_t s = 0; s < k; ++s) {
      const double shift = fraction * (lp.x[2 * s] - lp.x[2 * s + 1]);
      const double* old = &old_positions[3 * s];
      const double x[3] = {old[0] + shift * normal[0], old[1] + shift * normal[1], old[2] + shift * normal[2]};
      topo.move_vertex(vertices[s], x);
    }
    if (all_positive(topo, region)) {
      const AngleSummary after = summarize_angles(topo, quads);
      if (after.smallest > before.smallest && after.slivers <= before.slivers) return true;
    }
  }
  for (size_t s = 0; s < k; ++s) topo.move_vertex(vertices[s], &old_positions[3 * s]);
  return false;
}

}  // namespace partet
