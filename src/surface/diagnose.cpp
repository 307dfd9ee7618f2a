// diagnose_surface: the checks in the order the header gives, each with a
// message that names the entities.
#include "surface/diagnose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/intersections.hpp"
#include "core/timer.hpp"
#include "surface/edge_table.hpp"
#include "surface/entity_text.hpp"
#include "surface/orientation.hpp"
#include "surface/self_intersections.hpp"

namespace partet {

namespace {

void check_finite(const SurfaceMesh& s, const std::string& file) {
  std::vector<std::string> cases;
  size_t count = 0;
  for (uint32_t v = 0; v < s.num_vertices(); ++v) {
    const double* p = s.point(v);
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) continue;
    if (count++ < kListedCases) cases.push_back(vertex_text(s, v));
  }
  if (count) throw InputError(case_list(file, count, "vertices have NaN or infinite coordinates:", cases));
}

size_t drop_unused_vertices(SurfaceMesh& s) {
  std::vector<uint32_t> renumber(s.num_vertices(), UINT32_MAX);
  for (uint32_t v : s.tris) renumber[v] = 0;
  uint32_t next = 0;
  for (uint32_t v = 0; v < renumber.size(); ++v) {
    if (renumber[v] == UINT32_MAX) continue;
    renumber[v] = next;
    for (int i = 0; i < 3; ++i) s.xyz[3 * size_t{next} + i] = s.xyz[3 * size_t{v} + i];
    ++next;
  }
  size_t dropped = s.num_vertices() - next;
  s.xyz.resize(3 * size_t{next});
  for (uint32_t& v : s.tris) v = renumber[v];
  return dropped;
}

void find_degenerate(const SurfaceMesh& s, std::vector<std::string>& problems, const std::string& file) {
  std::vector<std::string> cases;
  size_t count = 0;
  for (uint32_t t = 0; t < s.num_triangles(); ++t) {
    const uint32_t* v = &s.tris[3 * size_t{t}];
    bool bad = v[0] == v[1] || v[1] == v[2] || v[2] == v[0] ||
               points_collinear(s.point(v[0]), s.point(v[1]), s.point(v[2]));
    if (bad && count++ < kListedCases) cases.push_back(triangle_text(s, t));
  }
  if (count)
    problems.push_back(case_list(file, count, "degenerate triangles (repeated or exactly collinear vertices):", cases));
}

void find_duplicates(const SurfaceMesh& s, std::vector<std::string>& problems, const std::string& file) {
  const uint32_t nt = static_cast<uint32_t>(s.num_triangles());
  std::vector<std::array<uint32_t, 4>> keyed(nt);
  for (uint32_t t = 0; t < nt; ++t) {
    std::array<uint32_t, 3> v{s.tris[3 * size_t{t}], s.tris[3 * size_t{t} + 1], s.tris[3 * size_t{t} + 2]};
    std::sort(v.begin(), v.end());
    keyed[t] = {v[0], v[1], v[2], t};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::string> cases;
  size_t count = 0;
  for (uint32_t i = 1; i < nt; ++i) {
    if (keyed[i][0] != keyed[i - 1][0] || keyed[i][1] != keyed[i - 1][1] || keyed[i][2] != keyed[i - 1][2]) continue;
    if (count++ < kListedCases)
      cases.push_back(triangle_text(s, keyed[i][3]) + " repeats triangle " + std::to_string(keyed[i - 1][3]));
  }
  if (count) problems.push_back(case_list(file, count, "duplicate triangles:", cases));
}

std::string edge_case(const SurfaceMesh& s, const EdgeTable& e, size_t edge) {
  uint32_t h = e.first_half_edge(edge);
  std::string text = "edge " + vertex_text(s, half_edge_from(s, h)) + " - " + vertex_text(s, half_edge_to(s, h)) +
                     (e.edge_size(edge) == 1 ? " of triangle" : " of triangles");
  for (uint32_t i = e.edge_start[edge]; i < e.edge_start[edge + 1] && i < e.edge_start[edge] + 4; ++i)
    text += (i == e.edge_start[edge] ? " " : ", ") + std::to_string(e.half_edges[i] / 3);
  if (e.edge_size(edge) > 4) text += ", ...";
  return text;
}

void find_bad_edges(const SurfaceMesh& s, const EdgeTable& e, std::vector<std::string>& problems,
                    const std::string& file) {
  std::vector<std::string> open_cases, multi_cases;
  size_t open = 0, multi = 0;
  for (size_t edge = 0; edge < e.num_edges(); ++edge) {
    uint32_t n = e.edge_size(edge);
    if (n == 1 && open++ < kListedCases) open_cases.push_back(edge_case(s, e, edge));
    if (n > 2 && multi++ < kListedCases) multi_cases.push_back(edge_case(s, e, edge));
  }
  if (open)
    problems.push_back(case_list(file, open, "open edges (used by one triangle only): the surface has holes and "
                                 "must be closed:", open_cases));
  if (multi)
    problems.push_back(case_list(file, multi, "non-manifold edges (used by more than two triangles); surfaces "
                                 "of several regions sharing internal faces are not supported yet:", multi_cases));
}

// Union-find over triangle corners (3t+k): corners at one vertex joined across
// the manifold edges around it; a vertex with more than one class is pinched.
uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void find_pinched_vertices(const SurfaceMesh& s, const EdgeTable& e, std::vector<std::string>& problems,
                           const std::string& file) {
  const size_t nc = s.tris.size();
  std::vector<uint32_t> parent(nc);
  std::iota(parent.begin(), parent.end(), 0u);
  auto corner_of = [&](uint32_t t, uint32_t v) {
    for (uint32_t k = 0; k < 3; ++k)
      if (s.tris[3 * t + k] == v) return 3 * t + k;
    return UINT32_MAX;
  };
  for (uint32_t h = 0; h < nc; ++h) {
    uint32_t g = e.twin[h];
    if (g == EdgeTable::kNone || g < h) continue;
    for (uint32_t v : {half_edge_from(s, h), half_edge_to(s, h)}) {
      uint32_t a = find_root(parent, corner_of(h / 3, v)), b = find_root(parent, corner_of(g / 3, v));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<uint32_t> fans(s.num_vertices(), 0);
  for (uint32_t c = 0; c < nc; ++c)
    if (find_root(parent, c) == c) ++fans[s.tris[c]];
  std::vector<std::string> cases;
  size_t count = 0;
  for (uint32_t v = 0; v < fans.size(); ++v)
    if (fans[v] > 1 && count++ < kListedCases)
      cases.push_back(vertex_text(s, v) + " joins " + std::to_string(fans[v]) + " separate fans of triangles");
  if (count)
    problems.push_back(case_list(file, count, "non-manifold vertices (where separate sheets of the surface touch):",
                                 cases));
}

void find_self_intersecting(const SurfaceMesh& s, std::vector<std::string>& problems, const std::string& file) {
  constexpr size_t kLimit = 1000;
  std::vector<TrianglePair> pairs = find_self_intersections(s, kLimit);
  if (pairs.empty()) return;
  std::vector<std::string> cases;
  for (size_t i = 0; i < pairs.size() && i < kListedCases; ++i)
    cases.push_back(triangle_text(s, pairs[i].a) + " meets " + triangle_text(s, pairs[i].b));
  std::string what = pairs.size() >= kLimit ? "or more pairs of intersecting triangles (the surface intersects itself):"
                                            : "pairs of intersecting triangles (the surface intersects itself):";
  problems.push_back(case_list(file, pairs.size(), what, cases));
}

}  // namespace

SurfaceSummary diagnose_surface(SurfaceMesh& s, const std::string& file,
                                const std::function<void(double)>& progress) {
  auto done = [&](double fraction) {
    if (progress) progress(fraction);
  };
  SurfaceSummary sum;
  if (s.num_triangles() == 0) throw InputError(file + ": the surface has no triangles");
  check_finite(s, file);
  sum.unused_vertices = drop_unused_vertices(s);
  if (sum.unused_vertices) sum.notes.push_back(std::to_string(sum.unused_vertices) + " unused vertices dropped");

  // Every problem found is reported together; each check runs when its
  // preconditions hold (pinched vertices need manifold edges, the
  // intersection test needs non-degenerate, distinct triangles).
  std::vector<std::string> problems;
  find_degenerate(s, problems, file);
  done(0.1);
  find_duplicates(s, problems, file);
  done(0.2);
  const bool triangles_sound = problems.empty();
  EdgeTable edges = build_edge_table(s);
  find_bad_edges(s, edges, problems, file);
  done(0.3);
  if (problems.empty()) find_pinched_vertices(s, edges, problems, file);
  done(0.4);
  if (triangles_sound) {
    Stopwatch watch;
    find_self_intersecting(s, problems, file);
    sum.seconds_self_intersections = watch.wall();
  }
  done(0.9);
  if (!problems.empty()) {
    std::string msg = problems[0];
    for (size_t i = 1; i < problems.size(); ++i) msg += "\n" + problems[i];
    throw InputError(msg);
  }

  ShellInfo shells = orient_shells(s, edges, file);
  sum.vertices = s.num_vertices();
  sum.triangles = s.num_triangles();
  sum.edges = edges.num_edges();
  sum.shells = shells.count;
  sum.reoriented = shells.reoriented;
  for (uint32_t sh = 0; sh < shells.count; ++sh) {
    sum.volume += shells.volume[sh];  // cavities count negative
    if (shells.depth[sh] % 2 == 1) ++sum.cavities;
  }
  if (sum.reoriented)
    sum.notes.push_back("reoriented " + std::to_string(sum.reoriented) + " of " + std::to_string(sum.triangles) +
                        " triangles (their orientation was inconsistent or inward)");
  for (int i = 0; i < 3; ++i) {
    sum.bbox[i] = HUGE_VAL;
    sum.bbox[3 + i] = -HUGE_VAL;
  }
  for (size_t v = 0; v < s.num_vertices(); ++v)
    for (int i = 0; i < 3; ++i) {
      sum.bbox[i] = std::min(sum.bbox[i], s.xyz[3 * v + i]);
      sum.bbox[3 + i] = std::max(sum.bbox[3 + i], s.xyz[3 * v + i]);
    }
  return sum;
}

}  // namespace partet
