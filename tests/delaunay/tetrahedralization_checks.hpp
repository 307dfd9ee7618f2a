// Checks shared by the Delaunay and edge-recovery tests: every tet of a
// DelaunayTets positive by exact orient3d, neighbours reciprocal over the
// same three vertices, four faces on the enclosing tet's boundary and the
// enclosing tet's volume filled.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

#include "core/predicates.hpp"
#include "delaunay/delaunay.hpp"

namespace partet {

// Six times tet t's signed volume.
inline double volume6(const DelaunayTets& d, size_t t) {
  const uint32_t* v = &d.tets[4 * t];
  const double* p[4];
  for (int k = 0; k < 4; ++k) p[k] = &d.xyz[3 * size_t{v[k]}];
  return orient3d_value(p[0], p[1], p[2], p[3]);
}

inline void expect_tetrahedralization(const DelaunayTets& d) {
  const size_t n = d.num_points;
  ASSERT_EQ(d.xyz.size(), 3 * (n + 4));
  double total = 0;
  size_t outer_faces = 0;
  for (size_t t = 0; t < d.num_tets(); ++t) {
    const uint32_t* v = &d.tets[4 * t];
    const double* p[4];
    for (int k = 0; k < 4; ++k) p[k] = &d.xyz[3 * size_t{v[k]}];
    ASSERT_GT(orient3d(p[0], p[1], p[2], p[3]), 0) << "tet " << t;
    total += volume6(d, t);
    for (int i = 0; i < 4; ++i) {
      const uint32_t across = d.neighbours[4 * t + i];
      if (across == kNoNeighbour) {
        ++outer_faces;
        continue;
      }
      ASSERT_EQ(d.neighbours[across], 4 * t + i);
      const uint32_t* w = &d.tets[4 * size_t{across / 4}];
      for (int k = 0; k < 4; ++k) {
        if (k == i) continue;
        bool found = false;
        for (int m = 0; m < 4; ++m) found |= m != static_cast<int>(across % 4) && w[m] == v[k];
        EXPECT_TRUE(found) << "tet " << t << " face " << i;
      }
    }
  }
  EXPECT_EQ(outer_faces, 4u);
  const double* c[4];
  for (int k = 0; k < 4; ++k) c[k] = &d.xyz[3 * (n + k)];
  const double whole = orient3d_value(c[0], c[1], c[2], c[3]);
  EXPECT_NEAR(total, whole, 1e-9 * whole);
}

}  // namespace partet
