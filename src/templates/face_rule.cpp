// The face triangulation table of face_rule.hpp, built at compile time:
// for each of the 6 leaf faces and 18 face cases, the triangles as leaf
// points, counterclockwise seen from outside the leaf, with the in-face
// quadrant each one lies in.
#include "templates/face_rule.hpp"

#include <array>

namespace partet {
namespace {

struct InFace {
  int u, v;
};

// The boundary polygon of a face, counterclockwise about +axis: corner,
// midpoint, corner, ... starting at (0,0). Odd positions are midpoints.
constexpr InFace kPolygon[8] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

using Table = std::array<FaceTriangulation, kLeafFaces * kFaceCases>;

// Appends the in-face triangle (a, b, c), given counterclockwise about
// +axis, to `t`, turned to face outward (clockwise about +axis on a lower
// face).
constexpr void add(FaceTriangulation& t, int f, InFace a, InFace b, InFace c) {
  if (face_side(f) == 0) {
    InFace s = b;
    b = c;
    c = s;
  }
  FaceTriangle& tri = t.tri[t.count++];
  tri.p[0] = static_cast<uint8_t>(face_point(f, a.u, a.v));
  tri.p[1] = static_cast<uint8_t>(face_point(f, b.u, b.v));
  tri.p[2] = static_cast<uint8_t>(face_point(f, c.u, c.v));
  // Centroid in units of a third of a lattice step: above 3 is the upper half.
  int qu = a.u + b.u + c.u > 3 ? 1 : 0;
  int qv = a.v + b.v + c.v > 3 ? 1 : 0;
  tri.quadrant = static_cast<uint8_t>(qu | qv << 1);
}

constexpr Table build_table() {
  Table table{};
  for (int f = 0; f < kLeafFaces; ++f) {
    for (int mask = 0; mask < 16; ++mask) {
      FaceTriangulation& t = table[f * kFaceCases + mask];
      // The polygon's points in order: corners always, midpoint k when bit k is set.
      InFace ring[8] = {};
      int n = 0;
      for (int k = 0; k < 8; ++k)
        if (k % 2 == 0 || (mask >> (k / 2) & 1)) ring[n++] = kPolygon[k];
      for (int k = 0; k < n; ++k) add(t, f, InFace{1, 1}, ring[k], ring[(k + 1) % n]);
    }
    FaceTriangulation& main_diagonal = table[f * kFaceCases + kDiagonalCase];
    add(main_diagonal, f, {0, 0}, {2, 0}, {2, 2});
    add(main_diagonal, f, {0, 0}, {2, 2}, {0, 2});
    FaceTriangulation& anti_diagonal = table[f * kFaceCases + kDiagonalCase + 1];
    add(anti_diagonal, f, {0, 0}, {2, 0}, {0, 2});
    add(anti_diagonal, f, {2, 0}, {2, 2}, {0, 2});
  }
  return table;
}

constexpr Table kTable = build_table();

constexpr bool edge_midpoints_right() {
  for (int k = 0; k < kLeafEdges; ++k) {
    int p = kEdgeMidpoints[k];
    if ((p % 3 == 1) + (p / 3 % 3 == 1) + (p / 9 == 1) != 1) return false;
    if (k > 0 && kEdgeMidpoints[k - 1] >= p) return false;
  }
  return true;
}
static_assert(edge_midpoints_right(), "kEdgeMidpoints must list the 12 edge midpoints");

}  // namespace

const FaceTriangulation& face_triangulation(int f, int c) { return kTable[f * kFaceCases + c]; }

}  // namespace partet
