// refine_midpoints (see midpoint_refine.hpp).
#include "surface/midpoint_refine.hpp"

#include <cstdint>
#include <unordered_map>

namespace partet {

SurfaceMesh refine_midpoints(const SurfaceMesh& in) {
  SurfaceMesh out;
  out.xyz = in.xyz;
  std::unordered_map<uint64_t, uint32_t> midpoint;
  auto mid = [&](uint32_t a, uint32_t b) {
    const uint64_t key = a < b ? (uint64_t{a} << 32 | b) : (uint64_t{b} << 32 | a);
    auto [it, fresh] = midpoint.try_emplace(key, static_cast<uint32_t>(out.num_vertices()));
    if (fresh)
      for (int i = 0; i < 3; ++i) out.xyz.push_back(0.5 * (in.xyz[3 * size_t{a} + i] + in.xyz[3 * size_t{b} + i]));
    return it->second;
  };
  for (size_t t = 0; t < in.num_triangles(); ++t) {
    const uint32_t a = in.tris[3 * t], b = in.tris[3 * t + 1], c = in.tris[3 * t + 2];
    const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.tris.insert(out.tris.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return out;
}

}  // namespace partet
