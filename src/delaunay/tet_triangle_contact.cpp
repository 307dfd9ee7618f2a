// Tet-triangle contact beyond shared vertices (see tet_triangle_contact.hpp).
#include "delaunay/tet_triangle_contact.hpp"

#include "core/intersections.hpp"
#include "core/predicates.hpp"

namespace partet {
namespace {

constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

bool point_in_tet(const double* const k[4], const double* p) {
  for (const auto& f : kFace)
    if (orient3d(k[f[0]], k[f[1]], k[f[2]], p) > 0) return false;
  return true;
}

// The closed segment pq meets the closed tet.
bool segment_meets_tet(const double* const k[4], const double* p, const double* q) {
  if (point_in_tet(k, p) || point_in_tet(k, q)) return true;
  for (const auto& f : kFace)
    if (segment_triangle_intersect(p, q, k[f[0]], k[f[1]], k[f[2]])) return true;
  return false;
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
    for (const auto& e : kEdge)
      if (segment_triangle_intersect(tet[e[0]], tet[e[1]], tri[0], tri[1], tri[2])) return true;
    for (int j = 0; j < 3; ++j)
      if (segment_meets_tet(tet, tri[j], tri[(j + 1) % 3])) return true;
    return false;
  }
  if (shared == 1) {
    int j = 0;
    while (in_tet[j] < 0) ++j;
    const int* f = kFace[in_tet[j]];
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
