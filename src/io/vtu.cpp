// VTK XML UnstructuredGrid (.vtu) reader, and the .pvtu index reader.
// Reads one Piece: Points (3 components, any numeric type), Cells
// (connectivity, offsets, types: tetrahedra (10) into tets, triangles (5)
// into tris, any other cell type refused), and PointData "GlobalNodeId".
// Data arrays may be ascii, inline base64 ("binary", UInt32 or UInt64 size
// header, header and data encoded together or apart), or appended (raw or
// base64), in either byte order, of types Int8..UInt64, Float32, Float64.
// Compressed files are refused. Errors name "file: byte N". Nothing is
// allocated beyond what the bytes actually present can fill.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "io/base64.hpp"
#include "io/byte_cursor.hpp"
#include "io/mesh_formats.hpp"
#include "io/text_cursor.hpp"
#include "io/xml_scan.hpp"

namespace partet {

namespace {

enum class Scalar { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kInt64, kUInt64, kFloat32, kFloat64 };

struct ScalarType {
  const char* name;
  Scalar scalar;
  size_t bytes;
};

constexpr ScalarType kScalarTypes[] = {
    {"Int8", Scalar::kInt8, 1},       {"UInt8", Scalar::kUInt8, 1},   {"Int16", Scalar::kInt16, 2},
    {"UInt16", Scalar::kUInt16, 2},   {"Int32", Scalar::kInt32, 4},   {"UInt32", Scalar::kUInt32, 4},
    {"Int64", Scalar::kInt64, 8},     {"UInt64", Scalar::kUInt64, 8}, {"Float32", Scalar::kFloat32, 4},
    {"Float64", Scalar::kFloat64, 8},
};

const ScalarType* find_scalar(std::string_view name) {
  for (const ScalarType& t : kScalarTypes)
    if (name == t.name) return &t;
  return nullptr;
}

const char* vtk_cell_name(int64_t type) {
  switch (type) {
    case 1:
      return "vertex";
    case 3:
      return "line";
    case 5:
      return "triangle";
    case 7:
      return "polygon";
    case 8:
      return "pixel";
    case 9:
      return "quad";
    case 10:
      return "tetra";
    case 11:
      return "voxel";
    case 12:
      return "hexahedron";
    case 13:
      return "wedge";
    case 14:
      return "pyramid";
    case 22:
      return "quadratic triangle";
    case 24:
      return "quadratic tetra";
    case 42:
      return "polyhedron";
    default:
      return "unknown";
  }
}

template <class U>
U load(const char* p, bool swap) {
  U v;
  std::memcpy(&v, p, sizeof v);
  if (swap) {
    if constexpr (sizeof(U) == 2) v = static_cast<U>(__builtin_bswap16(v));
    if constexpr (sizeof(U) == 4) v = static_cast<U>(__builtin_bswap32(v));
    if constexpr (sizeof(U) == 8) v = static_cast<U>(__builtin_bswap64(v));
  }
  return v;
}

double load_real(Scalar s, const char* p, bool swap) {
  switch (s) {
    case Scalar::kInt8:
      return static_cast<int8_t>(load<uint8_t>(p, swap));
    case Scalar::kUInt8:
      return load<uint8_t>(p, swap);
    case Scalar::kInt16:
      return static_cast<int16_t>(load<uint16_t>(p, swap));
    case Scalar::kUInt16:
      return load<uint16_t>(p, swap);
    case Scalar::kInt32:
      return static_cast<int32_t>(load<uint32_t>(p, swap));
    case Scalar::kUInt32:
      return load<uint32_t>(p, swap);
    case Scalar::kInt64:
      return static_cast<double>(static_cast<int64_t>(load<uint64_t>(p, swap)));
    case Scalar::kUInt64:
      return static_cast<double>(load<uint64_t>(p, swap));
    case Scalar::kFloat32:
      return std::bit_cast<float>(load<uint32_t>(p, swap));
    case Scalar::kFloat64:
      return std::bit_cast<double>(load<uint64_t>(p, swap));
  }
  return 0;
}

// False for float types and for UInt64 values above INT64_MAX.
bool load_integer(Scalar s, const char* p, bool swap, int64_t& out) {
  switch (s) {
    case Scalar::kInt8:
      out = static_cast<int8_t>(load<uint8_t>(p, swap));
      return true;
    case Scalar::kUInt8:
      out = load<uint8_t>(p, swap);
      return true;
    case Scalar::kInt16:
      out = static_cast<int16_t>(load<uint16_t>(p, swap));
      return true;
    case Scalar::kUInt16:
      out = load<uint16_t>(p, swap);
      return true;
    case Scalar::kInt32:
      out = static_cast<int32_t>(load<uint32_t>(p, swap));
      return true;
    case Scalar::kUInt32:
      out = load<uint32_t>(p, swap);
      return true;
    case Scalar::kInt64:
      out = static_cast<int64_t>(load<uint64_t>(p, swap));
      return true;
    case Scalar::kUInt64: {
      uint64_t u = load<uint64_t>(p, swap);
      out = static_cast<int64_t>(u);
      return u <= static_cast<uint64_t>(INT64_MAX);
    }
    case Scalar::kFloat32:
    case Scalar::kFloat64:
      return false;
  }
  return false;
}

struct DataArray {
  std::string name;
  const ScalarType* type = nullptr;
  uint64_t components = 1;
  enum Format { kAscii, kBinary, kAppended } format = kAscii;
  uint64_t offset = 0;       // appended: from the start of the appended data
  std::string_view content;  // inline: the text of the element
  size_t content_at = 0;     // offset of the content in the file
  size_t at = 0;             // offset of the tag in the file
};

class VtuReader {
 public:
  VtuReader(std::string_view bytes, const std::string& file) : xs_(bytes, file) {}
  TetMesh read();

