// Wavefront OBJ reader: `v x y z [w]` vertices (extra values such as colours
// are skipped) and `f` faces whose corners are `a`, `a/b`, `a//c` or `a/b/c`
// with 1-based indices, or negative ones counting back from the last vertex
// read. Every other statement (vt, vn, g, o, s, usemtl, mtllib, l, p, and
// unknown ones) is ignored. '#' starts a comment; a line ending in a backslash
// continues on the next one. Index 0 and indices outside the vertices read so
// far are refused with the line; faces that are not triangles are all counted
// and refused in one error naming the first ones.
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "io/polygon_faces.hpp"
#include "io/surface_formats.hpp"
#include "io/text_cursor.hpp"

namespace partet {

namespace {

constexpr size_t kMaxTokens = 5;

class ObjReader {
 public:
  ObjReader(std::string_view bytes, const std::string& file) : c_(bytes, file, '#'), file_(file) {}

  SurfaceMesh read() {
    std::string_view line;
    while (next_statement(line)) {
      std::string_view tok[kMaxTokens];
      size_t n = split_tokens(line, tok, kMaxTokens);
      if (n == 0) continue;
      if (tok[0] == "v") {
        vertex(tok, n);
      } else if (tok[0] == "f") {
        face(line.substr(static_cast<size_t>(tok[0].data() - line.data()) + 1));
      }
    }
    polygons_.check();
    if (mesh_.tris.empty())
      throw InputError(file_ + ": no triangles (the file has no 'f' statements)");
    return std::move(mesh_);
  }

 private:
  // The next statement, joining lines that end in a backslash.
  bool next_statement(std::string_view& out) {
    if (!c_.line(out)) return false;
    line_ = c_.line_number();
    if (out.empty() || out.back() != '\\') return true;
    joined_.assign(out.substr(0, out.size() - 1));
    std::string_view more;
    while (c_.line(more)) {
      joined_ += ' ';
      if (more.empty() || more.back() != '\\') {
        joined_ += more;
        break;
      }
      joined_ += more.substr(0, more.size() - 1);
    }
    out = joined_;
    return true;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_ + ":" + std::to_string(line_) + ": " + message);
  }

  void vertex(const std::string_view* tok, size_t n) {
    if (n < 4) fail("vertex " + std::to_string(mesh_.num_vertices()) + " has fewer than 3 coordinates");
    if (mesh_.num_vertices() >= UINT32_MAX) fail("more than 4294967295 vertices");
    for (int i = 1; i <= 3; ++i) {
      double x = 0;
      if (!parse_real(tok[i], x))
        fail("vertex " + std::to_string(mesh_.num_vertices()) + ": expected a coordinate, found '" +
             std::string(tok[i].substr(0, 40)) + "'");
      mesh_.xyz.push_back(x);
    }
  }

  // One corner `a[/b[/c]]`: the 0-based index of vertex a.
  uint32_t corner(std::string_view token) const {
    std::string_view a = token.substr(0, token.find('/'));
    int64_t index = 0;
    if (!parse_integer(a, index))
      fail("face " + std::to_string(faces_) + ": expected a vertex index, found '" +
           std::string(token.substr(0, 40)) + "'");
    int64_t nv = static_cast<int64_t>(mesh_.num_vertices());
    if (index == 0) fail("face " + std::to_string(faces_) + ": vertex index 0 (OBJ indices start at 1)");
    int64_t resolved = index > 0 ? index - 1 : nv + index;
    if (resolved < 0 || resolved >= nv)
      fail("face " + std::to_string(faces_) + ": vertex index " + std::to_string(index) +
           " is out of range (" + std::to_string(nv) + " vertices read so far)");
    return static_cast<uint32_t>(resolved);
  }

  void face(std::string_view corners) {
    uint32_t v[3] = {0, 0, 0};
    uint64_t n = 0;
    size_t i = 0;
    while (i < corners.size()) {
      std::string_view tok[1];
      if (split_tokens(corners.substr(i), tok, 1) == 0) break;
      i = static_cast<size_t>(tok[0].data() - corners.data()) + tok[0].size();
      uint32_t index = corner(tok[0]);
      if (n < 3) v[n] = index;
      ++n;
    }
    if (n == 3) {
      mesh_.tris.insert(mesh_.tris.end(), v, v + 3);
    } else {
      polygons_.add(faces_, n, file_ + ":" + std::to_string(line_), "line " + std::to_string(line_));
    }
    ++faces_;
  }

  TextCursor c_;
  const std::string& file_;
  SurfaceMesh mesh_;
  PolygonFaces polygons_;
  std::string joined_;
  size_t line_ = 0;
  size_t faces_ = 0;
};

}  // namespace

SurfaceMesh parse_obj(std::string_view bytes, const std::string& file) {
  return ObjReader(bytes, file).read();
}

}  // namespace partet
