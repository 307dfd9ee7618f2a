// Template meshing of interior leaves (see template_mesh.hpp) in four flat
// passes over the interior leaves, each leaf looking only at its upper
// cells (leaf_neighbourhood.hpp):
//  1. V: every interior leaf marks its 8 corners at their homes (one bit
//     per child anchor per leaf);
//  2. face cases: every interior leaf reads V at its 12 edge midpoints and
//     6 face centres, picks each face's case and marks the vertices it adds
//     (centres of fanned faces, its own centre) at their homes;
//  3. numbering: prefix sums of the per-leaf vertex masks; coordinates and
//     keys of the vertices, leaf by leaf;
//  4. tets: every interior leaf numbers its points from the masks and emits
//     one tet per face triangle.
// No hashing: a point's vertex index is its home's first vertex plus the
// number of vertex child anchors before it in the home's mask.
#include "templates/template_mesh.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "core/error.hpp"
#include "templates/face_rule.hpp"
#include "templates/leaf_neighbourhood.hpp"

namespace partet {
namespace {

// The 18 leaf points other than corners and centre that a face rule reads.
constexpr int kFacePointCount = kLeafEdges + kLeafFaces;
constexpr std::array<uint8_t, kFacePointCount> face_points() {
  std::array<uint8_t, kFacePointCount> points{};
  for (int k = 0; k < kLeafEdges; ++k) points[k] = kEdgeMidpoints[k];
  for (int f = 0; f < kLeafFaces; ++f)
    points[kLeafEdges + f] = static_cast<uint8_t>(face_centre(f));
  return points;
}
constexpr std::array<uint8_t, kFacePointCount> kFacePoints = face_points();

// The boundary polygon of face f in case c, counterclockwise about +axis
// from in-face corner (0, 0): the corners and, in a fanned case, the
// midpoints on the fan's boundary. Writes the leaf points to `points` (8
// at most) when given; returns their number.
int polygon_points(int f, int c, int* points) {
  constexpr int kCornerU[4] = {0, 2, 2, 0}, kCornerV[4] = {0, 0, 2, 2};
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    if (points) points[n] = face_point(f, kCornerU[k], kCornerV[k]);
    ++n;
    if (c < kDiagonalCase && (c >> k & 1)) {
      if (points) points[n] = face_midpoint(f, k);
      ++n;
    }
  }
  return n;
}

// Tets leaf i makes over face f in case c, its twin across f being `twin`
// (paired_leaf): see face_tets.
uint32_t tets_over_face(const LinearOctree& tree, size_t i, int f, int c, uint32_t twin) {
  if (twin == kAbsentLeaf) return face_triangulation(f, c).count;
  return tree.key[i] < tree.key[twin] ? static_cast<uint32_t>(polygon_points(f, c, nullptr)) : 0;
}

// The interior leaves whose corners are in V: all of them, or with a part
// those with an owner (own and layer-1 leaves of a local view).
std::vector<uint32_t> interior_leaves(const LinearOctree& tree, int32_t part) {
  std::vector<uint32_t> interior;
  for (size_t i = 0; i < tree.size(); ++i) {
    if (tree.cls[i] != LeafClass::kInterior || (part >= 0 && tree.owner[i] < 0)) continue;
    uint32_t a[3];
    tree.anchor(i, a[0], a[1], a[2]);
    const uint32_t edge = octant_edge(tree.level[i]);
    PARTET_ASSERT(a[0] + edge < kGridSize && a[1] + edge < kGridSize && a[2] + edge < kGridSize,
                  "interior leaf " + std::to_string(i) + " touches the far faces of the root cube");
    interior.push_back(static_cast<uint32_t>(i));
  }
  return interior;
}

// Pass 1: bit b of in_v[leaf] is set when child anchor b of the leaf is a
// corner of an interior leaf. Keeps the upper cells of every interior leaf,
// 7 per leaf, for the later passes.
std::vector<uint8_t> mark_corners(const LinearOctree& tree, const std::vector<uint32_t>& interior,
                                  LeafNeighbourhood& around, std::vector<uint32_t>& upper_cells) {
  std::vector<uint8_t> in_v(tree.size(), 0);
  upper_cells.resize(7 * interior.size());
  uint32_t* up = upper_cells.data();
  for (uint32_t i : interior) {
    around.reset(i);
    std::copy(around.upper_cells(), around.upper_cells() + 7, up);
    up += 7;
    for (int c = 0; c < 8; ++c) {
      PointHome h = around.home(corner_point(c));
      PARTET_ASSERT(h.leaf != kAbsentLeaf, "corner without a home at leaf " + std::to_string(i));
      in_v[h.leaf] |= static_cast<uint8_t>(1u << h.child);
    }
  }
  return in_v;
}

// Pass 2 for the current leaf of `around`: its face cases, and the vertices
// its tets use marked in `vertex_mask` (its corners, the midpoints in V and
// centres of its fanned faces, its centre). Returns its tet count.
uint32_t choose_face_cases(const LinearOctree& tree, const LeafNeighbourhood& around,
                           const std::vector<uint8_t>& in_v, std::vector<uint8_t>& vertex_mask, uint8_t* cases) {
  uint32_t present = 0;  // bit p: leaf point p is in V
  PointHome homes[kLeafPoints];
  for (int c = 0; c < 8; ++c) {
    const PointHome h = around.home(corner_point(c));
    vertex_mask[h.leaf] |= static_cast<uint8_t>(1u << h.child);
  }
  for (uint8_t p : kFacePoints) {
    PointHome h = around.home(p);
    homes[p] = h;
    if (h.leaf != kAbsentLeaf && (in_v[h.leaf] >> h.child & 1)) present |= 1u << p;
  }
  uint32_t tets = 0;
  for (int f = 0; f < kLeafFaces; ++f) {
    uint32_t midpoints = 0;
    for (int k = 0; k < 4; ++k) midpoints |= (present >> face_midpoint(f, k) & 1u) << k;
    const int centre = face_centre(f);
    const uint32_t twin = paired_leaf(tree, around.leaf(), f);
    int c;
    if (midpoints != 0 || (present >> centre & 1)) {
      c = static_cast<int>(midpoints);
      PointHome h = homes[centre];
      PARTET_ASSERT(h.leaf != kAbsentLeaf, "fanned face " + std::to_string(f) + " of leaf " +
                                               std::to_string(around.leaf()) +
                                               " has its centre off its home's lattice");
      if (twin == kAbsentLeaf) vertex_mask[h.leaf] |= static_cast<uint8_t>(1u << h.child);
      for (int k = 0; k < 4; ++k) {
        const PointHome m = homes[face_midpoint(f, k)];
        if (c >> k & 1) vertex_mask[m.leaf] |= static_cast<uint8_t>(1u << m.child);
      }
    } else {
      c = diagonal_case(f, around.anchor(), around.edge());
    }
    cases[f] = static_cast<uint8_t>(c);
    const uint32_t made = tets_over_face(tree, around.leaf(), f, c, twin);
    if (twin != kAbsentLeaf && made > 0) vertex_mask[twin] |= 0x80;  // the twin's centre
    tets += made;
  }
  vertex_mask[around.leaf()] |= 0x80;  // the leaf centre, child anchor 7
  return tets;
}

// Pass 3: vertex numbering, coordinates and keys.
void number_vertices(const LinearOctree& tree, const RootCube& root,
                     const std::vector<uint8_t>& vertex_mask, TemplateCore& core) {
  const size_t n = tree.size();
  core.leaf_first_vertex.assign(n + 1, 0);
  uint64_t count = 0;
  for (size_t i = 0; i < n; ++i) {
    core.leaf_first_vertex[i] = static_cast<uint32_t>(count);
    count += kByteBits[vertex_mask[i]];
    PARTET_ASSERT(count < UINT32_MAX, "more than 2^32 - 1 template vertices");
  }
  core.leaf_first_vertex[n] = static_cast<uint32_t>(count);
  core.mesh.xyz.resize(3 * count);
  core.mesh.global_ids.resize(count);
  double* xyz = core.mesh.xyz.data();
  uint64_t* ids = core.mesh.global_ids.data();
  for (size_t i = 0; i < n; ++i) {
    uint32_t mask = vertex_mask[i];
    if (mask == 0) continue;
    uint32_t a[3];
    tree.anchor(i, a[0], a[1], a[2]);
    const uint32_t half = octant_edge(tree.level[i]);  // half the edge in lattice units
    for (; mask != 0; mask &= mask - 1) {
      const uint32_t b = static_cast<uint32_t>(__builtin_ctz(mask));
      const uint32_t q[3] = {2 * a[0] + half * (b & 1), 2 * a[1] + half * (b >> 1 & 1),
                             2 * a[2] + half * (b >> 2 & 1)};
      root.lattice_point(q[0], q[1], q[2], xyz);
      xyz += 3;
      *ids++ = morton_key(q[0], q[1], q[2]);
    }
  }
}

// Pass 4 for the current leaf of `around`: its tets, written at `out`.
void emit_tets(const LinearOctree& tree, const LeafNeighbourhood& around, const uint8_t* cases,
               const std::vector<uint8_t>& vertex_mask, const std::vector<uint32_t>& first_vertex,
               uint32_t* out) {
  const uint8_t* mask = vertex_mask.data();
  const uint32_t* first = first_vertex.data();
  uint32_t vertex[kLeafPoints];
  for (int c = 0; c < 8; ++c)
    vertex[corner_point(c)] = home_vertex(around.home(corner_point(c)), mask, first);
  const uint32_t centre = home_vertex({static_cast<uint32_t>(around.leaf()), 7}, mask, first);
  vertex[kLeafCentre] = centre;
  uint32_t twins[kLeafFaces];
  for (int f = 0; f < kLeafFaces; ++f) twins[f] = paired_leaf(tree, around.leaf(), f);
  for (int f = 0; f < kLeafFaces; ++f) {
    const int c = cases[f];
    if (c >= kDiagonalCase) continue;
    if (twins[f] == kAbsentLeaf)
      vertex[face_centre(f)] = home_vertex(around.home(face_centre(f)), mask, first);
    for (int k = 0; k < 4; ++k)
      if (c >> k & 1)
        vertex[face_midpoint(f, k)] = home_vertex(around.home(face_midpoint(f, k)), mask, first);
  }
  for (int f = 0; f < kLeafFaces; ++f) {
    const uint32_t twin = twins[f];
    if (twin != kAbsentLeaf) {
      if (tree.key[twin] < tree.key[around.leaf()]) continue;  // the twin makes them
      // One tet per boundary segment (a, b) of the face, around the axis
      // between the two centres, positive with (a, b) counterclockwise
      // about +axis: (a, b, twin, centre) on a lower face, (b, a, ...) on
      // an upper one.
      const uint32_t twin_centre = home_vertex({twin, 7}, mask, first);
      int points[8];
      const int n = polygon_points(f, cases[f], points);
      for (int k = 0; k < n; ++k) {
        const uint32_t a = vertex[points[k]], b = vertex[points[(k + 1) % n]];
        out[0] = face_side(f) ? b : a;
        out[1] = face_side(f) ? a : b;
        out[2] = twin_centre;
        out[3] = centre;
        out += 4;
      }
      continue;
    }
    const FaceTriangulation& t = face_triangulation(f, cases[f]);
    for (int k = 0; k < t.count; ++k) {
      const uint8_t* p = t.tri[k].p;
      out[0] = vertex[p[0]];
      out[1] = vertex[p[2]];
      out[2] = vertex[p[1]];
      out[3] = centre;
      out += 4;
    }
  }
}

}  // namespace

