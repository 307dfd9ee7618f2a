// Shape quality of a tet mesh: dihedral angles, radius ratio, edge ratio and
// volume, gathered in one flat pass over the tets. Quality measures the
// shape of each tet regardless of its orientation (orientation is the
// validator's concern); `volume` is signed, so inverted tets subtract.
// Tets with an out-of-range vertex index or a non-finite coordinate are not
// measured (`tets` counts the measured ones); degenerate tets measure radius
// ratio 0 and dihedral angles 0 and 180, never NaN. An empty mesh gives zeros.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>
#include <nlohmann/json.hpp>

#include "core/tet_mesh.hpp"

namespace partet {

struct QualityStats {
  size_t tets = 0;              // tets measured
  double min_dihedral_deg = 0;  // over all tets
  double max_dihedral_deg = 0;
  double radius_ratio_min = 0;  // 3 * inradius / circumradius: 1 for the regular tet
  double radius_ratio_mean = 0;
  double radius_ratio_p01 = 0;  // 1st percentile
  size_t dihedral_under_5 = 0;  // tets having at least one dihedral angle under 5 degrees
  size_t dihedral_under_10 = 0;
  size_t dihedral_under_20 = 0;
  double edge_ratio_max = 0;  // worst longest/shortest edge within a tet (inf for a zero edge)
  double edge_ratio_mean = 0;
  double volume = 0;  // sum of signed tet volumes, compensated summation
};

// Shape quality of one tet, the per-tet part of measure_quality.
struct TetShape {
  double min_dihedral_rad;
  double max_dihedral_rad;
  double radius_ratio;
  double edge_ratio;
  double volume;  // signed: positive when orient3d(p0, p1, p2, p3) > 0
};
TetShape tet_shape(const double* p0, const double* p1, const double* p2, const double* p3);
// tet_shape's min_dihedral_rad alone.
double tet_min_dihedral(const double* p0, const double* p1, const double* p2, const double* p3);
// The faces opposite p_k and p_l (k < l) that meet at the tet's largest
// dihedral angle, as tet_shape finds it; their shared edge joins the other
// two vertices. False when a face has zero area.
bool widest_dihedral_faces(const double* p0, const double* p1, const double* p2, const double* p3, int& k,
                           int& l);
// tet_shape's radius_ratio alone (3 inradius / circumradius; 1 for the
// regular tet, 0 for a flat one), without the angles.
double tet_radius_ratio(const double* p0, const double* p1, const double* p2, const double* p3);

QualityStats measure_quality(const TetMesh& mesh);

// Per tet of a mesh whose tets all index its vertices: 1 when it has a
// dihedral angle under `degrees` or a face of zero area (tet_shape's
// smallest angle under `degrees`, found from its cosine, as
// measure_quality counts them), else 0.
std::vector<uint8_t> tets_under_angle(const TetMesh& mesh, double degrees);

// x is at least as good as y in the three measures the optimizer serves
// (smallest dihedral angle, share of tets under 10 degrees, mean radius
// ratio, this last up to kRadiusRatioSlack below y's) and better in one;
// false when either measured no tet. The slack lets a mesh with a larger
// smallest angle win over one whose mean radius ratio is a hair higher
// (the icosahedron refined once: its cone, 58.3 degrees and 0.756, over
// the optimized front's 33.9 degrees and 0.761).
inline constexpr double kRadiusRatioSlack = 0.01;
bool better_quality(const QualityStats& x, const QualityStats& y);

// Non-finite values (an infinite edge ratio) are written as null.
void to_json(nlohmann::json& j, const QualityStats& q);

}  // namespace partet
