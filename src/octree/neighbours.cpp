// Face and edge neighbours of a leaf by point location (see neighbours.hpp).
#include "octree/neighbours.hpp"

#include "core/error.hpp"

namespace partet {

namespace {

// The other two axes of `axis`, in cyclic order.
void other_axes(int axis, int& u, int& v) {
  u = (axis + 1) % 3;
  v = (axis + 2) % 3;
}

// Grid coordinate just across face side `side` of [a, a + h) on one axis:
// false when that is outside the root cube.
bool across(uint32_t a, uint32_t h, int side, uint32_t& out) {
  if (side == 0) {
    if (a == 0) return false;
    out = a - 1;
    return true;
  }
  if (a + h >= kGridSize) return false;
  out = a + h;
  return true;
}

// Appends the leaves across a square part of a face, of the size of a
// level-`level` octant, whose lowest grid cell just across the face is q:
// one leaf when the leaf containing q covers it, else the four quadrants
// recursively.
void collect_face(const LinearOctree& tree, const uint32_t* q, int axis, int level, std::vector<size_t>& out) {
  const size_t j = tree.locate(q[0], q[1], q[2]);
  if (tree.level[j] <= level) {
    out.push_back(j);
    return;
  }
  int u, v;
  other_axes(axis, u, v);
  const uint32_t h = octant_edge(level + 1);
  for (int k = 0; k < 4; ++k) {
    uint32_t p[3] = {q[0], q[1], q[2]};
    p[u] += (k & 1) ? h : 0;
    p[v] += (k & 2) ? h : 0;
    collect_face(tree, p, axis, level + 1, out);
  }
}

}  // namespace

void edge_corners(int edge, int& c0, int& c1) {
  const int axis = edge / 4;
  int u, v;
  other_axes(axis, u, v);
  c0 = ((edge & 1) << u) | (((edge >> 1) & 1) << v);
  c1 = c0 | (1 << axis);
}

int face_neighbours(const LinearOctree& tree, size_t i, int face, size_t out[4]) {
  const int axis = face / 2, level = tree.level[i];
  uint32_t a[3];
  tree.anchor(i, a[0], a[1], a[2]);
  uint32_t q[3] = {a[0], a[1], a[2]};
  if (!across(a[axis], octant_edge(level), face & 1, q[axis])) return 0;
  const size_t j = tree.locate(q[0], q[1], q[2]);
  if (tree.level[j] <= level) {
    out[0] = j;
    return 1;
  }
  int u, v;
  other_axes(axis, u, v);
  const uint32_t h = octant_edge(level + 1);
  for (int k = 0; k < 4; ++k) {
    uint32_t p[3] = {q[0], q[1], q[2]};
    p[u] += (k & 1) ? h : 0;
    p[v] += (k & 2) ? h : 0;
    out[k] = tree.locate(p[0], p[1], p[2]);
    PARTET_ASSERT(tree.level[out[k]] == level + 1, "face neighbours more than one level finer: tree not 2:1 balanced");
  }
  return 4;
}

void append_face_neighbours(const LinearOctree& tree, size_t i, int face, std::vector<size_t>& out) {
  const int axis = face / 2, level = tree.level[i];
  uint32_t q[3];
  tree.anchor(i, q[0], q[1], q[2]);
  if (!across(q[axis], octant_edge(level), face & 1, q[axis])) return;
  collect_face(tree, q, axis, level, out);
}

size_t edge_region_leaf(const LinearOctree& tree, size_t i, int edge, int region) {
  const int axis = edge / 4;
  const uint32_t h = octant_edge(tree.level[i]);
  int u, v;
  other_axes(axis, u, v);
  uint32_t p[3];
  tree.anchor(i, p[0], p[1], p[2]);
  // The edge lies on the leaf's side su of axis u and sv of axis v; the cell
  // is across that side, or just inside the leaf, on each of the two axes.
  const int su = edge & 1, sv = (edge >> 1) & 1;
  if (region & 1) {
    if (!across(p[u], h, su, p[u])) return kNoLeaf;
  } else if (su) {
    p[u] += h - 1;
  }
  if (region & 2) {
    if (!across(p[v], h, sv, p[v])) return kNoLeaf;
  } else if (sv) {
    p[v] += h - 1;
  }
  return tree.locate(p[0], p[1], p[2]);
}

bool edge_has_finer_leaf(const LinearOctree& tree, size_t i, int edge) {
  for (int region = 1; region < 4; ++region) {
    const size_t j = edge_region_leaf(tree, i, edge, region);
    if (j != kNoLeaf && tree.level[j] > tree.level[i]) return true;
  }
  return false;
}

}  // namespace partet
