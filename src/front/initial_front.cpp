// The initial front (see initial_front.hpp). Exposed core faces come from
// the face cases of the template, not from matching tet faces
// (templates/exposed_faces.hpp).
#include "front/initial_front.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "templates/exposed_faces.hpp"

namespace partet {
namespace {

// Grid coordinate of the cell [g, g+1) holding x along one axis: a first
// guess in floating point, corrected by exact comparisons with the cell
// bounds (lattice points, exactly representable), clamped to the root.
uint32_t grid_cell(double x, double origin, double unit) {
  const int64_t last = int64_t{kGridSize} - 1;
  auto bound = [&](int64_t g) { return origin + static_cast<double>(2 * g) * (0.5 * unit); };
  double guess = std::floor((x - origin) / unit);
  int64_t g = !(guess > 0)                         ? 0
              : guess >= static_cast<double>(last) ? last
                                                   : static_cast<int64_t>(guess);
  while (g > 0 && x < bound(g)) --g;
  while (g < last && x >= bound(g + 1)) ++g;
  return static_cast<uint32_t>(g);
}

// Appends the core's exposed faces, oriented away from their tets.
void add_core_faces(const LinearOctree& tree, const TemplateCore& core,
                    std::vector<uint32_t>& faces) {
  for (size_t i = 0; i < tree.size(); ++i) {
    if (tree.cls[i] != LeafClass::kInterior) continue;
    for_each_exposed_face(tree, core, i, [&](uint32_t, const uint32_t* v) {
      faces.insert(faces.end(), {v[0], v[2], v[1]});
    });
  }
}

}  // namespace

void list_front_vertices(InitialFront& front, size_t leaves) {
  const size_t n = front.vertex_leaf.size();
  std::vector<char> listed(n, 0);
  for (uint32_t v : front.faces) listed[v] = 1;
  std::fill(listed.end() - static_cast<std::ptrdiff_t>(front.free_vertices), listed.end(), 1);
  front.leaf_first_front_vertex.assign(leaves + 1, 0);
  for (size_t v = 0; v < n; ++v)
    if (listed[v]) ++front.leaf_first_front_vertex[front.vertex_leaf[v] + 1];
  for (size_t i = 0; i < leaves; ++i) front.leaf_first_front_vertex[i + 1] += front.leaf_first_front_vertex[i];
  front.front_vertices.resize(front.leaf_first_front_vertex[leaves]);
  std::vector<uint32_t> next(front.leaf_first_front_vertex.begin(), front.leaf_first_front_vertex.end() - 1);
  for (size_t v = 0; v < n; ++v)
    if (listed[v]) front.front_vertices[next[front.vertex_leaf[v]]++] = static_cast<uint32_t>(v);
}

uint32_t leaf_of_point(const LinearOctree& tree, const RootCube& root, const double* p) {
  uint32_t g[3];
  for (int k = 0; k < 3; ++k) g[k] = grid_cell(p[k], root.origin[k], root.unit);
  return static_cast<uint32_t>(tree.locate(g[0], g[1], g[2]));
}

InitialFront make_initial_front(const LinearOctree& tree, const RootCube& root,
                                const TemplateCore& core, const SurfaceMesh& surface) {
  InitialFront front;
  const size_t nc = core.mesh.num_vertices();
  const size_t ns = surface.num_vertices();
  PARTET_ASSERT(nc + ns < UINT32_MAX, "more than 2^32 - 1 front vertices");
  front.core_vertices = nc;
  front.xyz.reserve(3 * (nc + ns));
  front.xyz.assign(core.mesh.xyz.begin(), core.mesh.xyz.end());
  front.xyz.insert(front.xyz.end(), surface.xyz.begin(), surface.xyz.end());
  front.global_ids.reserve(nc + ns);
  front.global_ids.assign(core.mesh.global_ids.begin(), core.mesh.global_ids.end());
  for (size_t s = 0; s < ns; ++s) front.global_ids.push_back(kSurfaceVertexId | s);

  front.vertex_leaf.resize(nc + ns);
  for (size_t i = 0; i < tree.size(); ++i)
    std::fill(front.vertex_leaf.begin() + core.leaf_first_vertex[i],
              front.vertex_leaf.begin() + core.leaf_first_vertex[i + 1], static_cast<uint32_t>(i));
  for (size_t s = 0; s < ns; ++s)
    front.vertex_leaf[nc + s] = leaf_of_point(tree, root, surface.point(s));

  front.faces.reserve(surface.tris.size());
  const uint32_t offset = static_cast<uint32_t>(nc);
  for (size_t t = 0; t < surface.num_triangles(); ++t) {
    const uint32_t* v = &surface.tris[3 * t];
    PARTET_ASSERT(v[0] < ns && v[1] < ns && v[2] < ns,
                  "surface triangle " + std::to_string(t) + " has a vertex index out of range");
    front.faces.insert(front.faces.end(), {offset + v[0], offset + v[2], offset + v[1]});
  }
  front.surface_faces = surface.num_triangles();
  add_core_faces(tree, core, front.faces);

  list_front_vertices(front, tree.size());
  return front;
}

void add_free_vertices(InitialFront& front, const LinearOctree& tree, const std::vector<double>& xyz,
                       const std::vector<uint64_t>& ids, const std::vector<uint32_t>& leaf) {
  const size_t n = leaf.size();
  PARTET_ASSERT(xyz.size() == 3 * n && ids.size() == n, "free vertex arrays disagree");
  PARTET_ASSERT(front.vertex_leaf.size() + n < UINT32_MAX, "more than 2^32 - 1 front vertices");
  for (uint32_t i : leaf) PARTET_ASSERT(i < tree.size(), "free vertex leaf out of range");
  front.xyz.insert(front.xyz.end(), xyz.begin(), xyz.end());
  front.global_ids.insert(front.global_ids.end(), ids.begin(), ids.end());
  front.vertex_leaf.insert(front.vertex_leaf.end(), leaf.begin(), leaf.end());
  front.free_vertices += n;
  list_front_vertices(front, tree.size());
}

SurfaceMesh front_surface(const InitialFront& front) {
  SurfaceMesh mesh;
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> index(front.xyz.size() / 3, kUnused);
  for (uint32_t v : front.faces) index[v] = 0;
  uint32_t count = 0;
  for (size_t v = 0; v < index.size(); ++v) {
    if (index[v] == kUnused) continue;
    index[v] = count++;
    mesh.xyz.insert(mesh.xyz.end(), &front.xyz[3 * v], &front.xyz[3 * v] + 3);
  }
  mesh.tris.reserve(front.faces.size());
  for (uint32_t v : front.faces) mesh.tris.push_back(index[v]);
  return mesh;
}

}  // namespace partet
