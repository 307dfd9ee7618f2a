// The cone alternative (see cone_alternative.hpp).
#include "pipeline/cone_alternative.hpp"

#include <utility>
#include <vector>

#include "core/compact_mesh.hpp"
#include "core/kernel_point.hpp"
#include "core/predicates.hpp"
#include "pipeline/mesh_alternative.hpp"

namespace partet {

bool cone_mesh(const TetMesh& mesh, TetMesh& cone) {
  const size_t n = mesh.num_triangles();
  if (n == 0) return false;
  // The kernel's side of a triangle is where orient3d(a, b, c, q) > 0: the
  // outward triangles go in reversed.
  std::vector<double> triangles;
  triangles.reserve(9 * n);
  for (size_t t = 0; t < n; ++t)
    for (int k : {0, 2, 1}) {
      const double* p = mesh.point(mesh.tris[3 * t + k]);
      triangles.insert(triangles.end(), p, p + 3);
    }
  const KernelPoint kernel = deepest_kernel_point(triangles);
  if (!kernel.found || !(kernel.depth > 0)) return false;
  for (size_t t = 0; t < n; ++t) {
    const uint32_t* v = &mesh.tris[3 * t];
    if (orient3d(mesh.point(v[0]), mesh.point(v[2]), mesh.point(v[1]), kernel.point) <= 0) return false;
  }
  cone = TetMesh{};
  cone.xyz = mesh.xyz;
  cone.xyz.insert(cone.xyz.end(), kernel.point, kernel.point + 3);
  const auto apex = static_cast<uint32_t>(mesh.num_vertices());
  cone.tets.reserve(4 * n);
  for (size_t t = 0; t < n; ++t) {
    const uint32_t* v = &mesh.tris[3 * t];
    cone.tets.insert(cone.tets.end(), {v[0], v[2], v[1], apex});
  }
  cone.tris = mesh.tris;
  drop_unused_vertices(cone);
  return true;
}

nlohmann::ordered_json try_cone_alternative(TetMesh& mesh, QualityStats& quality,
                                            const OptimizeOptions& options) {
  nlohmann::ordered_json c;
  TetMesh cone;
  if (mesh.num_triangles() > kConeTriangles || !cone_mesh(mesh, cone)) {
    c["star-shaped"] = false;
    return c;
  }
  c["star-shaped"] = true;
  c.update(keep_better_alternative(mesh, std::move(cone), quality, options));
  return c;
}

}  // namespace partet
