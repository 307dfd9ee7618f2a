// Tet-triangle contact beyond shared vertices (see tet_triangle_contact.hpp).
#include "delaunay/tet_triangle_contact.hpp"

#include "core/intersections.hpp"
#include "core/predicates.hpp"
#include "core/tet_mesh.hpp"

namespace partet {
namespace {

constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

bool point_in_tet(const double* const k[4], const double* p) {
  for (const auto& f : kOutwardFace)
    if (orient3d(k[f[0]], k[f[1]], k[f[2]], p) > 0) return false;
  return true;
}

// The closed segment pq meets the closed tet.
bool segment_meets_tet(const double* const k[4], const double* p, const double* q) {
  if (point_in_tet(k, p) || point_in_tet(k, q)) return true;
  for (const auto& f : kOutwardFace)
    if (segment_triangle_intersect(p, q, k[f[0]], k[f[1]], k[f[2]])) return true;
  return false;
}

// True when the points `p` (count n), other than those equal to `skip`,
// all lie strictly on the outer side of one of the tet's faces (the faces
// through `skip` only when skip is a tet vertex index, else all): then the
// triangle meets the tet at most in that vertex. A filter: false says
// nothing.
bool outside_one_face(const double* const k[4], const double* const* p, int n, int skip) {
  for (int f = 0; f < 4; ++f) {
    if (f == skip) continue;
    bool all = true;
    const int* face = kOutwardFace[f];
    for (int j = 0; j < n && all; ++j) all = orient3d(k[face[0]], k[face[1]], k[face[2]], p[j]) > 0;
    if (all) return true;
  }
  return false;
}

// True when the tet's vertices other than `skip` (-1: none) all lie
// strictly on one side of the triangle's plane.
bool one_side_of_plane(const double* const k[4], const double* const t[3], int skip) {
  int sides = 0;
  for (int m = 0; m < 4; ++m)
    if (m != skip) {
      const int o = orient3d(t[0], t[1], t[2], k[m]);
      if (o == 0) return false;
      sides |= o > 0 ? 1 : 2;
    }
  return sides != 3;
}

}  // namespace

bool tet_meets_triangle_beyond_shared(const double* const tet[4], const uint32_t tet_ids[4],
                                      const double* const tri[3], const uint32_t tri_ids[3]) {
  int in_tet[3] = {-1, -1, -1};  // per triangle vertex: its index in the tet, or -1
  int shared = 0;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 4; ++k)
      if (tri_ids[j] == tet_ids[k]) {
        in_tet[j] = k;
        ++shared;
      }
  if (shared == 3) return false;
  if (shared == 0) {
    if (outside_one_face(tet, tri, 3, -1) || one_side_of_plane(tet, tri, -1)) return false;
    for (const auto& e : kEdge)
      if (segment_triangle_intersect(tet[e[0]], tet[e[1]], tri[0], tri[1], tri[2])) return true;
    for (int j = 0; j < 3; ++j)
      if (segment_meets_tet(tet, tri[j], tri[(j + 1) % 3])) return true;
    return false;
  }
  if (shared == 1) {
    int j = 0;
    while (in_tet[j] < 0) ++j;
    const double* const others[2] = {tri[(j + 1) % 3], tri[(j + 2) % 3]};
    if (outside_one_face(tet, others, 2, in_tet[j]) || one_side_of_plane(tet, tri, in_tet[j])) return false;
    const int* f = kOutwardFace[in_tet[j]];
    const double* const opposite_face[3] = {tet[f[0]], tet[f[1]], tet[f[2]]};
    if (triangles_intersect(opposite_face, tri)) return true;
    return segment_meets_tet(tet, tri[(j + 1) % 3], tri[(j + 2) % 3]);
  }
  // Two shared: u, w in both; p the triangle's third vertex; q, r the tet's other two.
  int j = 0;
  while (in_tet[j] >= 0) ++j;
  const double* p = tri[j];
  const double* u = tri[(j + 1) % 3];
  const double* w = tri[(j + 2) % 3];
  const double* other[2];
  int m = 0;
  for (int k = 0; k < 4; ++k)
    if (k != in_tet[(j + 1) % 3] && k != in_tet[(j + 2) % 3]) other[m++] = tet[k];
  const double* q = other[0];
  const double* r = other[1];
  const int side_q = orient3d(u, w, q, r);  // nonzero: the tet is not flat
  const int side_r = -side_q;               // orient3d(u, w, r, q)
  return orient3d(u, w, q, p) * side_q >= 0 && orient3d(u, w, r, p) * side_r >= 0;
}

}  // namespace partet
