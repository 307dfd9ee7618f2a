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

// The linear program of the file comment for moving `vertices` along
// `normal` (`region`: the tets of their stars): maximise c.x subject to
// a x <= b, x >= 0, with x the up and down parts of each displacement,
// then t. `now`: the smallest quotient before the move. False when a tet
// of the region is not positive in doubles or has no sine scale.
struct SheetProgram {
  std::vector<double> a, b, c;
  double now = 0;
};

bool sheet_program(const TetTopology& topo, const std::vector<uint32_t>& vertices,
                   const std::vector<uint32_t>& region, const double normal[3], SheetProgram& lp) {
  const size_t k = vertices.size(), r = region.size(), columns = 2 * k + 1, rows = r + 2 * k + 1;
  lp.a.assign(rows * columns, 0.0);
  lp.b.assign(rows, 0.0);
  lp.c.assign(columns, 0.0);
  lp.c[2 * k] = 1;  // maximise t
  std::vector<double> edge_sum(k, 0.0);
  std::vector<int> edge_count(k, 0);
  for (size_t i = 0; i < r; ++i) {
    const uint32_t* t = topo.tet(region[i]);
    const double* p[4] = {topo.point(t[0]), topo.point(t[1]), topo.point(t[2]), topo.point(t[3])};
    const double scale = sine_scale(p);
    const double now_i = orient3d_value(p[0], p[1], p[2], p[3]);
    if (!(now_i > 0) || !std::isfinite(scale)) return false;
    lp.b[i] = now_i / scale;
    lp.now = i == 0 ? lp.b[i] : std::min(lp.now, lp.b[i]);
    double* row = &lp.a[i * columns];
    row[2 * k] = 1;
    for (int j = 0; j < 4; ++j) {
      const auto it = std::find(vertices.begin(), vertices.end(), t[j]);
      if (it == vertices.end()) continue;
      const auto s = static_cast<size_t>(it - vertices.begin());
      for (int l = 0; l < 4; ++l)
        if (l != j) {
          edge_sum[s] += distance(p[j], p[l]);
          ++edge_count[s];
        }
      const double moved[3] = {p[j][0] + normal[0], p[j][1] + normal[1], p[j][2] + normal[2]};
      const double* q[4] = {p[0], p[1], p[2], p[3]};
      q[j] = moved;
      const double gain = (orient3d_value(q[0], q[1], q[2], q[3]) - now_i) / scale;
      row[2 * s] -= gain;
      row[2 * s + 1] += gain;
    }
  }
  for (size_t s = 0; s < k; ++s) {
    const double reach = edge_count[s] > 0 ? kMaxMove * edge_sum[s] / edge_count[s] : 0;
    lp.a[(r + 2 * s) * columns + 2 * s] = 1;
    lp.b[r + 2 * s] = reach;
    lp.a[(r + 2 * s + 1) * columns + 2 * s + 1] = 1;
    lp.b[r + 2 * s + 1] = reach;
  }
  lp.a[(rows - 1) * columns + 2 * k] = 1;
  lp.b[rows - 1] = 1;  // t is a sine
  return true;
}

// Moves each of `vertices` by its `shift` along `normal`, else by half or
// a quarter of it, kept as lift_sheet keeps a move; true if kept, else the
// vertices are back where they were.
bool try_shifts(TetTopology& topo, const std::vector<uint32_t>& vertices, const std::vector<uint32_t>& region,
                const double normal[3], const std::vector<double>& shift) {
  std::vector<uint32_t> quads;
  topo.tet_vertices(region, quads);
  const AngleSummary before = summarize_angles(topo, quads);
  const size_t k = vertices.size();
  std::vector<double> old_positions(3 * k);
  for (size_t s = 0; s < k; ++s) std::copy_n(topo.point(vertices[s]), 3, &old_positions[3 * s]);
  for (const double fraction : kFractions) {
    for (size_t s = 0; s < k; ++s) {
      const double* old = &old_positions[3 * s];
      const double step = fraction * shift[s];
      const double x[3] = {old[0] + step * normal[0], old[1] + step * normal[1], old[2] + step * normal[2]};
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

}  // namespace

bool lift_sheet(TetTopology& topo, uint32_t worst, const std::vector<uint8_t>& frozen) {
  const double flat = quality_of_angle(kSheetAngle);
  const double worst_quality = topo.quality(worst);
  if (!(worst_quality < flat)) return false;
  std::vector<uint32_t> vertices, region;
  tied_vertices(topo, worst, frozen, flat - worst_quality, kMaxVertices, vertices);
  double normal[3] = {0, 0, 0};
  if (vertices.empty() || !largest_face_normal(topo, worst, normal)) return false;
  joint_region(topo, vertices, region);
  SheetProgram program;
  if (!sheet_program(topo, vertices, region, normal, program)) return false;
  const LpResult lp = maximise_lp(program.a, program.b, program.c);
  if (lp.status != LpStatus::kOptimal || !(lp.objective > program.now)) return false;
  std::vector<double> shift(vertices.size());
  for (size_t s = 0; s < shift.size(); ++s) shift[s] = lp.x[2 * s] - lp.x[2 * s + 1];
  return try_shifts(topo, vertices, region, normal, shift);
}

}  // namespace partet