uint32_t paired_leaf(const LinearOctree& tree, size_t i, int f) {
  const uint32_t j = leaf_across(tree, i, f, 0);
  if (j == kAbsentLeaf || tree.level[j] != tree.level[i] || tree.cls[j] != LeafClass::kInterior) return kAbsentLeaf;
  return j;
}

uint32_t face_tets(const LinearOctree& tree, size_t i, int f, int face_case) {
  return tets_over_face(tree, i, f, face_case, paired_leaf(tree, i, f));
}

namespace {

TemplateCore template_leaves(const LinearOctree& tree, const RootCube& root, int32_t part) {
  TemplateCore core;
  const size_t n = tree.size();
  PARTET_ASSERT(n < UINT32_MAX, "more than 2^32 - 1 leaves");
  const std::vector<uint32_t> interior = interior_leaves(tree, part);
  LeafNeighbourhood around(tree);

  std::vector<uint32_t> upper_cells;
  const std::vector<uint8_t> in_v = mark_corners(tree, interior, around, upper_cells);

  // The leaves templated: all interior ones, or the part's.
  std::vector<uint32_t> templated;  // positions in `interior`
  for (size_t k = 0; k < interior.size(); ++k)
    if (part < 0 || tree.owner[interior[k]] == part) templated.push_back(static_cast<uint32_t>(k));
  core.leaves_templated = templated.size();

  std::vector<uint8_t> vertex_mask(n, 0);
  core.face_case.assign(kLeafFaces * n, kNoFaceCase);
  core.leaf_first_tet.assign(n + 1, 0);
  for (uint32_t k : templated) {
    const uint32_t i = interior[k];
    around.reset(i, &upper_cells[7 * k]);
    core.leaf_first_tet[i + 1] =
        choose_face_cases(tree, around, in_v, vertex_mask, &core.face_case[kLeafFaces * i]);
  }
  for (size_t i = 0; i < n; ++i) core.leaf_first_tet[i + 1] += core.leaf_first_tet[i];

  number_vertices(tree, root, vertex_mask, core);

  core.mesh.tets.resize(4 * core.leaf_first_tet[n]);
  for (uint32_t k : templated) {
    const uint32_t i = interior[k];
    around.reset(i, &upper_cells[7 * k]);
    uint32_t* out = &core.mesh.tets[4 * core.leaf_first_tet[i]];
    emit_tets(tree, around, &core.face_case[kLeafFaces * i], vertex_mask, core.leaf_first_vertex, out);
  }
  return core;
}

}  // namespace

TemplateCore template_interior(const LinearOctree& tree, const RootCube& root) {
  return template_leaves(tree, root, -1);
}

TemplateCore template_interior(const LinearOctree& view, const RootCube& root, int32_t part) {
  PARTET_ASSERT(part >= 0, "a part is a rank");
  return template_leaves(view, root, part);
}

}  // namespace partet
