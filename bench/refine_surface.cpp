// refine_surface IN OUT ROUNDS: splits every triangle of a surface into four
// (edge midpoints) ROUNDS times: the same shape with 4^ROUNDS times the
// triangles. Benchmarks use it to make large inputs from the corpus.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "io/mesh_file.hpp"

namespace {

partet::SurfaceMesh refine(const partet::SurfaceMesh& in) {
  partet::SurfaceMesh out;
  out.xyz = in.xyz;
  std::unordered_map<uint64_t, uint32_t> midpoint;
  auto mid = [&](uint32_t a, uint32_t b) {
    uint64_t key = a < b ? (uint64_t{a} << 32 | b) : (uint64_t{b} << 32 | a);
    auto [it, fresh] = midpoint.try_emplace(key, static_cast<uint32_t>(out.num_vertices()));
    if (fresh)
      for (int i = 0; i < 3; ++i) out.xyz.push_back(0.5 * (in.xyz[3 * size_t{a} + i] + in.xyz[3 * size_t{b} + i]));
    return it->second;
  };
  for (size_t t = 0; t < in.num_triangles(); ++t) {
    uint32_t a = in.tris[3 * t], b = in.tris[3 * t + 1], c = in.tris[3 * t + 2];
    uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.tris.insert(out.tris.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: refine_surface IN OUT ROUNDS\n");
    return 2;
  }
  try {
    partet::SurfaceMesh s = partet::read_surface_file(argv[1]);
    for (int r = std::atoi(argv[3]); r > 0; --r) s = refine(s);
    partet::write_surface_file(s, argv[2], {});
    std::printf("%zu\n", s.num_triangles());
  } catch (const partet::Error& e) {
    std::fprintf(stderr, "refine_surface: %s\n", e.what());
    return e.exit_code();
  }
  return 0;
}
