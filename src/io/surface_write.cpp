// Surface writers (see surface_write.hpp).
#include "io/surface_write.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "io/text_writer.hpp"

namespace partet {

namespace {

void append_point(std::string& out, const double* p) {
  for (int i = 0; i < 3; ++i) {
    if (i) out += ' ';
    append_real(out, p[i]);
  }
}

template <class T>
void append_le(std::string& out, T v) {
  static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

}  // namespace

std::string format_off(const SurfaceMesh& s) {
  std::string out = "OFF\n";
  append_uint(out, s.num_vertices());
  out += ' ';
  append_uint(out, s.num_triangles());
  out += " 0\n";
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    append_point(out, s.point(v));
    out += '\n';
  }
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    out += '3';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_uint(out, s.tris[3 * t + k]);
    }
    out += '\n';
  }
  return out;
}

std::string format_obj(const SurfaceMesh& s) {
  std::string out = "# written by partet\n";
  for (size_t v = 0; v < s.num_vertices(); ++v) {
    out += "v ";
    append_point(out, s.point(v));
    out += '\n';
  }
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_uint(out, uint64_t{s.tris[3 * t + k]} + 1);
    }
    out += '\n';
  }
  return out;
}

std::string format_stl_ascii(const SurfaceMesh& s) {
  std::string out = "solid partet\n";
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    const double* a = s.point(s.tris[3 * t]);
    const double* b = s.point(s.tris[3 * t + 1]);
    const double* c = s.point(s.tris[3 * t + 2]);
    double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                   (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                   (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = len > 0 ? x / len : 0.0;
    out += "facet normal ";
    append_point(out, n);
    out += "\n outer loop\n";
    for (const double* p : {a, b, c}) {
      out += "  vertex ";
      append_point(out, p);
      out += '\n';
    }
    out += " endloop\nendfacet\n";
  }
  out += "endsolid partet\n";
  return out;
}

std::string format_ply_binary(const SurfaceMesh& s) {
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by partet\nelement vertex " +
                    std::to_string(s.num_vertices()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(s.num_triangles()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  out.reserve(out.size() + 24 * s.num_vertices() + 13 * s.num_triangles());
  for (double c : s.xyz) append_le(out, c);
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    append_le(out, uint8_t{3});
    for (int k = 0; k < 3; ++k) append_le(out, s.tris[3 * t + k]);
  }
  return out;
}

}  // namespace partet
