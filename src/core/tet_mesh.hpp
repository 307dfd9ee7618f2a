// A tetrahedral mesh (or one rank's part of it) as flat arrays.
// Tets are 4 vertex indices, positively oriented: orient3d(v0,v1,v2,v3) > 0.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet {

// The face of a tet opposite its local vertex f, as the local vertices
// kOutwardFace[f]: for a positive tet the face's normal (b-a)x(c-a) points
// away from the tet.
inline constexpr int kOutwardFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct TetMesh {
  std::vector<double> xyz;           // 3 coordinates per vertex
  std::vector<uint32_t> tets;        // 4 vertex indices per tet
  std::vector<uint32_t> tris;        // 3 vertex indices per boundary triangle (may be empty)
  std::vector<uint64_t> global_ids;  // one per vertex on distributed parts, else empty

  size_t num_vertices() const { return xyz.size() / 3; }
  size_t num_tets() const { return tets.size() / 4; }
  size_t num_triangles() const { return tris.size() / 3; }
  const double* point(size_t v) const { return &xyz[3 * v]; }
};

}  // namespace partet
