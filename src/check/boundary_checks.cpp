// Checks on the boundary faces (see boundary_checks.hpp).
// Against a surface: surface vertices go into a flat open-addressing hash
// keyed by their exact coordinates; each boundary face's vertices are looked
// up there, giving the face as a triple of surface vertex ids. Boundary
// faces and surface triangles are then both keyed by their sorted triple
// plus the parity of the permutation that sorts it (the orientation),
// sorted, and merged.
// Closedness: every boundary face contributes its three directed edges;
// sorting them on the undirected edge packed in 64 bits groups each edge's
// uses, and a closed boundary uses each edge equally often both ways.
#include "check/boundary_checks.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <tuple>

#include "check/compensated_sum.hpp"
#include "check/problem_log.hpp"
#include "check/tet_faces.hpp"
#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "core/point_text.hpp"

namespace partet {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

// -0.0 and 0.0 compare equal, so they must hash alike.
uint64_t coordinate_bits(double x) { return std::bit_cast<uint64_t>(x == 0 ? 0.0 : x); }

// Surface vertices by exact coordinates; the first vertex at a position
// stands for all vertices there.
class PointIndex {
 public:
  explicit PointIndex(const SurfaceMesh& s) : s_(s) {
    size_t size = 16;
    while (size < 2 * s.num_vertices()) size *= 2;
    slots_.assign(size, kNone);
    canonical_.resize(s.num_vertices());
    for (uint32_t v = 0; v < s.num_vertices(); ++v) {
      size_t slot = probe(s.point(v));
      if (slots_[slot] == kNone) slots_[slot] = v;
      canonical_[v] = slots_[slot];
    }
  }
  uint32_t find(const double* p) const { return slots_[probe(p)]; }
  uint32_t canonical(uint32_t v) const { return canonical_[v]; }

 private:
  // The slot holding p's position, or the empty slot where it would go.
  size_t probe(const double* p) const {
    uint64_t h =
        hash_mix(hash_mix(hash_mix(coordinate_bits(p[0])) ^ coordinate_bits(p[1])) ^ coordinate_bits(p[2]));
    size_t mask = slots_.size() - 1;
    for (size_t slot = h & mask;; slot = (slot + 1) & mask) {
      uint32_t v = slots_[slot];
      if (v == kNone) return slot;
      const double* q = s_.point(v);
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) return slot;
    }
  }

  const SurfaceMesh& s_;
  std::vector<uint32_t> slots_;
  std::vector<uint32_t> canonical_;
};

// A triangle as its sorted vertex triple and orientation.
struct Keyed {
  uint32_t v[3];
  uint32_t odd;    // 1 when sorting the oriented triple took an odd permutation
  uint32_t index;  // boundary face list index, or surface triangle id
  bool operator<(const Keyed& o) const {
    return std::tie(v[0], v[1], v[2], odd, index) <
           std::tie(o.v[0], o.v[1], o.v[2], o.odd, o.index);
  }
  bool same_triple(const Keyed& o) const {
    return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2];
  }
};

int compare_triples(const Keyed& a, const Keyed& b) {
  auto ta = std::tie(a.v[0], a.v[1], a.v[2]), tb = std::tie(b.v[0], b.v[1], b.v[2]);
  return ta < tb ? -1 : tb < ta ? 1 : 0;
}

Keyed keyed(const uint32_t t[3], uint32_t index) {
  Keyed k{{t[0], t[1], t[2]}, 0, index};
  k.odd = (t[0] > t[1]) + (t[0] > t[2]) + (t[1] > t[2]);
  k.odd %= 2;
  std::sort(k.v, k.v + 3);
  return k;
}

void require_indices_in_range(const SurfaceMesh& s) {
  for (uint32_t v : s.tris)
    if (v >= s.num_vertices())
      throw InputError("surface triangle vertex " + std::to_string(v) + " is out of range (" +
                       std::to_string(s.num_vertices()) + " vertices)");
}

