// Helpers of the template and front tests: small octrees built by hand as
// sorted flat arrays (uniform trees, leaves replaced by their 8 children,
// a brute-force 2:1 balance across faces and edges), and exact checks of a
// template core against its tree, in integer lattice coordinates decoded
// from the vertex keys (no floating point):
//  - every tet positive, every tet face shared by at most two tets;
//  - the tet volumes add up to the interior leaves' volume exactly;
//  - every boundary face of the core separates an interior leaf from a
//    leaf that is not interior (or from outside the root): a face between
//    two interior leaves whose triangulations differ would show up here,
//    even where the two triangulations have the same boundary edges;
//  - the boundary is closed and consistently oriented: every directed edge
//    of the outward boundary faces is used as often as its reverse.
// Together with validate_mesh these say the core is a conforming mesh of
// exactly the interior leaves.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "check/validate.hpp"
#include "octree/octree.hpp"
#include "templates/template_mesh.hpp"

namespace partet::test {

struct Cell {
  uint32_t a[3];  // anchor, grid units
  int level;
};

inline uint32_t cell_edge(const Cell& c) { return octant_edge(c.level); }

inline std::vector<Cell> uniform_cells(int level) {
  std::vector<Cell> cells;
  const uint32_t n = 1u << level, h = octant_edge(level);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) cells.push_back({{x * h, y * h, z * h}, level});
  return cells;
}

// Replaces cells[i] by its 8 children (the order is fixed by make_tree).
inline void refine(std::vector<Cell>& cells, size_t i) {
  const Cell c = cells[i];
  const uint32_t h = cell_edge(c) / 2;
  cells[i] = {{c.a[0], c.a[1], c.a[2]}, c.level + 1};
  for (uint32_t b = 1; b < 8; ++b)
    cells.push_back({{c.a[0] + (b & 1) * h, c.a[1] + (b >> 1 & 1) * h, c.a[2] + (b >> 2 & 1) * h},
                     c.level + 1});
}

// Index of the cell with this anchor and level, or -1.
inline long find_cell(const std::vector<Cell>& cells, uint32_t x, uint32_t y, uint32_t z,
                      int level) {
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i].a[0] == x && cells[i].a[1] == y && cells[i].a[2] == z && cells[i].level == level)
      return static_cast<long>(i);
  return -1;
}

// Number of axes along which the closed boxes of two cells overlap with
// positive length, or -1 when they are disjoint: 2 for a shared piece of
// face, 1 for a shared piece of edge, 0 for a shared point.
inline int contact_dimension(const Cell& p, const Cell& q) {
  int dims = 0;
  for (int k = 0; k < 3; ++k) {
    int64_t lo = std::max<int64_t>(p.a[k], q.a[k]);
    int64_t hi = std::min<int64_t>(int64_t{p.a[k]} + cell_edge(p), int64_t{q.a[k]} + cell_edge(q));
    if (hi < lo) return -1;
    if (hi > lo) ++dims;
  }
  return dims;
}

// Refines until cells sharing a piece of face or edge differ by one level at most.
inline void balance(std::vector<Cell>& cells) {
  for (;;) {
    std::vector<size_t> coarse;
    for (size_t i = 0; i < cells.size(); ++i)
      for (size_t j = 0; j < cells.size(); ++j)
        if (cells[j].level > cells[i].level + 1 && contact_dimension(cells[i], cells[j]) >= 1) {
          coarse.push_back(i);
          break;
        }
    if (coarse.empty()) return;
    for (size_t i : coarse) refine(cells, i);
  }
}

inline bool touches_far_root(const Cell& c) {
  const uint32_t h = cell_edge(c);
  return c.a[0] + h >= kGridSize || c.a[1] + h >= kGridSize || c.a[2] + h >= kGridSize;
}

