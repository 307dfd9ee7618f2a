// Deepest kernel point of front faces (see kernel_point.hpp).
#include "front/kernel_point.hpp"

namespace partet {

KernelPoint deepest_kernel_point(const Front& front, const std::vector<uint32_t>& faces, const double* lift) {
  std::vector<double> triangles;
  triangles.reserve(9 * faces.size());
  for (uint32_t f : faces)
    for (int i = 0; i < 3; ++i) {
      const double* p = front.point(front.face(f)[i]);
      triangles.insert(triangles.end(), p, p + 3);
    }
  return deepest_kernel_point(triangles, lift);
}

}  // namespace partet
