// OFF reader. The header keyword is [ST][C][N]OFF (optional, as in
// Geomview's definition), followed on the same or the next line by the
// vertex, face and (optional, ignored) edge counts. '#' starts a comment
// anywhere. Records are read line by line: a vertex line gives its first 3
// numbers (colours, normals, texture coordinates that follow are skipped), a
// face line gives its vertex count n and n indices (a trailing colour is
// skipped). Faces that are not triangles are all counted and refused in one
// error naming the first ones; indices out of range are refused with the face
// and its line. Counts are checked against the file size before allocating.
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "io/polygon_faces.hpp"
#include "io/surface_formats.hpp"
#include "io/text_cursor.hpp"

namespace partet {

namespace {

// Bytes a record needs at least: "0 0 0\n" for a vertex, "3\n" for a face,
// "3 0 1 2\n" for a triangle.
constexpr uint64_t kMinVertexBytes = 6;
constexpr uint64_t kMinFaceBytes = 2;
constexpr uint64_t kMinTriangleBytes = 8;
constexpr size_t kMaxTokens = 8;

// The next line that holds a token, split into at most kMaxTokens tokens.
size_t next_record(TextCursor& c, std::string_view* tokens) {
  std::string_view line;
  while (c.line(line)) {
    size_t n = split_tokens(line, tokens, kMaxTokens);
    if (n > 0) return n;
  }
  return 0;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// Checks an [ST][C][N]OFF header keyword; refuses 4D, nD and binary OFF.
void check_keyword(TextCursor& c, std::string_view keyword, std::string_view next) {
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.starts_with("ST")) prefix.remove_prefix(2);
  if (prefix.starts_with("C")) prefix.remove_prefix(1);
  if (prefix.starts_with("N")) prefix.remove_prefix(1);
  if (prefix.starts_with("4") || prefix.starts_with("n"))
    c.fail("header '" + std::string(keyword) +
           "': only 3-dimensional OFF is supported (no '4' or 'n' prefix)");
  if (!prefix.empty()) c.fail("unknown OFF header keyword '" + std::string(keyword.substr(0, 40)) + "'");
  if (next == "BINARY") c.fail("binary OFF is not supported; write it as text OFF");
}

uint64_t header_count(TextCursor& c, std::string_view token, const char* what, uint64_t limit) {
  int64_t v = 0;
  if (!parse_integer(token, v))
    c.fail(std::string("expected the ") + what + " count, found '" +
           std::string(token.substr(0, 40)) + "'");
  if (v < 0) c.fail(std::string(what) + " count is negative (" + std::to_string(v) + ")");
  if (static_cast<uint64_t>(v) > limit)
    c.fail(std::string(what) + " count " + std::to_string(v) + " is more than the file can hold (" +
           std::to_string(c.size()) + " bytes)");
  return static_cast<uint64_t>(v);
}

}  // namespace

SurfaceMesh parse_off(std::string_view bytes, const std::string& file) {
  TextCursor c(bytes, file, '#');
  std::string_view tok[kMaxTokens];
  size_t n = next_record(c, tok);
  if (n == 0) c.fail("empty file, expected an OFF header");
  size_t first = 0;
  if (ends_with(tok[0], "OFF")) {
    check_keyword(c, tok[0], n > 1 ? tok[1] : std::string_view());
    first = 1;
    if (n < 3) {
      n = next_record(c, tok);
      first = 0;
      if (n == 0) c.fail("unexpected end of file, expected the vertex and face counts");
    }
  }
  if (n - first < 2) c.fail("expected the vertex and face counts on one line");
  uint64_t left = c.size() - c.offset() + 1;
  uint64_t nv = header_count(c, tok[first], "vertex", std::min<uint64_t>(left / kMinVertexBytes, UINT32_MAX));
  uint64_t nf = header_count(c, tok[first + 1], "face", left / kMinFaceBytes);

  SurfaceMesh mesh;
  mesh.xyz.resize(3 * nv);
  for (uint64_t v = 0; v < nv; ++v) {
    n = next_record(c, tok);
    if (n == 0)
      c.fail("unexpected end of file, expected vertex " + std::to_string(v) + " of " +
             std::to_string(nv));
    if (n < 3) c.fail("vertex " + std::to_string(v) + " has fewer than 3 coordinates");
    for (int i = 0; i < 3; ++i)
      if (!parse_real(tok[i], mesh.xyz[3 * v + i]))
        c.fail("vertex " + std::to_string(v) + ": expected a coordinate, found '" +
               std::string(tok[i].substr(0, 40)) + "'");
  }

  mesh.tris.reserve(3 * std::min(nf, left / kMinTriangleBytes));
  PolygonFaces polygons;
  for (uint64_t f = 0; f < nf; ++f) {
    n = next_record(c, tok);
    if (n == 0)
      c.fail("unexpected end of file, expected face " + std::to_string(f) + " of " +
             std::to_string(nf));
    int64_t k = 0;
    if (!parse_integer(tok[0], k) || k < 0)
      c.fail("face " + std::to_string(f) + ": expected its vertex count, found '" +
             std::string(tok[0].substr(0, 40)) + "'");
    if (k != 3) {
      polygons.add(f, static_cast<uint64_t>(k), file + ":" + std::to_string(c.line_number()),
                   "line " + std::to_string(c.line_number()));
      continue;
    }
    if (n < 4) c.fail("face " + std::to_string(f) + " lists fewer than its 3 vertices");
    for (int i = 1; i <= 3; ++i) {
      int64_t index = 0;
      if (!parse_integer(tok[i], index))
        c.fail("face " + std::to_string(f) + ": expected a vertex index, found '" +
               std::string(tok[i].substr(0, 40)) + "'");
      if (index < 0 || static_cast<uint64_t>(index) >= nv)
        c.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(index) +
               " is out of range (the file has " + std::to_string(nv) + " vertices)");
      mesh.tris.push_back(static_cast<uint32_t>(index));
    }
  }
  polygons.check();
  if (mesh.tris.empty()) c.fail("no triangles (the header says 0 faces)");
  return mesh;
}

}  // namespace partet
