// The validator (see validate.hpp): per-vertex and per-tet checks here, face
// matching in tet_faces.cpp, boundary checks in boundary_checks.cpp, then
// the report as JSON or text.
#include "check/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "check/boundary_checks.hpp"
#include "check/problem_log.hpp"
#include "check/tet_faces.hpp"
#include "core/predicates.hpp"

namespace partet {
namespace {

// Why a relative volume tolerance is sound. Once the boundary faces are
// exactly the surface's triangles and the two tets at every interior face
// lie on opposite sides of it, the number of tets covering a point is
// constant across every face, so it is one integer k inside the surface:
// the tet volume is k times the enclosed volume. A wrong mesh (overlapping
// layers, k >= 2) is off by a relative 1 or more, while rounding only
// perturbs each tet and triangle term by a few ulps of its size and the
// compensated sums add about one ulp: relative errors near 1e-15 for any
// sane mesh, far below 1e-9.
constexpr double kVolumeTolerance = 1e-9;

bool finite_point(const double* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

std::string number_text(double x, const char* format = "%.17g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// Range, finiteness and orientation of each tet; marks used vertices.
std::vector<TetState> classify_tets(const TetMesh& mesh, const std::vector<char>& finite,
                                    std::vector<char>& used, std::vector<std::string>& problems) {
  ProblemKind out_of_range("tets have a vertex index out of range (" +
                           std::to_string(mesh.num_vertices()) + " vertices)");
  ProblemKind inverted("tets are inverted (orient3d < 0)");
  ProblemKind flat("tets are degenerate (zero volume, orient3d = 0)");
  const size_t num_vertices = mesh.num_vertices();
  std::vector<TetState> state(mesh.num_tets());
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    if (v[0] >= num_vertices || v[1] >= num_vertices || v[2] >= num_vertices ||
        v[3] >= num_vertices) {
      state[t] = TetState::kOutOfRange;
      if (out_of_range.note()) out_of_range.describe(tet_text(mesh, t));
      continue;
    }
    for (int k = 0; k < 4; ++k) used[v[k]] = 1;
    if (!finite[v[0]] || !finite[v[1]] || !finite[v[2]] || !finite[v[3]]) {
      state[t] = TetState::kNonFinite;
      continue;
    }
    int sign = orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
    state[t] = sign > 0 ? TetState::kPositive : sign < 0 ? TetState::kNegative : TetState::kFlat;
    ProblemKind* kind = sign < 0 ? &inverted : sign == 0 ? &flat : nullptr;
    if (kind && kind->note()) kind->describe(tet_text(mesh, t));
  }
  out_of_range.report(problems);
  inverted.report(problems);
  flat.report(problems);
  return state;
}

}  // namespace

ValidationResult validate_mesh(const TetMesh& mesh, const SurfaceMesh* surface) {
  ValidationResult r;
  r.vertices = mesh.num_vertices();
  r.tets = mesh.num_tets();

  std::vector<char> finite(r.vertices);
  ProblemKind non_finite("vertices have a NaN or infinite coordinate");
  for (size_t v = 0; v < r.vertices; ++v) {
    finite[v] = finite_point(mesh.point(v));
    if (!finite[v] && non_finite.note())
      non_finite.describe(mesh_vertex_text(mesh, static_cast<uint32_t>(v)));
  }
  non_finite.report(r.problems);

  std::vector<char> used(r.vertices, 0);
  std::vector<TetState> state = classify_tets(mesh, finite, used, r.problems);

  FaceProblems face_problems;
  FaceMatch faces = match_tet_faces(mesh, state, face_problems);
  face_problems.crowded.report(r.problems);
  face_problems.same_side.report(r.problems);
  face_problems.duplicate.report(r.problems);
  r.interior_faces = faces.interior;
  r.boundary_faces = faces.boundary.size();

  r.quality = measure_quality(mesh);
  r.tet_volume = r.quality.volume;
  if (surface) {
    match_boundary_to_surface(mesh, faces.boundary, *surface, r.problems);
    r.surface_volume = enclosed_volume(*surface);
    double difference = std::fabs(r.tet_volume - *r.surface_volume);
    double scale = std::max(std::fabs(r.tet_volume), std::fabs(*r.surface_volume));
    if (!(difference <= kVolumeTolerance * scale))
      r.problems.push_back("tet volume " + number_text(r.tet_volume) +
                           " differs from the surface's enclosed volume " +
                           number_text(*r.surface_volume) + " (relative difference " +
                           number_text(difference / scale, "%.3g") + ")");
  } else {
    check_boundary_closed(mesh, faces.boundary, r.problems, r.warnings);
  }

  ProblemKind unused("vertices are not used by any tet");
  for (size_t v = 0; v < r.vertices; ++v)
    if (!used[v] && unused.note())
      unused.describe(mesh_vertex_text(mesh, static_cast<uint32_t>(v)));
  r.unused_vertices = unused.count();
  unused.report(r.warnings);

  r.valid = r.problems.empty();
  return r;
}

void to_json(nlohmann::json& j, const ValidationResult& r) {
  j = nlohmann::json{
      {"valid", r.valid},
      {"problems", r.problems},
      {"warnings", r.warnings},
      {"vertices", r.vertices},
      {"tets", r.tets},
      {"interior_faces", r.interior_faces},
      {"boundary_faces", r.boundary_faces},
      {"unused_vertices", r.unused_vertices},
      {"tet_volume", std::isfinite(r.tet_volume) ? nlohmann::json(r.tet_volume) : nlohmann::json()},
      {"surface_volume", nlohmann::json()},
      {"quality", r.quality}};
  if (r.surface_volume && std::isfinite(*r.surface_volume)) j["surface_volume"] = *r.surface_volume;
}

std::string format_text(const ValidationResult& r) {
  std::string text =
      r.valid ? "VALID" : "INVALID (" + std::to_string(r.problems.size()) + " kinds of problem)";
  text += "\n";
  char line[256];
  auto row = [&](const char* label, const std::string& value) {
    std::snprintf(line, sizeof line, "  %-16s %s\n", label, value.c_str());
    text += line;
  };
  row("vertices",
      std::to_string(r.vertices) + " (" + std::to_string(r.unused_vertices) + " unused)");
  row("tets", std::to_string(r.tets));
  row("interior faces", std::to_string(r.interior_faces));
  row("boundary faces", std::to_string(r.boundary_faces));
  row("tet volume", number_text(r.tet_volume, "%.15g"));
  if (r.surface_volume) row("surface volume", number_text(*r.surface_volume, "%.15g"));
  for (const std::string& p : r.problems) text += "problem: " + p + "\n";
  for (const std::string& w : r.warnings) text += "warning: " + w + "\n";

  const QualityStats& q = r.quality;
  text += "quality (" + std::to_string(q.tets) + " tets)\n";
  auto g = [](double x) { return number_text(x, "%.4g"); };
  row("dihedral angle",
      "min " + g(q.min_dihedral_deg) + "  max " + g(q.max_dihedral_deg) + " degrees");
  row("radius ratio", "min " + g(q.radius_ratio_min) + "  mean " + g(q.radius_ratio_mean) +
                          "  1st percentile " + g(q.radius_ratio_p01));
  row("small dihedral", "tets with an angle under 5: " + std::to_string(q.dihedral_under_5) +
                            "  under 10: " + std::to_string(q.dihedral_under_10) +
                            "  under 20: " + std::to_string(q.dihedral_under_20));
  row("edge ratio", "max " + g(q.edge_ratio_max) + "  mean " + g(q.edge_ratio_mean));
  return text;
}

}  // namespace partet
