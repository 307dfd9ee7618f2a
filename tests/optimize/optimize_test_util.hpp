// Helpers for the optimizer tests: small positive meshes built from vertex
// lists, the boundary faces of a mesh as canonical oriented triples, and the
// worst tet quality.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include "core/predicates.hpp"
#include "core/tet_mesh.hpp"
#include "optimize/tet_quality.hpp"

namespace partet::test {

// Appends tet (a, b, c, d), swapping c and d if needed to make it positive.
inline void add_positive_tet(TetMesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  if (orient3d(m.point(a), m.point(b), m.point(c), m.point(d)) < 0) std::swap(c, d);
  m.tets.insert(m.tets.end(), {a, b, c, d});
}

// Faces of exactly one tet, outward, rotated so the smallest index comes
// first, sorted: equal lists mean the same boundary, same sides.
inline std::vector<std::array<uint32_t, 3>> boundary_faces(const TetMesh& m) {
  static constexpr int kOut[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<uint32_t, 3>, std::vector<std::array<uint32_t, 3>>> by_key;
  for (size_t t = 0; t < m.num_tets(); ++t) {
    for (int f = 0; f < 4; ++f) {
      std::array<uint32_t, 3> face;
      for (int k = 0; k < 3; ++k) face[k] = m.tets[4 * t + kOut[f][k]];
      std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
      std::array<uint32_t, 3> key = face;
      std::sort(key.begin(), key.end());
      by_key[key].push_back(face);
    }
  }
  std::vector<std::array<uint32_t, 3>> out;
  for (const auto& [key, faces] : by_key)
    if (faces.size() == 1) out.push_back(faces[0]);
  std::sort(out.begin(), out.end());
  return out;
}

// The cube [0, cells]^3 as cells^3 unit cubes, each split into the 6 Kuhn
// tets around its (0,0,0)-(1,1,1) diagonal (they match across cubes), all
// positive; vertex (x, y, z) has index x + (cells + 1) (y + (cells + 1) z).
inline TetMesh kuhn_lattice(int cells) {
  TetMesh m;
  const int n = cells + 1;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) m.xyz.insert(m.xyz.end(), {double(x), double(y), double(z)});
  auto id = [n](const int* c) { return static_cast<uint32_t>(c[0] + n * (c[1] + n * c[2])); };
  constexpr int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int z = 0; z < cells; ++z)
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x)
        for (const auto& path : kPaths) {
          int c[3] = {x, y, z};
          uint32_t v[4];
          v[0] = id(c);
          for (int k = 0; k < 3; ++k) {
            ++c[path[k]];
            v[k + 1] = id(c);
          }
          add_positive_tet(m, v[0], v[1], v[2], v[3]);
        }
  return m;
}

inline double worst_quality(const TetMesh& m) {
  double worst = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    worst = std::min(worst, tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
  }
  return worst;
}

inline bool all_positive(const TetMesh& m) {
  for (size_t t = 0; t < m.num_tets(); ++t) {
    const uint32_t* v = &m.tets[4 * t];
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) <= 0) return false;
  }
  return true;
}

}  // namespace partet::test
