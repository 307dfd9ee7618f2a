// The initial front on a box inside a graded tree: leaves meeting the box's
// surface are boundary leaves, leaves inside it interior. The front is two
// closed, consistently oriented sheets (the reversed surface and the
// core's exposed faces, every directed edge used once and its reverse
// once), it faces the gap (its signed volume is minus the gap's volume),
// and its vertices are indexed by the leaves containing them.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "front/initial_front.hpp"
#include "template_trees.hpp"

namespace partet::test {
namespace {

// The surface of the box [lo, hi]^3, each face an n x n grid of squares
// split in two, outward.
SurfaceMesh gridded_box(double lo, double hi, int n) {
  SurfaceMesh s;
  std::map<std::vector<int>, uint32_t> index;
  auto vertex = [&](int i, int j, int k) {
    auto [it, added] = index.try_emplace({i, j, k}, static_cast<uint32_t>(index.size()));
    if (added)
      for (int c : {i, j, k}) s.xyz.push_back(lo + (hi - lo) * c / n);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          uint32_t p[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int m = 0; m < 4; ++m) {
            int t[3];
            t[axis] = side * n;
            t[(axis + 1) % 3] = a + du[m];
            t[(axis + 2) % 3] = b + dv[m];
            p[m] = vertex(t[0], t[1], t[2]);
          }
          if (side == 1)
            s.tris.insert(s.tris.end(), {p[0], p[1], p[2], p[0], p[2], p[3]});
          else
            s.tris.insert(s.tris.end(), {p[0], p[2], p[1], p[0], p[3], p[2]});
        }
  return s;
}

double signed_volume(const std::vector<double>& xyz, const std::vector<uint32_t>& faces) {
  double sum = 0;
  for (size_t t = 0; t + 2 < faces.size(); t += 3) {
    const double* a = &xyz[3 * faces[t]];
    const double* b = &xyz[3 * faces[t + 1]];
    const double* c = &xyz[3 * faces[t + 2]];
    sum += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return sum / 6;
}

// The box [lo, hi]^3 in a level-3 tree refined to level 5 around the box's
// surface, balanced.
struct BoxCase {
  SurfaceMesh surface;
  LinearOctree tree;
  TemplateCore core;
  InitialFront front;
};

BoxCase box_case(double lo, double hi) {
  BoxCase b;
  b.surface = gridded_box(lo, hi, 5);
  auto box_class = [&](const Cell& c) {
    bool inside = true, meets = true;
    for (int k = 0; k < 3; ++k) {
      const double x0 = static_cast<double>(c.a[k]) / kGridSize;
      const double x1 = static_cast<double>(c.a[k] + cell_edge(c)) / kGridSize;
      inside = inside && lo < x0 && x1 < hi;
      meets = meets && x0 <= hi && lo <= x1;
    }
    return inside ? LeafClass::kInterior : meets ? LeafClass::kBoundary : LeafClass::kOutside;
  };
  std::vector<Cell> cells = uniform_cells(3);
  for (int level = 3; level < 5; ++level)
    for (size_t i = 0, n = cells.size(); i < n; ++i)
      if (cells[i].level == level && box_class(cells[i]) == LeafClass::kBoundary) refine(cells, i);
  balance(cells);
  b.tree = make_tree(cells, box_class);
  b.core = template_interior(b.tree, unit_root());
  b.front = make_initial_front(b.tree, unit_root(), b.core, b.surface);
  return b;
}

TEST(FrontInitial, BoxFrontIsTwoClosedOrientedSheets) {
  BoxCase b = box_case(0.3, 0.7);
  const InitialFront& front = b.front;
  expect_core_conforms(b.tree, b.core, "box core");
  ASSERT_GT(b.core.mesh.num_tets(), 0u);
  EXPECT_EQ(front.surface_faces, b.surface.num_triangles());
  ASSERT_GT(front.num_faces(), front.surface_faces);

  // Every directed edge once, its reverse once; no edge shared by the sheets.
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  std::map<std::pair<uint32_t, uint32_t>, int> sheet;
  for (size_t t = 0; t < front.num_faces(); ++t)
    for (int k = 0; k < 3; ++k) {
      uint32_t from = front.faces[3 * t + k], to = front.faces[3 * t + (k + 1) % 3];
      ++directed[{from, to}];
      sheet[{std::min(from, to), std::max(from, to)}] |= t < front.surface_faces ? 1 : 2;
    }
  size_t bad = 0;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    bad += count != 1 || reverse == directed.end() || reverse->second != 1;
  }
  EXPECT_EQ(bad, 0u);
  for (const auto& [edge, sheets] : sheet) EXPECT_NE(sheets, 3) << "edge on both sheets";

  // Facing the gap: the front bounds the gap with normals pointing into it.
  double core_volume = 0;
  for (size_t i = 0; i < b.tree.size(); ++i)
    if (b.tree.cls[i] == LeafClass::kInterior) core_volume += std::pow(0.5, 3 * b.tree.level[i]);
  const double gap = 0.4 * 0.4 * 0.4 - core_volume;
  ASSERT_GT(gap, 0);
  EXPECT_NEAR(signed_volume(front.xyz, front.faces), -gap, 1e-12);
  std::vector<uint32_t> core_faces(front.faces.begin() + 3 * front.surface_faces,
                                   front.faces.end());
  EXPECT_NEAR(signed_volume(front.xyz, core_faces), core_volume, 1e-12);

  // The --front-out surface: the same faces over the vertices they use.
  SurfaceMesh out = front_surface(front);
  EXPECT_EQ(out.num_triangles(), front.num_faces());
  EXPECT_EQ(out.num_vertices(), front.front_vertices.size());
  EXPECT_NEAR(signed_volume(out.xyz, out.tris), -gap, 1e-12);
}

TEST(FrontInitial, VerticesAreIndexedByTheirLeaves) {
  BoxCase b = box_case(0.3, 0.7);
  const InitialFront& front = b.front;
  const size_t nc = b.core.mesh.num_vertices(), ns = b.surface.num_vertices();
  ASSERT_EQ(front.core_vertices, nc);
  ASSERT_EQ(front.xyz.size(), 3 * (nc + ns));
  ASSERT_EQ(front.vertex_leaf.size(), nc + ns);
  for (size_t v = 0; v < nc + ns; ++v) {
    if (v < nc) {
      EXPECT_EQ(front.global_ids[v], b.core.mesh.global_ids[v]);
      EXPECT_EQ(front.global_ids[v] & kSurfaceVertexId, 0u);
    } else {
      EXPECT_EQ(front.global_ids[v], kSurfaceVertexId | (v - nc));
    }
    // In the leaf's half-open box.
    const Cell c = tree_cell(b.tree, front.vertex_leaf[v]);
    for (int k = 0; k < 3; ++k) {
      const double x = front.xyz[3 * v + k] * kGridSize;
      EXPECT_LE(static_cast<double>(c.a[k]), x);
      EXPECT_LT(x, static_cast<double>(c.a[k] + cell_edge(c)));
    }
  }
  // The front vertices, each once, under its leaf, ascending in a leaf.
  std::vector<char> used(nc + ns, 0);
  for (uint32_t v : front.faces) used[v] = 1;
  std::vector<int> listed(nc + ns, 0);
  ASSERT_EQ(front.leaf_first_front_vertex.size(), b.tree.size() + 1);
  for (size_t i = 0; i < b.tree.size(); ++i)
    for (uint32_t k = front.leaf_first_front_vertex[i]; k < front.leaf_first_front_vertex[i + 1];
         ++k) {
      const uint32_t v = front.front_vertices[k];
      ++listed[v];
      EXPECT_EQ(front.vertex_leaf[v], i);
      if (k > front.leaf_first_front_vertex[i]) {
        EXPECT_LT(front.front_vertices[k - 1], v);
      }
    }
  for (size_t v = 0; v < nc + ns; ++v) EXPECT_EQ(listed[v], used[v]) << "vertex " << v;
}

TEST(FrontInitial, PointsOnLeafFacesBelongToTheUpperLeaf) {
  std::vector<Cell> cells = uniform_cells(2);
  refine(cells, 0);
  LinearOctree tree = make_tree(cells, [](const Cell&) { return LeafClass::kOutside; });
  const RootCube root = unit_root();
  auto leaf_anchor = [&](const double* p) {
    const Cell c = tree_cell(tree, leaf_of_point(tree, root, p));
    return std::vector<double>{c.a[0] / double(kGridSize), c.a[1] / double(kGridSize),
                               c.a[2] / double(kGridSize)};
  };
  const double on_corner[3] = {0.25, 0.25, 0.25};
  EXPECT_EQ(leaf_anchor(on_corner), (std::vector<double>{0.25, 0.25, 0.25}));
  const double below[3] = {std::nextafter(0.25, 0.0), 0.125, 0.125};
  EXPECT_EQ(leaf_anchor(below), (std::vector<double>{0.125, 0.125, 0.125}));
  const double on_face[3] = {0.5, 0.3, 0.9};
  EXPECT_EQ(leaf_anchor(on_face), (std::vector<double>{0.5, 0.25, 0.75}));
  const double far[3] = {1.0, 2.0, -1.0};  // clamped into the root cube
  EXPECT_EQ(leaf_anchor(far), (std::vector<double>{0.75, 0.75, 0.0}));
}

}  // namespace
}  // namespace partet::test