 private:
  void scan();
  void vtk_file(const XmlTag& tag);
  void piece(const XmlTag& tag);
  DataArray data_array(const XmlTag& tag);
  void assign(std::string_view parent, DataArray&& a);
  uint64_t count_attribute(const XmlTag& tag, const char* name);
  std::string_view binary_data(const DataArray& a, std::string& storage);
  template <class T, class R, class F>
  void decode(const DataArray& a, R&& reserve, F&& f);
  void build_cells(TetMesh& mesh);
  [[noreturn]] void fail(size_t at, const std::string& message) const { xs_.fail(at, message); }

  XmlScanner xs_;
  bool swap_ = false;
  size_t header_bytes_ = 4;
  bool have_vtk_file_ = false;
  int pieces_ = 0;
  size_t piece_at_ = 0;
  uint64_t num_points_ = 0;
  uint64_t num_cells_ = 0;
  std::optional<size_t> appended_base_;
  bool appended_base64_ = false;
  std::optional<DataArray> points_, connectivity_, offsets_, types_, ids_;
};

void VtuReader::vtk_file(const XmlTag& tag) {
  std::string v;
  if (tag.name != "VTKFile")
    fail(tag.begin, "not a VTK XML file: the first element is <" + std::string(tag.name.substr(0, 40)) + ">");
  if (!xs_.attribute(tag, "type", v) || v != "UnstructuredGrid")
    fail(tag.begin, "VTK file type '" + v.substr(0, 40) + "'; partet reads UnstructuredGrid (.vtu) files");
  if (xs_.attribute(tag, "compressor", v) && !v.empty())
    fail(tag.begin, "compressed VTU is not supported (compressor " + v.substr(0, 40) +
                        "); write it uncompressed (e.g. meshio compression=None, ParaView: no compression)");
  if (xs_.attribute(tag, "byte_order", v)) {
    if (v != "LittleEndian" && v != "BigEndian") fail(tag.begin, "unknown byte_order '" + v.substr(0, 40) + "'");
    swap_ = (v == "BigEndian") != (std::endian::native == std::endian::big);
  }
  if (xs_.attribute(tag, "header_type", v)) {
    if (v == "UInt64")
      header_bytes_ = 8;
    else if (v != "UInt32")
      fail(tag.begin, "unknown header_type '" + v.substr(0, 40) + "'");
  }
  have_vtk_file_ = true;
}

uint64_t VtuReader::count_attribute(const XmlTag& tag, const char* name) {
  std::string v;
  if (!xs_.attribute(tag, name, v)) fail(tag.begin, std::string("<") + std::string(tag.name) + "> has no " + name);
  int64_t n = 0;
  if (!parse_integer(v, n) || n < 0) fail(tag.begin, std::string(name) + " '" + v.substr(0, 40) + "' is not a count");
  return static_cast<uint64_t>(n);
}

void VtuReader::piece(const XmlTag& tag) {
  if (++pieces_ > 1) fail(tag.begin, "more than one Piece; partet reads single-piece .vtu files");
  piece_at_ = tag.begin;
  num_points_ = count_attribute(tag, "NumberOfPoints");
  num_cells_ = count_attribute(tag, "NumberOfCells");
  if (num_points_ > UINT32_MAX) fail(tag.begin, std::to_string(num_points_) + " points are more than partet can index");
}

DataArray VtuReader::data_array(const XmlTag& tag) {
  DataArray a;
  a.at = tag.begin;
  std::string v;
  xs_.attribute(tag, "Name", a.name);
  if (!xs_.attribute(tag, "type", v)) fail(tag.begin, "DataArray '" + a.name.substr(0, 40) + "' has no type");
  a.type = find_scalar(v);
  if (a.type == nullptr)
    fail(tag.begin, "DataArray '" + a.name.substr(0, 40) + "' has unsupported type '" + v.substr(0, 40) + "'");
  if (xs_.attribute(tag, "NumberOfComponents", v)) {
    int64_t c = 0;
    if (!parse_integer(v, c) || c < 1)
      fail(tag.begin, "NumberOfComponents '" + v.substr(0, 40) + "' is not a positive count");
    a.components = static_cast<uint64_t>(c);
  }
  if (!xs_.attribute(tag, "format", v)) v = "ascii";
  if (v == "ascii") {
    a.format = DataArray::kAscii;
  } else if (v == "binary") {
    a.format = DataArray::kBinary;
  } else if (v == "appended") {
    a.format = DataArray::kAppended;
    std::string off;
    int64_t o = 0;
    if (!xs_.attribute(tag, "offset", off) || !parse_integer(off, o) || o < 0)
      fail(tag.begin, "appended DataArray '" + a.name.substr(0, 40) + "' has no valid offset");
    a.offset = static_cast<uint64_t>(o);
  } else {
    fail(tag.begin, "DataArray '" + a.name.substr(0, 40) + "' has unknown format '" + v.substr(0, 40) + "'");
  }
  return a;
}

void VtuReader::assign(std::string_view parent, DataArray&& a) {
  std::optional<DataArray>* slot = nullptr;
  if (parent == "Points")
    slot = &points_;
  else if (parent == "Cells" && a.name == "connectivity")
    slot = &connectivity_;
  else if (parent == "Cells" && a.name == "offsets")
    slot = &offsets_;
  else if (parent == "Cells" && a.name == "types")
    slot = &types_;
  else if (parent == "PointData" && a.name == "GlobalNodeId")
    slot = &ids_;
  if (slot == nullptr) return;
  if (slot->has_value()) fail(a.at, "second " + std::string(parent) + " array '" + a.name.substr(0, 40) + "'");
  *slot = std::move(a);
}

// Walks the tags up to <AppendedData> (whose raw bytes are not XML).
void VtuReader::scan() {
  XmlTag tag;
  std::vector<std::string_view> stack;
  std::optional<DataArray> open_array;  // an inline DataArray being read
  std::string_view open_parent;
  size_t array_depth = 0;  // stack size inside the open DataArray
  size_t prev_end = 0;
  while (xs_.next(tag)) {
    if (open_array && stack.size() == array_depth) {
      std::string_view text = xs_.text().substr(prev_end, tag.begin - prev_end);
      if (text.find_first_not_of(" \t\r\n") != std::string_view::npos) {
        if (!open_array->content.empty())
          fail(prev_end, "DataArray '" + open_array->name.substr(0, 40) + "' has its data split by elements");
        open_array->content = text;
        open_array->content_at = prev_end;
      }
    }
    prev_end = tag.end;
    if (tag.kind == XmlTag::kClose) {
      if (stack.empty() || stack.back() != tag.name)
        fail(tag.begin, "</" + std::string(tag.name.substr(0, 40)) + "> closes no open element");
      stack.pop_back();
      if (open_array && stack.size() + 1 == array_depth) {
        assign(open_parent, std::move(*open_array));
        open_array.reset();
      }
      continue;
    }
    if (stack.empty()) {
      if (have_vtk_file_) fail(tag.begin, "element <" + std::string(tag.name.substr(0, 40)) + "> after </VTKFile>");
      vtk_file(tag);
    } else if (tag.name == "Piece" && stack.back() == "UnstructuredGrid") {
      piece(tag);
    } else if (tag.name == "DataArray") {
      if (open_array) fail(tag.begin, "DataArray inside a DataArray");
      DataArray a = data_array(tag);
      if (tag.kind == XmlTag::kEmpty) {
        assign(stack.back(), std::move(a));
      } else {
        open_parent = stack.back();
        open_array = std::move(a);
        array_depth = stack.size() + 1;
      }
    } else if (tag.name == "AppendedData") {
      std::string enc;
      xs_.attribute(tag, "encoding", enc);
      if (enc != "raw" && enc != "base64")
        fail(tag.begin, "AppendedData encoding '" + enc.substr(0, 40) + "' is neither raw nor base64");
      appended_base64_ = enc == "base64";
      std::string_view t = xs_.text();
      size_t p = tag.end;
      while (p < t.size() && (t[p] == ' ' || t[p] == '\t' || t[p] == '\r' || t[p] == '\n')) ++p;
      if (p >= t.size() || t[p] != '_') fail(p, "AppendedData does not start with '_'");
      appended_base_ = p + 1;
      return;
    }
    if (tag.kind == XmlTag::kOpen) stack.push_back(tag.name);
  }
  if (!have_vtk_file_) fail(0, "not a VTK XML file: no VTKFile element");
  if (!stack.empty())
    fail(xs_.text().size(), "unexpected end of file inside <" + std::string(stack.back().substr(0, 40)) + ">");
}

// The bytes of a binary or appended array, in the file's byte order.
std::string_view VtuReader::binary_data(const DataArray& a, std::string& storage) {
  std::string_view text = xs_.text();
  std::string what = "DataArray '" + a.name.substr(0, 40) + "'";
  std::string_view source = text.substr(0, a.content_at + a.content.size());
  size_t start = a.content_at;
  if (a.format == DataArray::kAppended) {
    if (!appended_base_) fail(a.at, what + " is appended but the file has no AppendedData");
    if (a.offset > text.size() - *appended_base_)
      fail(a.at, what + " offset " + std::to_string(a.offset) + " is past the end of the file");
    start = *appended_base_ + a.offset;
    source = text;
    if (!appended_base64_) {
      ByteCursor bc(text, xs_.file(), start);
      std::string_view h = bc.take(header_bytes_, "appended size header");
      uint64_t n = header_bytes_ == 4 ? load<uint32_t>(h.data(), swap_) : load<uint64_t>(h.data(), swap_);
      return bc.take(n, "appended data");
    }
  }
  Base64Decoder d(source, start);
  char h[8];
  if (!d.read(header_bytes_, h)) fail(d.position(), what + ": bad or missing base64 size header");
  uint64_t n = header_bytes_ == 4 ? load<uint32_t>(h, swap_) : load<uint64_t>(h, swap_);
  if (n > d.max_bytes()) fail(a.at, what + " announces " + std::to_string(n) + " bytes but holds fewer");
  storage.resize(n);
  if (!d.read(n, storage.data())) fail(d.position(), what + ": bad or truncated base64 data");
  return storage;
}

// Calls f(value) for each value of `a`, as a double (T = double) or as an
// integer (T = int64_t; float data or values beyond int64 fail). Binary data
// first calls reserve(count) with the count of values it holds.
template <class T, class R, class F>
void VtuReader::decode(const DataArray& a, R&& reserve, F&& f) {
  std::string what = "DataArray '" + a.name.substr(0, 40) + "'";
  if (a.format == DataArray::kAscii) {
    std::string_view c = a.content;
    size_t i = 0;
    while (true) {
      while (i < c.size() && (c[i] == ' ' || c[i] == '\t' || c[i] == '\r' || c[i] == '\n')) ++i;
      if (i >= c.size()) return;
      size_t start = i;
      while (i < c.size() && !(c[i] == ' ' || c[i] == '\t' || c[i] == '\r' || c[i] == '\n')) ++i;
      std::string_view token = c.substr(start, i - start);
      T v{};
      bool ok;
      if constexpr (std::is_same_v<T, double>)
        ok = parse_real(token, v);
      else
        ok = parse_integer(token, v);
      if (!ok)
        fail(a.content_at + start, what + ": '" + std::string(token.substr(0, 40)) + "' is not " +
                                       (std::is_same_v<T, double> ? "a number" : "an integer"));
      f(v);
    }
  }
  std::string storage;
  std::string_view bytes = binary_data(a, storage);
  size_t size = a.type->bytes;
  if (bytes.size() % size != 0)
    fail(a.at, what + " holds " + std::to_string(bytes.size()) + " bytes, not a whole number of " + a.type->name);
  reserve(bytes.size() / size);
  for (size_t k = 0; k < bytes.size(); k += size) {
    if constexpr (std::is_same_v<T, double>) {
      f(load_real(a.type->scalar, bytes.data() + k, swap_));
    } else {
      int64_t v = 0;
      if (!load_integer(a.type->scalar, bytes.data() + k, swap_, v))
        fail(a.at, what + " of type " + a.type->name + " does not hold 64-bit integers");
      f(v);
    }
  }
}

void VtuReader::build_cells(TetMesh& mesh) {
  if (num_cells_ == 0 && !connectivity_ && !offsets_ && !types_) return;
  if (!connectivity_ || !offsets_ || !types_) fail(piece_at_, "Cells needs connectivity, offsets and types arrays");
  std::vector<uint32_t> conn;
  uint64_t nv = num_points_;
  decode<int64_t>(
      *connectivity_, [&](size_t n) { conn.reserve(n); },
      [&](int64_t v) {
        if (v < 0 || static_cast<uint64_t>(v) >= nv)
          fail(connectivity_->at, "connectivity entry " + std::to_string(conn.size()) + " is point " +
                                      std::to_string(v) + ", out of range 0.." + std::to_string(nv) + "-1");
        conn.push_back(static_cast<uint32_t>(v));
      });
  std::vector<int64_t> offsets;
  decode<int64_t>(
      *offsets_, [&](size_t n) { offsets.reserve(n); }, [&](int64_t v) { offsets.push_back(v); });
  std::vector<uint8_t> types;
  decode<int64_t>(
      *types_, [&](size_t n) { types.reserve(n); },
      [&](int64_t v) {
        if (v < 0 || v > 255) fail(types_->at, "cell type " + std::to_string(v) + " is out of range");
        types.push_back(static_cast<uint8_t>(v));
      });
  if (types.size() != num_cells_)
    fail(types_->at,
         "types holds " + std::to_string(types.size()) + " values for " + std::to_string(num_cells_) + " cells");
  // Offsets are cell ends; a leading 0 (VTK's newer layout) gives cell starts.
  bool starts = offsets.size() == num_cells_ + 1 && offsets[0] == 0;
  if (offsets.size() != num_cells_ && !starts)
    fail(offsets_->at,
         "offsets holds " + std::to_string(offsets.size()) + " values for " + std::to_string(num_cells_) + " cells");
  size_t num_tets = static_cast<size_t>(std::count(types.begin(), types.end(), uint8_t{10}));
  mesh.tets.reserve(4 * num_tets);
  mesh.tris.reserve(3 * static_cast<size_t>(std::count(types.begin(), types.end(), uint8_t{5})));
  int64_t begin = 0;
  for (size_t c = 0; c < num_cells_; ++c) {
    int64_t end = offsets[starts ? c + 1 : c];
    if (starts) begin = offsets[c];
    if (end < begin || static_cast<uint64_t>(end) > conn.size())
      fail(offsets_->at, "cell " + std::to_string(c) + " spans connectivity [" + std::to_string(begin) + ", " +
                             std::to_string(end) + "), outside 0.." + std::to_string(conn.size()));
    size_t corners = types[c] == 10 ? 4 : types[c] == 5 ? 3 : 0;
    if (corners == 0)
      fail(types_->at, "cell " + std::to_string(c) + " has VTK type " + std::to_string(types[c]) + " (" +
                           vtk_cell_name(types[c]) + "); partet reads tetrahedra (10) and triangles (5) only");
    if (static_cast<size_t>(end - begin) != corners)
      fail(offsets_->at, "cell " + std::to_string(c) + " of type " + std::to_string(types[c]) + " has " +
                             std::to_string(end - begin) + " points, not " + std::to_string(corners));
    std::vector<uint32_t>& out = corners == 4 ? mesh.tets : mesh.tris;
    out.insert(out.end(), conn.begin() + begin, conn.begin() + end);
    begin = end;
  }
}

TetMesh VtuReader::read() {
  scan();
  if (pieces_ == 0) fail(0, "no Piece in the UnstructuredGrid");
  TetMesh mesh;
  if (!points_) {
    if (num_points_ > 0) fail(piece_at_, "Piece has no Points array");
  } else {
    if (points_->components != 3)
      fail(points_->at, "Points have " + std::to_string(points_->components) + " components, not 3");
    decode<double>(
        *points_, [&](size_t n) { mesh.xyz.reserve(n); },
        [&](double v) {
          if (mesh.xyz.size() == 3 * num_points_)
            fail(points_->at, "Points hold more than " + std::to_string(num_points_) + " points");
          mesh.xyz.push_back(v);
        });
    if (mesh.xyz.size() != 3 * num_points_)
      fail(points_->at,
           "Points hold " + std::to_string(mesh.xyz.size()) + " values for " + std::to_string(num_points_) + " points");
  }
  build_cells(mesh);
  if (ids_) {
    decode<int64_t>(
        *ids_, [&](size_t n) { mesh.global_ids.reserve(n); },
        [&](int64_t v) {
          // Ids are 64-bit patterns (partet's surface vertices set the top
          // bit); VTK stores them as signed Int64: keep the bits.
          if (mesh.global_ids.size() == num_points_) fail(ids_->at, "GlobalNodeId holds more values than points");
          mesh.global_ids.push_back(static_cast<uint64_t>(v));
        });
    if (mesh.global_ids.size() != num_points_)
      fail(ids_->at, "GlobalNodeId holds " + std::to_string(mesh.global_ids.size()) + " values for " +
                         std::to_string(num_points_) + " points");
  }
  return mesh;
}

}  // namespace

TetMesh parse_vtu(std::string_view bytes, const std::string& file) { return VtuReader(bytes, file).read(); }

std::vector<std::string> parse_pvtu_pieces(std::string_view bytes, const std::string& file) {
  XmlScanner xs(bytes, file);
  XmlTag tag;
  std::string v;
  if (!xs.next(tag) || tag.name != "VTKFile") xs.fail(tag.begin, "not a VTK XML file: no VTKFile element first");
  if (!xs.attribute(tag, "type", v) || v != "PUnstructuredGrid")
    xs.fail(tag.begin, "VTK file type '" + v.substr(0, 40) + "'; a .pvtu index is PUnstructuredGrid");
  std::vector<std::string> pieces;
  while (xs.next(tag)) {
    if (tag.kind == XmlTag::kClose || tag.name != "Piece") continue;
    if (!xs.attribute(tag, "Source", v) || v.empty()) xs.fail(tag.begin, "Piece has no Source");
    pieces.push_back(v);
  }
  if (pieces.empty()) xs.fail(0, "the .pvtu index lists no Piece");
  return pieces;
}

}  // namespace partet