std::string surface_triangle_text(const SurfaceMesh& s, uint32_t t) {
  const uint32_t* v = &s.tris[3 * t];
  std::string text = "surface triangle " + std::to_string(t) + " [" + std::to_string(v[0]) + " " +
                     std::to_string(v[1]) + " " + std::to_string(v[2]) + "]";
  for (int i = 0; i < 3; ++i) text += " " + point_text(s.point(v[i]));
  return text;
}

class Matcher {
 public:
  Matcher(const TetMesh& mesh, const std::vector<uint32_t>& boundary, const SurfaceMesh& surface)
      : mesh_(mesh), boundary_(boundary), surface_(surface) {}

  void boundary_unmatched(uint32_t i) {
    if (not_surface_.note()) not_surface_.describe(face_text(i));
  }
  void surface_unmatched(uint32_t t) {
    if (uncovered_.note()) uncovered_.describe(surface_triangle_text(surface_, t));
  }
  // One triple's boundary faces and surface triangles, each sorted with the
  // even orientation first: pair equal orientations, then opposite ones.
  void match_run(const Keyed* b, size_t nb, const Keyed* s, size_t ns) {
    used_.assign(nb, 0);
    left_.clear();
    for (size_t j = 0; j < ns; ++j) {
      size_t i = 0;
      while (i < nb && (used_[i] || b[i].odd != s[j].odd)) ++i;
      if (i < nb)
        used_[i] = 1;
      else
        left_.push_back(static_cast<uint32_t>(j));
    }
    for (uint32_t j : left_) {
      size_t i = 0;
      while (i < nb && used_[i]) ++i;
      if (i < nb) {
        used_[i] = 1;
        if (reversed_.note())
          reversed_.describe(face_text(b[i].index) + " against " +
                             surface_triangle_text(surface_, s[j].index));
      } else {
        surface_unmatched(s[j].index);
      }
    }
    for (size_t i = 0; i < nb; ++i)
      if (!used_[i]) boundary_unmatched(b[i].index);
  }
  void report(std::vector<std::string>& problems) const {
    not_surface_.report(problems);
    uncovered_.report(problems);
    reversed_.report(problems);
  }

 private:
  std::string face_text(uint32_t i) const {
    uint32_t v[3];
    outward_face(mesh_, boundary_[i], v);
    const uint32_t* t = &mesh_.tets[boundary_[i] - boundary_[i] % 4];
    return "face " + triangle_text(mesh_, v) + " of tet " + std::to_string(boundary_[i] / 4) +
           " [" + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
           " " + std::to_string(t[3]) + "]";
  }

  const TetMesh& mesh_;
  const std::vector<uint32_t>& boundary_;
  const SurfaceMesh& surface_;
  std::vector<char> used_;      // per boundary face of the current run
  std::vector<uint32_t> left_;  // surface triangles of the run without an equal orientation
  ProblemKind not_surface_{"boundary faces are not surface triangles"};
  ProblemKind uncovered_{"surface triangles are not boundary faces"};
  ProblemKind reversed_{"boundary faces have the wrong orientation (reversed surface triangles)"};
};

struct EdgeUse {
  uint64_t key;       // smaller vertex << 32 | larger vertex
  uint32_t face;      // index into the boundary face list
  uint32_t reversed;  // 1 when the face runs from the larger vertex to the smaller
  bool operator<(const EdgeUse& o) const {
    return key != o.key ? key < o.key : face != o.face ? face < o.face : reversed < o.reversed;
  }
};

std::string edge_text(const TetMesh& mesh, uint64_t key, size_t forward, size_t backward,
                      uint32_t face_code) {
  uint32_t u = static_cast<uint32_t>(key >> 32), v = static_cast<uint32_t>(key);
  return "edge " + mesh_vertex_text(mesh, u) + " - " + mesh_vertex_text(mesh, v) + " used " +
         std::to_string(forward) + " times from " + std::to_string(u) + " to " + std::to_string(v) +
         " and " + std::to_string(backward) + " times back, e.g. by " +
         tet_text(mesh, face_code / 4);
}

}  // namespace

