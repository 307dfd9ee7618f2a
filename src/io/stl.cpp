// STL reader, ASCII and binary, told apart by content: a file is binary when
// its size is exactly 84 + 50 * N (N = the uint32 at byte 80), even if it
// starts with "solid"; anything else must be ASCII STL (solid / facet normal /
// outer loop / 3 x vertex / endloop / endfacet / endsolid, keywords in any
// case, any number of solids). Binary float32 coordinates convert to double
// exactly. Vertices with bitwise-equal coordinates (-0.0 equal to +0.0) are
// merged and numbered by first appearance, so the result is deterministic.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/byte_cursor.hpp"
#include "io/surface_formats.hpp"
#include "io/text_cursor.hpp"

namespace partet {

namespace {

constexpr uint64_t kHeaderBytes = 84;
constexpr uint64_t kFacetBytes = 50;

// Merges vertices with equal coordinates into `mesh`: an open-addressing
// table of vertex ids, hashed and compared on the coordinates' bits.
class VertexMerger {
 public:
  VertexMerger(SurfaceMesh& mesh, const std::string& file, size_t expected)
      : mesh_(mesh), file_(file) {
    size_t slots = 1024;
    while (slots < 2 * expected) slots *= 2;
    slots_.assign(slots, kEmpty);
  }

  uint32_t add(const double p[3]) {
    const uint64_t key[3] = {bits(p[0]), bits(p[1]), bits(p[2])};
    size_t mask = slots_.size() - 1;
    for (size_t s = hash(key) & mask;; s = (s + 1) & mask) {
      uint32_t v = slots_[s];
      if (v == kEmpty) return insert(s, p);
      const double* q = mesh_.point(v);
      if (bits(q[0]) == key[0] && bits(q[1]) == key[1] && bits(q[2]) == key[2]) return v;
    }
  }

 private:
  static constexpr uint32_t kEmpty = UINT32_MAX;

  // The bits of a coordinate, with -0.0 read as +0.0.
  static uint64_t bits(double x) { return std::bit_cast<uint64_t>(x == 0.0 ? 0.0 : x); }

  static uint64_t hash(const uint64_t key[3]) {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < 3; ++i) {
      h ^= key[i] + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xbf58476d1ce4e5b9ull;
      h ^= h >> 31;
    }
    return h;
  }

  uint32_t insert(size_t slot, const double p[3]) {
    size_t n = mesh_.num_vertices();
    if (n >= kEmpty - 1) throw InputError(file_ + ": more than 4294967294 distinct vertices");
    mesh_.xyz.insert(mesh_.xyz.end(), p, p + 3);
    slots_[slot] = static_cast<uint32_t>(n);
    if (2 * (n + 1) > slots_.size()) grow();
    return static_cast<uint32_t>(n);
  }

  void grow() {
    slots_.assign(2 * slots_.size(), kEmpty);
    size_t mask = slots_.size() - 1;
    for (size_t v = 0; v < mesh_.num_vertices(); ++v) {
      const double* q = mesh_.point(v);
      const uint64_t key[3] = {bits(q[0]), bits(q[1]), bits(q[2])};
      size_t s = hash(key) & mask;
      while (slots_[s] != kEmpty) s = (s + 1) & mask;
      slots_[s] = static_cast<uint32_t>(v);
    }
  }

