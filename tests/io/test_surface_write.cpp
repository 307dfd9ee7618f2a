// Surface writers: every format reads back to the same triangles with
// bit-identical coordinates.
#include <gtest/gtest.h>

#include "io/mesh_file.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

TEST(SurfaceWrite, EveryFormatRoundTripsExactly) {
  SurfaceMesh s = test::box_surface(1.0 / 3.0, 1e-300, 12345.678901234567);
  s.xyz[0] = -0.1;
  s.xyz[4] = 5e-324;
  std::string dir = test::scratch_dir("surface_write");
  for (const char* ext : {"off", "obj", "stl", "ply", "mesh", "msh"}) {
    SCOPED_TRACE(ext);
    std::string path = dir + "/box." + ext;
    write_surface_file(s, path, {});
    SurfaceMesh back = read_surface_file(path);
    ASSERT_EQ(back.num_triangles(), s.num_triangles());
    // STL stores corners per triangle (vertices are merged on reading):
    // compare triangle corner coordinates, which every format must keep.
    for (size_t t = 0; t < s.num_triangles(); ++t)
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(back.point(back.tris[3 * t + k])[i], s.point(s.tris[3 * t + k])[i]);
  }
}

TEST(SurfaceWrite, AsciiGmshToo) {
  SurfaceMesh s = test::box_surface();
  std::string path = test::scratch_dir("surface_write_ascii") + "/box.msh";
  write_surface_file(s, path, {.ascii = true});
  EXPECT_EQ(test::read_text(path).substr(0, 11), "$MeshFormat");
  EXPECT_EQ(read_surface_file(path).tris, s.tris);
}

}  // namespace
}  // namespace partet