inline LinearOctree make_tree(std::vector<Cell> cells,
                              const std::function<LeafClass(const Cell&)>& cls) {
  std::sort(cells.begin(), cells.end(), [](const Cell& p, const Cell& q) {
    return morton_key(p.a[0], p.a[1], p.a[2]) < morton_key(q.a[0], q.a[1], q.a[2]);
  });
  LinearOctree tree;
  for (const Cell& c : cells) {
    tree.key.push_back(morton_key(c.a[0], c.a[1], c.a[2]));
    tree.level.push_back(static_cast<uint8_t>(c.level));
    tree.cls.push_back(cls(c));
    tree.owner.push_back(0);
  }
  return tree;
}

inline Cell tree_cell(const LinearOctree& tree, size_t i) {
  Cell c;
  tree.anchor(i, c.a[0], c.a[1], c.a[2]);
  c.level = tree.level[i];
  return c;
}

// The root cube [0,1]^3: one grid unit is 2^-20.
inline RootCube unit_root() {
  RootCube root;
  root.unit = 1.0 / kGridSize;
  return root;
}

struct LatticePoint {
  int64_t q[3];
};

inline LatticePoint lattice_of(const TemplateCore& core, uint32_t v) {
  uint32_t x, y, z;
  morton_decode(core.mesh.global_ids[v], x, y, z);
  return {{x, y, z}};
}