  SurfaceMesh& mesh_;
  const std::string& file_;
  std::vector<uint32_t> slots_;
};

bool is_text_byte(unsigned char c) {
  return c >= 0x20 ? c != 0x7f : (c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f');
}

bool looks_like_text(std::string_view bytes) {
  for (char c : bytes)
    if (!is_text_byte(static_cast<unsigned char>(c))) return false;
  return true;
}

bool keyword_is(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (size_t i = 0; i < token.size(); ++i) {
    char c = token[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != keyword[i]) return false;
  }
  return true;
}

std::string quoted(std::string_view token) {
  return "'" + std::string(token.substr(0, 40)) + (token.size() > 40 ? "...'" : "'");
}

void expect_keyword(TextCursor& c, const char* keyword, size_t facet) {
  std::string what = std::string("'") + keyword + "'";
  std::string_view t = c.token(what.c_str());
  if (keyword_is(t, keyword)) return;
  if (keyword_is(keyword, "endloop") && keyword_is(t, "vertex"))
    c.fail("facet " + std::to_string(facet) +
           " has more than 3 vertices; partet meshes triangle surfaces only");
  c.fail("facet " + std::to_string(facet) + ": expected " + what + ", found " + quoted(t));
}

SurfaceMesh parse_ascii(std::string_view bytes, const std::string& file) {
  TextCursor c(bytes, file);
  SurfaceMesh mesh;
  VertexMerger merger(mesh, file, 0);
  std::string_view rest;
  size_t facet = 0;
  if (!c.has_token()) c.fail("empty file, expected 'solid'");
  while (c.has_token()) {
    std::string_view t = c.token("'solid'");
    if (!keyword_is(t, "solid")) c.fail("expected 'solid', found " + quoted(t));
    c.line(rest);  // the solid's name
    for (;;) {
      t = c.token("'facet' or 'endsolid'");
      if (keyword_is(t, "endsolid")) break;
      if (!keyword_is(t, "facet")) c.fail("expected 'facet' or 'endsolid', found " + quoted(t));
      expect_keyword(c, "normal", facet);
      for (int i = 0; i < 3; ++i) c.real("a normal coordinate");
      expect_keyword(c, "outer", facet);
      expect_keyword(c, "loop", facet);
      for (int k = 0; k < 3; ++k) {
        expect_keyword(c, "vertex", facet);
        double p[3];
        for (double& x : p) x = c.real("a vertex coordinate");
        mesh.tris.push_back(merger.add(p));
      }
      expect_keyword(c, "endloop", facet);
      expect_keyword(c, "endfacet", facet);
      ++facet;
    }
    c.line(rest);  // the name after endsolid
  }
  if (mesh.tris.empty()) c.fail("no triangles (the file has no facets)");
  return mesh;
}

SurfaceMesh parse_binary(std::string_view bytes, const std::string& file, uint32_t count) {
  ByteCursor c(bytes, file, kHeaderBytes);
  if (count == 0) c.fail("no triangles (the binary STL header says 0 facets)");
  c.need(count, kFacetBytes, "facets");
  SurfaceMesh mesh;
  mesh.tris.reserve(3 * static_cast<size_t>(count));
  VertexMerger merger(mesh, file, count);
  for (uint32_t t = 0; t < count; ++t) {
    c.skip(12, "facet normal");
    for (int k = 0; k < 3; ++k) {
      double p[3];
      for (double& x : p) x = static_cast<double>(c.read<float>("vertex coordinate"));
      mesh.tris.push_back(merger.add(p));
    }
    c.skip(2, "facet attribute");
  }
  return mesh;
}

}  // namespace

SurfaceMesh parse_stl(std::string_view bytes, const std::string& file) {
  uint64_t count = 0;
  if (bytes.size() >= kHeaderBytes) {
    ByteCursor header(bytes, file, 80);
    count = header.read<uint32_t>("facet count");
    if (bytes.size() == kHeaderBytes + kFacetBytes * count)
      return parse_binary(bytes, file, static_cast<uint32_t>(count));
  }
  try {
    return parse_ascii(bytes, file);
  } catch (const InputError&) {
    if (looks_like_text(bytes)) throw;
    if (bytes.size() < kHeaderBytes)
      throw InputError(file + ": byte 0: not an STL file: " + std::to_string(bytes.size()) +
                       " bytes of binary data, too short for a binary STL (84-byte header)");
    throw InputError(file + ": byte 80: truncated binary STL: the header says " +
                     std::to_string(count) + " facets, so the file should have 84 + 50 x " +
                     std::to_string(count) + " = " +
                     std::to_string(kHeaderBytes + kFacetBytes * count) + " bytes, but it has " +
                     std::to_string(bytes.size()));
  }
}

}  // namespace partet