void match_boundary_to_surface(const TetMesh& mesh, const std::vector<uint32_t>& boundary,
                               const SurfaceMesh& surface, std::vector<std::string>& problems) {
  require_indices_in_range(surface);
  PointIndex index(surface);
  Matcher matcher(mesh, boundary, surface);

  std::vector<Keyed> faces;
  faces.reserve(boundary.size());
  for (uint32_t i = 0; i < boundary.size(); ++i) {
    uint32_t v[3];
    outward_face(mesh, boundary[i], v);
    for (uint32_t& x : v) x = index.find(mesh.point(x));
    if (v[0] == kNone || v[1] == kNone || v[2] == kNone)
      matcher.boundary_unmatched(i);
    else
      faces.push_back(keyed(v, i));
  }
  std::vector<Keyed> tris;
  tris.reserve(surface.num_triangles());
  for (uint32_t t = 0; t < surface.num_triangles(); ++t) {
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) v[k] = index.canonical(surface.tris[3 * t + k]);
    tris.push_back(keyed(v, t));
  }
  std::sort(faces.begin(), faces.end());
  std::sort(tris.begin(), tris.end());

  // Merge on the triple: each step takes one triple's faces and triangles.
  size_t i = 0, j = 0;
  while (i < faces.size() || j < tris.size()) {
    int order = i == faces.size() ? 1 : j == tris.size() ? -1 : compare_triples(faces[i], tris[j]);
    size_t ie = i, je = j;
    if (order <= 0)
      while (ie < faces.size() && faces[ie].same_triple(faces[i])) ++ie;
    if (order >= 0)
      while (je < tris.size() && tris[je].same_triple(tris[j])) ++je;
    matcher.match_run(faces.data() + i, ie - i, tris.data() + j, je - j);
    i = ie;
    j = je;
  }
  matcher.report(problems);
}

void check_boundary_closed(const TetMesh& mesh, const std::vector<uint32_t>& boundary,
                           std::vector<std::string>& problems, std::vector<std::string>& warnings) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * boundary.size());
  for (uint32_t i = 0; i < boundary.size(); ++i) {
    uint32_t v[3];
    outward_face(mesh, boundary[i], v);
    for (int k = 0; k < 3; ++k) {
      uint32_t from = v[k], to = v[(k + 1) % 3];
      uint32_t lo = std::min(from, to), hi = std::max(from, to);
      uses.push_back({(uint64_t{lo} << 32) | hi, i, from > to ? 1u : 0u});
    }
  }
  std::sort(uses.begin(), uses.end());

  ProblemKind open(
      "boundary edges are open (not used equally often in both directions by "
      "boundary faces)");
  ProblemKind non_manifold(
      "boundary edges are non-manifold (closed, but used by more than two "
      "boundary faces)");
  size_t j = 0;
  for (size_t i = 0; i < uses.size(); i = j) {
    size_t backward = 0;
    for (j = i; j < uses.size() && uses[j].key == uses[i].key; ++j) backward += uses[j].reversed;
    size_t forward = j - i - backward;
    ProblemKind* kind = forward != backward ? &open : forward > 1 ? &non_manifold : nullptr;
    if (kind && kind->note())
      kind->describe(edge_text(mesh, uses[i].key, forward, backward, boundary[uses[i].face]));
  }
  open.report(problems);
  non_manifold.report(warnings);
}

double enclosed_volume(const SurfaceMesh& surface) {
  require_indices_in_range(surface);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t v = 0; v < surface.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], surface.point(v)[k]);
      hi[k] = std::max(hi[k], surface.point(v)[k]);
    }
  double o[3];
  for (int k = 0; k < 3; ++k) o[k] = lo[k] <= hi[k] ? 0.5 * (lo[k] + hi[k]) : 0.0;
  CompensatedSum sum;
  for (size_t t = 0; t < surface.num_triangles(); ++t) {
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = surface.point(surface.tris[3 * t + k]);
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) a[k] = p[0][k] - o[k], b[k] = p[1][k] - o[k], c[k] = p[2][k] - o[k];
    sum.add((a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
             a[2] * (b[0] * c[1] - b[1] * c[0])) /
            6);
  }
  return sum.value();
}

}  // namespace partet