inline __int128 det6(const LatticePoint& p0, const LatticePoint& p1, const LatticePoint& p2,
                     const LatticePoint& p3) {
  __int128 a[3], b[3], c[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = p1.q[k] - p0.q[k];
    b[k] = p2.q[k] - p0.q[k];
    c[k] = p3.q[k] - p0.q[k];
  }
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The leaf containing the point X / 18 (grid units), or -1 outside the root.
inline long leaf_at(const LinearOctree& tree, const int64_t* x18) {
  uint32_t g[3];
  for (int k = 0; k < 3; ++k) {
    if (x18[k] < 0 || x18[k] >= int64_t{18} * kGridSize) return -1;
    g[k] = static_cast<uint32_t>(x18[k] / 18);
  }
  return static_cast<long>(tree.locate(g[0], g[1], g[2]));
}

struct CoreFacts {
  size_t boundary_faces = 0;
  size_t non_manifold_edges = 0;  // directed boundary edges used more than once
};

// The checks listed at the top; failures name `label`.
inline CoreFacts expect_core_conforms(const LinearOctree& tree, const TemplateCore& core,
                                      const std::string& label) {
  CoreFacts facts;
  const TetMesh& mesh = core.mesh;
  ValidationResult r = validate_mesh(mesh, nullptr);
  EXPECT_TRUE(r.valid) << label << "\n" << format_text(r);
  EXPECT_EQ(r.unused_vertices, 0u) << label;

  std::vector<LatticePoint> q(mesh.num_vertices());
  for (uint32_t v = 0; v < q.size(); ++v) q[v] = lattice_of(core, v);

  // Exact volume, times 6, in lattice units.
  __int128 tets6 = 0, leaves6 = 0;
  for (size_t t = 0; t < mesh.num_tets(); ++t) {
    const uint32_t* v = &mesh.tets[4 * t];
    __int128 d = det6(q[v[0]], q[v[1]], q[v[2]], q[v[3]]);
    EXPECT_GT(d, 0) << label << ": tet " << t << " not positive";
    tets6 += d;
  }
  size_t interior = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    if (tree.cls[i] != LeafClass::kInterior) continue;
    ++interior;
    __int128 e = 2 * __int128{octant_edge(tree.level[i])};
    leaves6 += 6 * e * e * e;
  }
  EXPECT_TRUE(tets6 == leaves6) << label << ": tet volume differs from the interior leaves' volume";
  EXPECT_EQ(core.leaves_templated, interior) << label;

  // Faces: outward faces of every tet, matched by sorted vertex triple.
  constexpr int kOutward[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  struct FaceUse {
    uint64_t key;
    uint32_t tet;
    int face;
  };
  std::vector<FaceUse> uses;
  uses.reserve(4 * mesh.num_tets());
  for (uint32_t t = 0; t < mesh.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      uint64_t s[3];
      for (int k = 0; k < 3; ++k) s[k] = mesh.tets[4 * t + kOutward[f][k]];
      std::sort(s, s + 3);
      uses.push_back({s[0] << 42 | s[1] << 21 | s[2], t, f});
    }
  std::sort(uses.begin(), uses.end(), [](const FaceUse& p, const FaceUse& u) {
    return p.key != u.key ? p.key < u.key : p.tet < u.tet;
  });
  std::vector<uint64_t> edges;  // boundary edges as (from, to) pairs, 21 bits each
  size_t bad_boundary = 0;
  for (size_t i = 0, j; i < uses.size(); i = j) {
    for (j = i; j < uses.size() && uses[j].key == uses[i].key; ++j) {
    }
    EXPECT_LE(j - i, 2u) << label << ": a face shared by more than two tets";
    if (j - i != 1) continue;
    ++facts.boundary_faces;
    const uint32_t* tv = &mesh.tets[4 * uses[i].tet];
    const uint32_t f[3] = {tv[kOutward[uses[i].face][0]], tv[kOutward[uses[i].face][1]],
                           tv[kOutward[uses[i].face][2]]};
    for (int k = 0; k < 3; ++k) edges.push_back(uint64_t{f[k]} << 21 | f[(k + 1) % 3]);
    // The face lies on a leaf face: the axis where its three points agree.
    int axis = -1;
    for (int k = 0; k < 3; ++k)
      if (q[f[0]].q[k] == q[f[1]].q[k] && q[f[0]].q[k] == q[f[2]].q[k]) axis = k;
    EXPECT_GE(axis, 0) << label << ": boundary face off the leaf faces";
    if (axis < 0) continue;
    const uint32_t opposite = tv[uses[i].face];
    const int64_t out = q[opposite].q[axis] < q[f[0]].q[axis] ? 1 : -1;
    // A point inside the triangle with weights 2/9, 3/9, 4/9, in 1/18 grid units.
    int64_t x[3];
    for (int k = 0; k < 3; ++k) x[k] = 2 * q[f[0]].q[k] + 3 * q[f[1]].q[k] + 4 * q[f[2]].q[k];
    x[axis] += out;
    long outside = leaf_at(tree, x);
    x[axis] -= 2 * out;
    long inside = leaf_at(tree, x);
    bool ok = inside >= 0 && tree.cls[inside] == LeafClass::kInterior &&
              (outside < 0 || tree.cls[outside] != LeafClass::kInterior);
    if (!ok && bad_boundary++ < 3)
      ADD_FAILURE() << label << ": boundary face of tet " << uses[i].tet
                    << " does not separate an interior leaf from a non-interior one";
  }
  EXPECT_EQ(bad_boundary, 0u) << label;
  // Each directed edge as often as its reverse; more than once: non-manifold.
  std::sort(edges.begin(), edges.end());
  auto uses_of = [&](uint64_t e) {
    auto range = std::equal_range(edges.begin(), edges.end(), e);
    return static_cast<size_t>(range.second - range.first);
  };
  size_t open = 0;
  for (size_t i = 0, j; i < edges.size(); i = j) {
    for (j = i; j < edges.size() && edges[j] == edges[i]; ++j) {
    }
    const size_t reverse = uses_of((edges[i] & ((1u << 21) - 1)) << 21 | edges[i] >> 21);
    open += reverse != j - i;
    facts.non_manifold_edges += j - i > 1;
  }
  EXPECT_EQ(open, 0u) << label << ": boundary edges not used equally in both directions";
  EXPECT_EQ(r.boundary_faces, facts.boundary_faces) << label;
  return facts;
}

}  // namespace partet::test
