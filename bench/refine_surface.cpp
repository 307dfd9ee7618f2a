// refine_surface IN OUT ROUNDS: splits every triangle of a surface into four
// (edge midpoints) ROUNDS times: the same shape with 4^ROUNDS times the
// triangles. Benchmarks use it to make large inputs from the corpus.
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "surface/midpoint_refine.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: refine_surface IN OUT ROUNDS\n");
    return 2;
  }
  try {
    partet::SurfaceMesh s = partet::read_surface_file(argv[1]);
    for (int r = std::atoi(argv[3]); r > 0; --r) s = partet::refine_midpoints(s);
    partet::write_surface_file(s, argv[2], {});
    std::printf("%zu\n", s.num_triangles());
  } catch (const partet::Error& e) {
    std::fprintf(stderr, "refine_surface: %s\n", e.what());
    return e.exit_code();
  }
  return 0;
}
