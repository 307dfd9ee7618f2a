// make_boundary_front: the faces of the initial front on the ranks owning
// their leaves (see boundary_front.hpp).
#include "partition/boundary_front.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/expansion.hpp"
#include "front/initial_front.hpp"
#include "templates/exposed_faces.hpp"

namespace partet {
namespace {

// Sign of (a + b + c) / 3 - x, exactly.
int centroid_side(double a, double b, double c, double x) {
  return (exact::exact_difference(a, x) + exact::exact_difference(b, x) + exact::exact_difference(c, x)).sign();
}

// The grid cell [g, g + 1) holding the centroid of a, b, c along one axis:
// a guess in floating point, corrected by exact comparisons with the cell
// bounds (lattice points, exactly representable), clamped to the root.
uint32_t centroid_cell(double a, double b, double c, double origin, double unit) {
  const int64_t last = int64_t{kGridSize} - 1;
  auto bound = [&](int64_t g) { return origin + static_cast<double>(2 * g) * (0.5 * unit); };
  const double guess = std::floor(((a + b + c) / 3.0 - origin) / unit);
  int64_t g = !(guess > 0) ? 0 : guess >= static_cast<double>(last) ? last : static_cast<int64_t>(guess);
  while (g > 0 && centroid_side(a, b, c, bound(g)) < 0) --g;
  while (g < last && centroid_side(a, b, c, bound(g + 1)) >= 0) ++g;
  return static_cast<uint32_t>(g);
}

// The faces this rank makes, with the rank of their leaf, and the vertices
// they use: the core part's vertices, then the surface's (compacted later
// by migrate_faces, which sends only used vertices).
struct Made {
  FaceBatch batch;
  std::vector<int32_t> destination;
};

// The exposed triangles of this rank's interior leaves, each given to the
// leaf across it (templates/exposed_faces.hpp, as make_initial_front).
void add_core_faces(const LinearOctree& view, const TemplateCore& core, int rank, Made& made) {
  for (size_t i = 0; i < view.size(); ++i) {
    if (view.owner[i] != rank || view.cls[i] != LeafClass::kInterior) continue;
    for_each_exposed_face(view, core, i, [&](uint32_t other, const uint32_t* v) {
      PARTET_ASSERT(other != kAbsentLeaf, "an interior leaf touches the root cube's boundary");
      PARTET_ASSERT(front_leaf_class(view.cls[other]) && view.owner[other] >= 0,
                    "a core face lies against a leaf that is neither boundary nor too close, or unknown here");
      made.batch.leaf_key.push_back(view.key[other]);
      made.batch.faces.insert(made.batch.faces.end(), {v[0], v[2], v[1]});
      made.destination.push_back(view.owner[other]);
    });
  }
}

// The reversed surface triangles whose centroid lies in an own leaf.
void add_surface_faces(const LinearOctree& view, const RootCube& root, const SurfaceMesh& surface, int rank,
                       uint32_t first_vertex, Made& made) {
  for (size_t t = 0; t < surface.num_triangles(); ++t) {
    const uint32_t* v = &surface.tris[3 * t];
    const size_t leaf = leaf_of_centroid(view, root, surface.point(v[0]), surface.point(v[1]), surface.point(v[2]));
    if (view.owner[leaf] != rank) continue;
    PARTET_ASSERT(view.cls[leaf] == LeafClass::kBoundary,
                  "surface triangle " + std::to_string(t) + " has its centroid in a leaf that is not boundary");
    made.batch.leaf_key.push_back(view.key[leaf]);
    made.batch.faces.insert(made.batch.faces.end(), {first_vertex + v[0], first_vertex + v[2], first_vertex + v[1]});
    made.destination.push_back(rank);
  }
}

}  // namespace

size_t leaf_of_centroid(const LinearOctree& tree, const RootCube& root, const double* a, const double* b,
                        const double* c) {
  uint32_t g[3];
  for (int k = 0; k < 3; ++k) g[k] = centroid_cell(a[k], b[k], c[k], root.origin[k], root.unit);
  return tree.locate(g[0], g[1], g[2]);
}

FrontPart make_boundary_front(const Comm& comm, const LinearOctree& view, const TemplateCore& core,
                              const RootCube& root, const SurfaceMesh& surface, MigrationBytes* bytes) {
  const int rank = comm.rank();
  const size_t nc = core.mesh.num_vertices(), ns = surface.num_vertices();
  PARTET_ASSERT(nc + ns < UINT32_MAX, "more than 2^32 - 1 front vertices on one rank");
  Made made;
  made.batch.global_ids = core.mesh.global_ids;
  made.batch.xyz = core.mesh.xyz;
  for (size_t s = 0; s < ns; ++s) made.batch.global_ids.push_back(kSurfaceVertexId | s);
  made.batch.xyz.insert(made.batch.xyz.end(), surface.xyz.begin(), surface.xyz.end());
  add_core_faces(view, core, rank, made);
  add_surface_faces(view, root, surface, rank, static_cast<uint32_t>(nc), made);
  const FaceBatch mine = migrate_faces(comm, made.batch, made.destination, bytes);

  LinearOctree leaves;
  for (size_t i = 0; i < view.size(); ++i) {
    if (view.owner[i] != rank || !front_leaf_class(view.cls[i])) continue;
    leaves.key.push_back(view.key[i]);
    leaves.level.push_back(view.level[i]);
    leaves.cls.push_back(view.cls[i]);
  }
  return assemble_front_part(std::move(leaves), mine, rank);
}

}  // namespace partet
