// The face rule's table (face_rule.hpp): every case tiles its face with
// outward triangles over the right points, the diagonal joins the face's
// (even, even) corner to its (odd, odd) corner, and the shapes of all the
// template tets, which are the same at every level: the worst dihedral
// angle of the templates is 45 degrees, exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "check/quality.hpp"
#include "templates/face_rule.hpp"

namespace partet {
namespace {

void point_t(int p, int* t) {
  t[0] = p % 3;
  t[1] = p / 3 % 3;
  t[2] = p / 9;
}

TEST(TemplatesFaceRule, EveryCaseTilesItsFaceOutward) {
  for (int f = 0; f < kLeafFaces; ++f) {
    const int axis = face_axis(f);
    const int outward = face_side(f) ? 1 : -1;
    for (int c = 0; c < kFaceCases; ++c) {
      const FaceTriangulation& tri = face_triangulation(f, c);
      EXPECT_EQ(tri.count, c < kDiagonalCase ? 4 + __builtin_popcount(c) : 2) << f << " " << c;
      int area2 = 0;  // twice the area, in lattice units squared
      std::set<int> points;
      for (int k = 0; k < tri.count; ++k) {
        int t[3][3];
        for (int m = 0; m < 3; ++m) {
          point_t(tri.tri[k].p[m], t[m]);
          EXPECT_EQ(t[m][axis], 2 * face_side(f)) << "point off face " << f;
          points.insert(tri.tri[k].p[m]);
        }
        int a[3], b[3];
        for (int m = 0; m < 3; ++m) a[m] = t[1][m] - t[0][m], b[m] = t[2][m] - t[0][m];
        const int normal[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                               a[0] * b[1] - a[1] * b[0]};
        EXPECT_GT(normal[axis] * outward, 0) << "face " << f << " case " << c << " triangle " << k;
        area2 += normal[axis] * outward;
        // The triangle's quadrant holds part of it: its centroid is in the
        // quadrant's closed square.
        const int u = face_u(f), v = face_v(f);
        const int cu = t[0][u] + t[1][u] + t[2][u], cv = t[0][v] + t[1][v] + t[2][v];
        const int qu = tri.tri[k].quadrant & 1, qv = tri.tri[k].quadrant >> 1;
        EXPECT_TRUE(cu >= 3 * qu && cu <= 3 * qu + 3 && cv >= 3 * qv && cv <= 3 * qv + 3);
      }
      EXPECT_EQ(area2, 8) << "face " << f << " case " << c << " does not tile the face";
      std::set<int> expected = {face_point(f, 0, 0), face_point(f, 2, 0), face_point(f, 2, 2),
                                face_point(f, 0, 2)};
      if (c < kDiagonalCase) {
        expected.insert(face_centre(f));
        for (int k = 0; k < 4; ++k)
          if (c >> k & 1) expected.insert(face_midpoint(f, k));
      }
      EXPECT_EQ(points, expected) << "face " << f << " case " << c;
    }
  }
}

TEST(TemplatesFaceRule, DiagonalJoinsTheEvenEvenCorner) {
  const uint32_t edge = 1u << 10;
  for (int f = 0; f < kLeafFaces; ++f)
    for (uint32_t i = 0; i < 2; ++i)
      for (uint32_t j = 0; j < 2; ++j) {
        uint32_t anchor[3] = {4 * edge, 4 * edge, 4 * edge};
        anchor[face_u(f)] += i * edge;
        anchor[face_v(f)] += j * edge;
        const int c = diagonal_case(f, anchor, edge);
        // The (even, even) corner in in-face lattice coordinates.
        const int eu = 2 * static_cast<int>(i), ev = 2 * static_cast<int>(j);
        const int even = face_point(f, eu, ev), odd = face_point(f, 2 - eu, 2 - ev);
        int joined = 0;
        const FaceTriangulation& tri = face_triangulation(f, c);
        for (int k = 0; k < tri.count; ++k) {
          std::set<int> p(tri.tri[k].p, tri.tri[k].p + 3);
          joined += p.count(even) && p.count(odd);
        }
        EXPECT_EQ(joined, 2) << "face " << f << " anchor offset " << i << " " << j;
      }
}

TEST(TemplatesFaceRule, WorstDihedralAngleOfTheTemplates) {
  // Every coned template tet is a face triangle coned to the leaf centre,
  // so the tets of one leaf of lattice edge 2 show every shape there is
  // (paired faces make better ones: test_template_random.cpp).
  double worst = 180, widest = 0;
  for (int f = 0; f < kLeafFaces; ++f)
    for (int c = 0; c < kFaceCases; ++c) {
      const FaceTriangulation& tri = face_triangulation(f, c);
      for (int k = 0; k < tri.count; ++k) {
        double p[4][3];
        const int ids[4] = {tri.tri[k].p[0], tri.tri[k].p[2], tri.tri[k].p[1], kLeafCentre};
        for (int m = 0; m < 4; ++m) {
          int t[3];
          point_t(ids[m], t);
          for (int a = 0; a < 3; ++a) p[m][a] = t[a];
        }
        TetShape s = tet_shape(p[0], p[1], p[2], p[3]);
        EXPECT_GT(s.volume, 0);
        worst = std::min(worst, s.min_dihedral_rad * 180 / std::numbers::pi);
        widest = std::max(widest, s.max_dihedral_rad * 180 / std::numbers::pi);
      }
    }
  std::printf("template dihedral angles: min %.6f max %.6f degrees\n", worst, widest);
  EXPECT_NEAR(worst, 45.0, 1e-9);
  EXPECT_NEAR(widest, 120.0, 1e-9);
}

}  // namespace
}  // namespace partet
