// PLY reader: `format ascii 1.0`, `binary_little_endian 1.0` or
// `binary_big_endian 1.0`; every PLY scalar type under both its names
// (char/int8 ... double/float64). Coordinates come from the x, y, z
// properties of element `vertex` (any types, any order; other properties
// skipped); triangles from the list property `vertex_indices` (or
// `vertex_index`) of element `face`. Other elements and properties are read
// past. Counts in the header are checked against the bytes after it before
// anything is allocated. Errors name "file:line" in the header and in ASCII
// data, "file: byte N" in binary data; faces that are not triangles are all
// counted and refused in one error naming the first ones.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/byte_cursor.hpp"
#include "io/polygon_faces.hpp"
#include "io/surface_formats.hpp"
#include "io/text_cursor.hpp"

namespace partet {

namespace {

enum class PlyType : uint8_t { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };
enum class PlyFormat : uint8_t { kNone, kAscii, kLittle, kBig };

bool parse_type(std::string_view s, PlyType& out) {
  static constexpr std::string_view kNames[8][2] = {
      {"char", "int8"},   {"uchar", "uint8"},   {"short", "int16"},   {"ushort", "uint16"},
      {"int", "int32"},   {"uint", "uint32"},   {"float", "float32"}, {"double", "float64"}};
  for (int t = 0; t < 8; ++t)
    if (s == kNames[t][0] || s == kNames[t][1]) {
      out = static_cast<PlyType>(t);
      return true;
    }
  return false;
}

uint64_t type_size(PlyType t) {
  static constexpr uint64_t kSizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
  return kSizes[static_cast<int>(t)];
}

bool is_integer(PlyType t) { return t < PlyType::kFloat32; }

struct Property {
  std::string_view name;
  PlyType type;        // of the value, or of the items of a list
  PlyType count_type;  // of a list's length
  bool list;
};

struct Element {
  std::string_view name;
  uint64_t count;
  size_t first, end;  // its properties: [first, end) in Header::properties
  size_t line;        // of its `element` line
};

struct Header {
  PlyFormat format = PlyFormat::kNone;
  std::vector<Element> elements;
  std::vector<Property> properties;
};

std::string clip(std::string_view s) { return std::string(s.substr(0, 40)); }

Header parse_header(TextCursor& c) {
  Header h;
  std::string_view line;
  if (!c.line(line) || line != "ply") c.fail("not a PLY file: the first line is not 'ply'");
  for (;;) {
    if (!c.line(line)) c.fail("unexpected end of file in the PLY header (no 'end_header')");
    std::string_view tok[6];
    size_t n = split_tokens(line, tok, 6);
    if (n == 0 || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "end_header") break;
    if (tok[0] == "format") {
      if (n != 3) c.fail("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (tok[1] == "ascii") h.format = PlyFormat::kAscii;
      else if (tok[1] == "binary_little_endian") h.format = PlyFormat::kLittle;
      else if (tok[1] == "binary_big_endian") h.format = PlyFormat::kBig;
      else c.fail("unknown PLY format '" + clip(tok[1]) + "'");
      if (tok[2] != "1.0") c.fail("unsupported PLY version '" + clip(tok[2]) + "' (1.0 expected)");
    } else if (tok[0] == "element") {
      int64_t count = 0;
      if (n != 3 || !parse_integer(tok[2], count) || count < 0)
        c.fail("expected 'element <name> <count>' with a non-negative count");
      size_t end = h.properties.size();
      h.elements.push_back({tok[1], static_cast<uint64_t>(count), end, end, c.line_number()});
    } else if (tok[0] == "property") {
      if (h.elements.empty()) c.fail("'property' before any 'element'");
      Property p{};
      bool ok = false;
      if (n >= 2 && tok[1] == "list") {
        p.list = true;
        ok = n == 5 && parse_type(tok[2], p.count_type) && parse_type(tok[3], p.type);
        if (ok && !is_integer(p.count_type)) c.fail("the length type of a list must be an integer type");
        p.name = tok[4];
      } else {
        ok = n == 3 && parse_type(tok[1], p.type);
        p.name = tok[2];
      }
      if (!ok) c.fail("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      h.properties.push_back(p);
      h.elements.back().end = h.properties.size();
    } else {
      c.fail("unknown PLY header line '" + clip(tok[0]) + "'");
    }
  }
  if (h.format == PlyFormat::kNone) c.fail("the PLY header has no 'format' line");
  return h;
}

// A property of element `e` by name; `props.size()` when there is none.
size_t find_property(const Header& h, const Element& e, std::string_view name) {
  for (size_t p = e.first; p < e.end; ++p)
    if (h.properties[p].name == name) return p;
  return h.properties.size();
}

// ASCII values: one token each; positions are lines.
class AsciiValues {
 public:
  explicit AsciiValues(TextCursor& c) : c_(c) {}
  double real(PlyType) { return c_.real("a property value"); }
  int64_t integer(PlyType, const char* what) { return c_.integer(what); }
  void skip(PlyType) { c_.token("a property value"); }
  void skip_items(uint64_t n, PlyType) {
    for (uint64_t i = 0; i < n; ++i) c_.token("a list item");
  }
  size_t mark() const { return 0; }
  uint64_t remaining() const { return c_.size() - c_.offset(); }
  // Bytes a triangle's list takes at least: "3 0 1 2\n".
  uint64_t triangle_bytes(PlyType, PlyType) const { return 8; }
  // Where the value read last is, for a face whose list length was just read.
  std::string located(size_t) const { return c_.file() + ":" + std::to_string(c_.line_number()); }
  std::string where(size_t) const { return "line " + std::to_string(c_.line_number()); }
  [[noreturn]] void fail(const std::string& message) const { c_.fail(message); }

 private:
  TextCursor& c_;
};

// Binary values through a ByteCursor, byte-swapped when the file's
// endianness is not the machine's; positions are byte offsets.
class BinaryValues {
 public:
  BinaryValues(std::string_view bytes, const std::string& file, size_t start, bool big)
      : c_(bytes, file, start), file_(file), swap_(big != (std::endian::native == std::endian::big)) {}

  double real(PlyType t) {
    switch (t) {
      case PlyType::kFloat32: return static_cast<double>(std::bit_cast<float>(u32("a float")));
      case PlyType::kFloat64: return std::bit_cast<double>(u64("a double"));
      default: return static_cast<double>(integer(t, "an integer"));
    }
  }

  int64_t integer(PlyType t, const char* what) {
    switch (t) {
      case PlyType::kInt8: return c_.read<int8_t>(what);
      case PlyType::kUInt8: return c_.read<uint8_t>(what);
      case PlyType::kInt16: return static_cast<int16_t>(u16(what));
      case PlyType::kUInt16: return u16(what);
      case PlyType::kInt32: return static_cast<int32_t>(u32(what));
      case PlyType::kUInt32: return u32(what);
      default: c_.fail(std::string(what) + " must have an integer type");
    }
  }

  void skip(PlyType t) { c_.skip(type_size(t), "a property value"); }
  void skip_items(uint64_t n, PlyType t) {
    c_.need(n, type_size(t), "a list");
    c_.skip(n * type_size(t), "a list");
  }
  size_t mark() const { return c_.offset(); }
  uint64_t remaining() const { return c_.remaining(); }
  uint64_t triangle_bytes(PlyType count, PlyType index) const { return type_size(count) + 3 * type_size(index); }
  std::string located(size_t mark) const { return file_ + ": byte " + std::to_string(mark); }
  std::string where(size_t mark) const { return "byte " + std::to_string(mark); }
  [[noreturn]] void fail(const std::string& message) const { c_.fail(message); }

 private:
  uint16_t u16(const char* what) {
    uint16_t v = c_.read<uint16_t>(what);
    return swap_ ? static_cast<uint16_t>((v >> 8) | (v << 8)) : v;
  }
  uint32_t u32(const char* what) {
    uint32_t v = c_.read<uint32_t>(what);
    return swap_ ? __builtin_bswap32(v) : v;
  }
  uint64_t u64(const char* what) {
    uint64_t v = c_.read<uint64_t>(what);
    return swap_ ? __builtin_bswap64(v) : v;
  }

  ByteCursor c_;
  const std::string& file_;
  bool swap_;
};

// Reads past a property of any kind.
template <class Values>
void skip_property(Values& in, const Property& p) {
  if (!p.list) return in.skip(p.type);
  int64_t n = in.integer(p.count_type, "a list length");
  if (n < 0) in.fail("negative list length " + std::to_string(n));
  in.skip_items(static_cast<uint64_t>(n), p.type);
}

// The body: every element in header order, keeping vertices and triangles.
template <class Values>
void read_body(const Header& h, Values& in, SurfaceMesh& mesh, PolygonFaces& polygons) {
  static constexpr std::string_view kAxes[3] = {"x", "y", "z"};
  uint64_t nv = 0;
  for (const Element& e : h.elements)
    if (e.name == "vertex") nv = e.count;
  for (const Element& e : h.elements) {
    if (e.first == e.end) continue;  // no properties: nothing to read
    size_t xyz[3] = {h.properties.size(), h.properties.size(), h.properties.size()};
    size_t list = h.properties.size();
    if (e.name == "vertex") {
      for (int i = 0; i < 3; ++i) xyz[i] = find_property(h, e, kAxes[i]);
      mesh.xyz.resize(3 * e.count);
    } else if (e.name == "face") {
      list = std::min(find_property(h, e, "vertex_indices"), find_property(h, e, "vertex_index"));
      const Property& p = h.properties[list];
      mesh.tris.reserve(3 * std::min(e.count, in.remaining() / in.triangle_bytes(p.count_type, p.type)));
    }
    for (uint64_t r = 0; r < e.count; ++r) {
      for (size_t p = e.first; p < e.end; ++p) {
        const Property& prop = h.properties[p];
        if (p == xyz[0] || p == xyz[1] || p == xyz[2]) {
          mesh.xyz[3 * r + (p == xyz[0] ? 0 : p == xyz[1] ? 1 : 2)] = in.real(prop.type);
        } else if (p != list) {
          skip_property(in, prop);
        } else {
          size_t mark = in.mark();
          int64_t n = in.integer(prop.count_type, "a face's vertex count");
          if (n < 0) in.fail("face " + std::to_string(r) + " has a negative vertex count");
          if (n != 3) {
            polygons.add(r, static_cast<uint64_t>(n), in.located(mark), in.where(mark));
            in.skip_items(static_cast<uint64_t>(n), prop.type);
            continue;
          }
          for (int k = 0; k < 3; ++k) {
            int64_t v = in.integer(prop.type, "a vertex index");
            if (v < 0 || static_cast<uint64_t>(v) >= nv)
              in.fail("face " + std::to_string(r) + ": vertex index " + std::to_string(v) +
                      " is out of range (the file has " + std::to_string(nv) + " vertices)");
            mesh.tris.push_back(static_cast<uint32_t>(v));
          }
        }
      }
    }
  }
}

// Checks what the body is to hold against the header and the bytes left.
void check_header(const Header& h, TextCursor& c, uint64_t body_bytes) {
  bool ascii = h.format == PlyFormat::kAscii;
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : h.elements) {
    uint64_t min_bytes = 0;
    for (size_t p = e.first; p < e.end; ++p) {
      const Property& prop = h.properties[p];
      min_bytes += ascii ? 2 : type_size(prop.list ? prop.count_type : prop.type);
    }
    uint64_t limit = min_bytes == 0 ? UINT64_MAX : (body_bytes + (ascii ? 1 : 0)) / min_bytes;
    std::string name = "element '" + clip(e.name) + "' (line " + std::to_string(e.line) + ")";
    if (e.count > limit)
      c.fail(name + " claims " + std::to_string(e.count) + " entries, more than the " +
             std::to_string(body_bytes) + " bytes after the header can hold");
    if (e.name == "vertex" || e.name == "face") {
      const Element*& slot = e.name == "vertex" ? vertex : face;
      if (slot) c.fail("a second " + name);
      slot = &e;
    }
  }
  if (!vertex) c.fail("the PLY header has no 'vertex' element");
  if (vertex->count > UINT32_MAX) c.fail("more than 4294967295 vertices");
  for (const char* axis : {"x", "y", "z"}) {
    size_t p = find_property(h, *vertex, axis);
    if (p == h.properties.size()) c.fail(std::string("element 'vertex' has no '") + axis + "' property");
    if (h.properties[p].list) c.fail(std::string("property '") + axis + "' of 'vertex' is a list");
  }
  if (!face) c.fail("no triangles: the PLY header has no 'face' element");
  size_t list = std::min(find_property(h, *face, "vertex_indices"), find_property(h, *face, "vertex_index"));
  if (list == h.properties.size())
    c.fail("element 'face' has no 'vertex_indices' (or 'vertex_index') list");
  const Property& p = h.properties[list];
  if (!p.list || !is_integer(p.type))
    c.fail("property '" + clip(p.name) + "' of 'face' must be a list of integers");
}

}  // namespace

SurfaceMesh parse_ply(std::string_view bytes, const std::string& file) {
  TextCursor c(bytes, file);
  Header h = parse_header(c);
  size_t body = c.offset();
  check_header(h, c, bytes.size() - body);
  SurfaceMesh mesh;
  PolygonFaces polygons;
  if (h.format == PlyFormat::kAscii) {
    AsciiValues in(c);
    read_body(h, in, mesh, polygons);
  } else {
    BinaryValues in(bytes, file, body, h.format == PlyFormat::kBig);
    read_body(h, in, mesh, polygons);
  }
  polygons.check();
  if (mesh.tris.empty()) throw InputError(file + ": no triangles (element 'face' is empty)");
  return mesh;
}

}  // namespace partet
