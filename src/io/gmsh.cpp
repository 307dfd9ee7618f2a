// Gmsh .msh 4.1 reader and writer, ASCII and binary.
// Reading: either byte order (told by the one-int marker), size_t of 4 or 8
// bytes. $Entities and $PartitionedEntities are parsed by their layout (so
// binary data is never scanned for markers); $Nodes entity blocks with
// sparse node tags are mapped to 0-based indices; $Elements keeps triangles
// and tets, skips other known types by their node count and refuses unknown
// types; $PhysicalNames and any other section is skipped line by line to its
// $End marker, as Gmsh does. Reading stops once $Nodes and $Elements are read.
// A surface read keeps triangles and refuses other faces (quadrangles,
// higher-order triangles); a volume read keeps tets and triangles and refuses
// other volume elements. Errors name "file:line" (ASCII) or "file: byte N"
// (binary); counts are checked against the bytes left before allocating.
// Writing: one volume entity (and one surface entity when there are
// triangles), all nodes in one block tagged 1..N, a triangle block (type 2)
// and a tet block (type 4); binary in native byte order with 8-byte size_t;
// ASCII reals with 17 significant digits.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "io/byte_cursor.hpp"
#include "io/mesh_formats.hpp"
#include "io/text_cursor.hpp"
#include "io/text_writer.hpp"

namespace partet {

namespace {

struct ElementType {
  int type;
  int nodes;
  int dim;
  const char* name;
};

constexpr ElementType kElementTypes[] = {
    {1, 2, 1, "2-node line"},           {2, 3, 2, "3-node triangle"},       {3, 4, 2, "4-node quadrangle"},
    {4, 4, 3, "4-node tetrahedron"},    {5, 8, 3, "8-node hexahedron"},     {6, 6, 3, "6-node prism"},
    {7, 5, 3, "5-node pyramid"},        {8, 3, 1, "3-node line"},           {9, 6, 2, "6-node triangle"},
    {10, 9, 2, "9-node quadrangle"},    {11, 10, 3, "10-node tetrahedron"}, {12, 27, 3, "27-node hexahedron"},
    {13, 18, 3, "18-node prism"},       {14, 14, 3, "14-node pyramid"},     {15, 1, 0, "point"},
    {16, 8, 2, "8-node quadrangle"},    {17, 20, 3, "20-node hexahedron"},  {18, 15, 3, "15-node prism"},
    {19, 13, 3, "13-node pyramid"},     {20, 9, 2, "9-node triangle"},      {21, 10, 2, "10-node triangle"},
    {22, 12, 2, "12-node triangle"},    {23, 15, 2, "15-node triangle"},    {24, 15, 2, "15-node triangle"},
    {25, 21, 2, "21-node triangle"},    {26, 4, 1, "4-node line"},          {27, 5, 1, "5-node line"},
    {28, 6, 1, "6-node line"},          {29, 20, 3, "20-node tetrahedron"}, {30, 35, 3, "35-node tetrahedron"},
    {31, 56, 3, "56-node tetrahedron"}, {92, 64, 3, "64-node hexahedron"},  {93, 125, 3, "125-node hexahedron"},
};

const ElementType* find_element_type(int64_t type) {
  for (const ElementType& t : kElementTypes)
    if (t.type == type) return &t;
  return nullptr;
}

// The numbers of one section, read as text tokens (ASCII) or as binary values
// (binary), with errors naming the line or the byte offset.
class Fields {
 public:
  Fields(TextCursor& tc, bool binary, bool swap, int size_bytes)
      : tc_(tc), bc_(tc.text(), tc.file()), binary_(binary), swap_(swap), size_bytes_(size_bytes) {}

  // Binary: the data starts at the cursor; end() moves the text cursor past it.
  void begin() { bc_ = ByteCursor(tc_.text(), tc_.file(), tc_.offset()); }
  void end() {
    if (binary_) tc_.seek(bc_.offset());
  }

  uint64_t size(const char* what) {
    if (!binary_) {
      int64_t v = tc_.integer(what);
      if (v < 0) tc_.fail(std::string(what) + " is negative (" + std::to_string(v) + ")");
      return static_cast<uint64_t>(v);
    }
    if (size_bytes_ == 4) return swapped(bc_.read<uint32_t>(what));
    return swapped(bc_.read<uint64_t>(what));
  }

  int64_t integer(const char* what) {
    if (!binary_) {
      int64_t v = tc_.integer(what);
      if (v < INT32_MIN || v > INT32_MAX) tc_.fail(std::string(what) + " " + std::to_string(v) + " is out of range");
      return v;
    }
    return static_cast<int32_t>(swapped(bc_.read<uint32_t>(what)));
  }

  double real(const char* what) {
    if (!binary_) return tc_.real(what);
    uint64_t bits = swapped(bc_.read<uint64_t>(what));
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

  // A count of items, each at least `tokens` text tokens or `bytes` binary bytes.
  uint64_t count(const char* what, uint64_t tokens, uint64_t bytes) {
    if (!binary_) return tc_.count(what, (tc_.size() - tc_.offset()) / (2 * tokens) + 1);
    uint64_t n = size(what);
    bc_.need(n, bytes, what);
    return n;
  }

  uint64_t size_bytes() const { return static_cast<uint64_t>(size_bytes_); }

  [[noreturn]] void fail(const std::string& message) const {
    if (binary_) bc_.fail(message);
    tc_.fail(message);
  }

 private:
  uint32_t swapped(uint32_t v) const { return swap_ ? __builtin_bswap32(v) : v; }
  uint64_t swapped(uint64_t v) const { return swap_ ? __builtin_bswap64(v) : v; }

  TextCursor& tc_;
  ByteCursor bc_;
  bool binary_;
  bool swap_;
  int size_bytes_;
};

// Node tags (any positive 64-bit values, any order) to 0-based indices: a
// dense table when the tags are compact, else a sorted list.
class NodeIndex {
 public:
  // False when a tag repeats (`repeated` is then that tag).
  bool build(const std::vector<uint64_t>& tags, uint64_t& repeated) {
    uint64_t max_tag = 0;
    for (uint64_t t : tags) max_tag = std::max(max_tag, t);
    if (max_tag <= 2 * static_cast<uint64_t>(tags.size()) + 1024) {
      dense_.assign(max_tag + 1, kNone);
      for (size_t i = 0; i < tags.size(); ++i) {
        if (dense_[tags[i]] != kNone) {
          repeated = tags[i];
          return false;
        }
        dense_[tags[i]] = static_cast<uint32_t>(i);
      }
      return true;
    }
    sorted_.resize(tags.size());
    for (size_t i = 0; i < tags.size(); ++i) sorted_[i] = {tags[i], static_cast<uint32_t>(i)};
    std::sort(sorted_.begin(), sorted_.end());
    for (size_t i = 1; i < sorted_.size(); ++i) {
      if (sorted_[i].first == sorted_[i - 1].first) {
        repeated = sorted_[i].first;
        return false;
      }
    }
    return true;
  }

  bool find(uint64_t tag, uint32_t& index) const {
    if (!sorted_.empty()) {
      auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(tag, uint32_t{0}));
      if (it == sorted_.end() || it->first != tag) return false;
      index = it->second;
      return true;
    }
    if (tag >= dense_.size() || dense_[tag] == kNone) return false;
    index = dense_[tag];
    return true;
  }

 private:
  static constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> dense_;
  std::vector<std::pair<uint64_t, uint32_t>> sorted_;
};

class GmshReader {
 public:
  GmshReader(std::string_view bytes, const std::string& file, MeshRead what) : tc_(bytes, file), what_(what) {}

  TetMesh read();

 private:
  void mesh_format();
  void end_of_header_line();
  void expect(std::string_view marker);
  void skip_section(std::string_view name);
  void entities(bool partitioned);
  void nodes();
  void elements();
  void skip_values(Fields& f, uint64_t n, bool reals, const char* what);
  [[noreturn]] void fail(const std::string& message) const;
  Fields fields() { return Fields(tc_, binary_, swap_, size_bytes_); }

  TextCursor tc_;
  MeshRead what_;
  bool binary_ = false;
  bool swap_ = false;
  int size_bytes_ = 8;
  bool have_nodes_ = false;
  bool have_elements_ = false;
  NodeIndex node_index_;
  TetMesh mesh_;
};

void GmshReader::fail(const std::string& message) const {
  if (binary_) throw InputError(tc_.file() + ": byte " + std::to_string(tc_.offset()) + ": " + message);
  tc_.fail(message);
}

// The rest of a section's header line must be empty (binary data follows it).
void GmshReader::end_of_header_line() {
  std::string_view rest;
  if (tc_.line(rest) && !rest.empty())
    fail("unexpected '" + std::string(rest.substr(0, 40)) + "' after a section header");
}

void GmshReader::expect(std::string_view marker) {
  std::string_view t = tc_.token(std::string(marker).c_str());
  if (t != marker) fail("expected " + std::string(marker) + ", found '" + std::string(t.substr(0, 40)) + "'");
}

void GmshReader::mesh_format() {
  std::string_view t = tc_.token("$MeshFormat");
  if (t != "$MeshFormat") fail("not a Gmsh mesh: expected $MeshFormat, found '" + std::string(t.substr(0, 40)) + "'");
  std::string_view version = tc_.token("format version");
  if (version != "4.1")
    fail("Gmsh format " + std::string(version.substr(0, 20)) +
         " is not supported; partet reads format 4.1 (Gmsh option Mesh.MshFileVersion = 4.1)");
  int64_t file_type = tc_.integer("file type");
  int64_t data_size = tc_.integer("data size");
  if (file_type != 0 && file_type != 1)
    fail("file type " + std::to_string(file_type) + " is neither 0 (ASCII) nor 1 (binary)");
  if (file_type == 1) {
    if (data_size != 4 && data_size != 8) fail("binary data size " + std::to_string(data_size) + " is neither 4 nor 8");
    end_of_header_line();
    ByteCursor bc(tc_.text(), tc_.file(), tc_.offset());
    uint32_t one = bc.read<uint32_t>("the binary one-marker");
    if (one == __builtin_bswap32(1u))
      swap_ = true;
    else if (one != 1)
      bc.fail("binary one-marker is " + std::to_string(one) + ", not 1 in either byte order");
    tc_.seek(bc.offset());
    binary_ = true;
    size_bytes_ = static_cast<int>(data_size);
  }
  expect("$EndMeshFormat");
}

// Skips a section line by line to its $End marker.
void GmshReader::skip_section(std::string_view name) {
  std::string end_marker = "$End" + std::string(name.substr(1));
  std::string_view l;
  tc_.line(l);
  while (tc_.line(l)) {
    size_t first = l.find_first_not_of(" \t");
    if (first != std::string_view::npos && l.substr(first) == end_marker) return;
  }
  fail("section " + std::string(name.substr(0, 40)) + " has no " + end_marker.substr(0, 44));
}

void GmshReader::skip_values(Fields& f, uint64_t n, bool reals, const char* what) {
  for (uint64_t i = 0; i < n; ++i) {
    if (reals)
      f.real(what);
    else
      f.integer(what);
  }
}

// $Entities / $PartitionedEntities: read through for their layout only.
void GmshReader::entities(bool partitioned) {
  if (binary_) end_of_header_line();
  Fields f = fields();
  f.begin();
  if (partitioned) {
    f.size("number of partitions");
    uint64_t ghosts = f.count("number of ghost entities", 2, 8);
    skip_values(f, 2 * ghosts, false, "ghost entity");
  }
  uint64_t counts[4];
  const char* names[4] = {"number of point entities", "number of curve entities", "number of surface entities",
                          "number of volume entities"};
  for (int d = 0; d < 4; ++d) counts[d] = f.size(names[d]);
  for (int d = 0; d < 4; ++d) {
    uint64_t reals = d == 0 ? 3 : 6;
    uint64_t n = counts[d];
    for (uint64_t i = 0; i < n; ++i) {
      f.integer("entity tag");
      if (partitioned) {
        f.integer("parent dimension");
        f.integer("parent tag");
        skip_values(f, f.count("number of partitions", 1, 4), false, "partition tag");
      }
      skip_values(f, reals, true, "entity coordinate");
      skip_values(f, f.count("number of physical tags", 1, 4), false, "physical tag");
      if (d > 0) skip_values(f, f.count("number of bounding entities", 1, 4), false, "bounding entity");
    }
  }
  f.end();
  expect(partitioned ? "$EndPartitionedEntities" : "$EndEntities");
}

void GmshReader::nodes() {
  if (have_nodes_) fail("second $Nodes section");
  have_nodes_ = true;
  if (binary_) end_of_header_line();
  Fields f = fields();
  f.begin();
  uint64_t sb = f.size_bytes();
  uint64_t blocks = f.count("number of node blocks", 4, 12 + sb);
  uint64_t n = f.count("number of nodes", 4, sb + 24);
  if (n > UINT32_MAX) f.fail(std::to_string(n) + " nodes are more than partet can index");
  f.size("minimum node tag");
  f.size("maximum node tag");
  std::vector<uint64_t> tags(n);
  mesh_.xyz.resize(3 * n);
  uint64_t done = 0;
  for (uint64_t b = 0; b < blocks; ++b) {
    int64_t dim = f.integer("entity dimension");
    if (dim < 0 || dim > 3) f.fail("node block entity dimension " + std::to_string(dim) + " is not 0..3");
    f.integer("entity tag");
    int64_t parametric = f.integer("parametric flag");
    if (parametric != 0 && parametric != 1) f.fail("parametric flag " + std::to_string(parametric) + " is not 0 or 1");
    uint64_t extra = parametric ? static_cast<uint64_t>(dim) : 0;
    uint64_t m = f.count("number of nodes in block", 4 + extra, sb + 8 * (3 + extra));
    if (m > n - done) f.fail("node blocks hold more nodes than the " + std::to_string(n) + " announced");
    for (uint64_t i = 0; i < m; ++i) {
      uint64_t t = f.size("node tag");
      if (t == 0) f.fail("node tag 0 (tags start at 1)");
      tags[done + i] = t;
    }
    for (uint64_t i = 0; i < m; ++i) {
      for (int k = 0; k < 3; ++k) mesh_.xyz[3 * (done + i) + k] = f.real("node coordinate");
      skip_values(f, extra, true, "node parametric coordinate");
    }
    done += m;
  }
  if (done != n) f.fail("$Nodes announces " + std::to_string(n) + " nodes but its blocks hold " + std::to_string(done));
  f.end();
  expect("$EndNodes");
  uint64_t repeated = 0;
  if (!node_index_.build(tags, repeated)) fail("node tag " + std::to_string(repeated) + " appears twice in $Nodes");
}

void GmshReader::elements() {
  if (have_elements_) fail("second $Elements section");
  if (!have_nodes_) fail("$Elements before $Nodes");
  have_elements_ = true;
  if (binary_) end_of_header_line();
  Fields f = fields();
  f.begin();
  uint64_t sb = f.size_bytes();
  uint64_t blocks = f.count("number of element blocks", 4, 12 + sb);
  uint64_t total = f.count("number of elements", 2, 2 * sb);
  f.size("minimum element tag");
  f.size("maximum element tag");
  uint64_t done = 0;
  for (uint64_t b = 0; b < blocks; ++b) {
    f.integer("entity dimension");
    f.integer("entity tag");
    int64_t type = f.integer("element type");
    const ElementType* et = find_element_type(type);
    if (et == nullptr) f.fail("unknown element type " + std::to_string(type));
    uint64_t per = 1 + static_cast<uint64_t>(et->nodes);
    uint64_t m = f.count("number of elements in block", per, per * sb);
    if (m > total - done) f.fail("element blocks hold more elements than the " + std::to_string(total) + " announced");
    done += m;
    std::vector<uint32_t>* keep = nullptr;
    if (et->type == 2)
      keep = &mesh_.tris;
    else if (et->type == 4 && what_ == MeshRead::kVolume)
      keep = &mesh_.tets;
    if (m > 0 && what_ == MeshRead::kSurface && et->dim == 2 && et->type != 2)
      f.fail(std::to_string(m) + " faces are of type " + std::to_string(type) + " (" + et->name +
             "); partet meshes triangle surfaces only");
    if (m > 0 && what_ == MeshRead::kVolume && et->dim == 3 && et->type != 4)
      f.fail(std::to_string(m) + " elements are of type " + std::to_string(type) + " (" + et->name +
             "); partet reads linear tetrahedral meshes only");
    if (keep != nullptr) keep->reserve(keep->size() + m * et->nodes);
    for (uint64_t i = 0; i < m; ++i) {
      uint64_t element = f.size("element tag");
      for (int k = 0; k < et->nodes; ++k) {
        uint64_t t = f.size("node tag");
        if (keep == nullptr) continue;
        uint32_t index = 0;
        if (!node_index_.find(t, index))
          f.fail("element " + std::to_string(element) + " refers to node tag " + std::to_string(t) +
                 ", which is not in $Nodes");
        keep->push_back(index);
      }
    }
  }
  if (done != total)
    f.fail("$Elements announces " + std::to_string(total) + " elements but its blocks hold " + std::to_string(done));
  f.end();
  expect("$EndElements");
}

TetMesh GmshReader::read() {
  mesh_format();
  while (!(have_nodes_ && have_elements_) && tc_.has_token()) {
    std::string_view name = tc_.token("section");
    if (name.size() < 2 || name[0] != '$')
      fail("expected a section ($Name), found '" + std::string(name.substr(0, 40)) + "'");
    if (name == "$Entities")
      entities(false);
    else if (name == "$PartitionedEntities")
      entities(true);
    else if (name == "$Nodes")
      nodes();
    else if (name == "$Elements")
      elements();
    else
      skip_section(name);
  }
  if (!have_nodes_) fail("no $Nodes section");
  if (!have_elements_) fail("no $Elements section");
  return std::move(mesh_);
}

// Writes the values of a section as text (separated by spaces, lines ended
// by end_line()) or as native binary values (end_line() writes nothing).
class GmshWriter {
 public:
  explicit GmshWriter(bool binary) : binary_(binary) {}

  void text(const char* s) { out_ += s; }
  void size(uint64_t v) {
    if (binary_) return raw(v);
    append_uint(out_, v);
    out_ += ' ';
  }
  void integer(int32_t v) {
    if (binary_) return raw(v);
    out_ += std::to_string(v);
    out_ += ' ';
  }
  void real(double v) {
    if (binary_) return raw(v);
    append_real(out_, v);
    out_ += ' ';
  }
  void end_line() {
    if (!binary_ && !out_.empty() && out_.back() == ' ') out_.back() = '\n';
  }
  // Ends a section's data: binary data is followed by a line break.
  void end_section(const char* marker) {
    if (binary_) out_ += '\n';
    out_ += marker;
    out_ += '\n';
  }
  void reserve(size_t n) { out_.reserve(n); }
  std::string take() { return std::move(out_); }

 private:
  template <class T>
  void raw(T v) {
    out_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }

  bool binary_;
  std::string out_;
};

void write_entities(GmshWriter& w, const TetMesh& mesh) {
  double box[6] = {0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < mesh.num_vertices(); ++i) {
    for (int k = 0; k < 3; ++k) {
      double c = mesh.xyz[3 * i + k];
      if (i == 0 || c < box[k]) box[k] = c;
      if (i == 0 || c > box[3 + k]) box[3 + k] = c;
    }
  }
  bool surface = !mesh.tris.empty();
  w.text("$Entities\n");
  w.size(0);
  w.size(0);
  w.size(surface ? 1 : 0);
  w.size(1);
  w.end_line();
  if (surface) {
    w.integer(1);
    for (double c : box) w.real(c);
    w.size(0);  // physical tags
    w.size(0);  // bounding curves
    w.end_line();
  }
  w.integer(1);
  for (double c : box) w.real(c);
  w.size(0);  // physical tags
  w.size(surface ? 1 : 0);
  if (surface) w.integer(1);
  w.end_line();
  w.end_section("$EndEntities");
}

void write_nodes(GmshWriter& w, const TetMesh& mesh) {
  uint64_t n = mesh.num_vertices();
  w.text("$Nodes\n");
  w.size(n > 0 ? 1 : 0);
  w.size(n);
  w.size(n > 0 ? 1 : 0);
  w.size(n);
  w.end_line();
  if (n > 0) {
    w.integer(3);
    w.integer(1);
    w.integer(0);
    w.size(n);
    w.end_line();
    for (uint64_t i = 1; i <= n; ++i) {
      w.size(i);
      w.end_line();
    }
    for (uint64_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) w.real(mesh.xyz[3 * i + k]);
      w.end_line();
    }
  }
  w.end_section("$EndNodes");
}

void write_block(GmshWriter& w, int dim, int type, const std::vector<uint32_t>& v, size_t corners, uint64_t& tag) {
  size_t m = v.size() / corners;
  w.integer(dim);
  w.integer(1);
  w.integer(type);
  w.size(m);
  w.end_line();
  for (size_t i = 0; i < m; ++i) {
    w.size(tag++);
    for (size_t k = 0; k < corners; ++k) w.size(static_cast<uint64_t>(v[corners * i + k]) + 1);
    w.end_line();
  }
}

void write_elements(GmshWriter& w, const TetMesh& mesh) {
  uint64_t total = mesh.num_triangles() + mesh.num_tets();
  uint64_t blocks = (mesh.tris.empty() ? 0 : 1) + (mesh.tets.empty() ? 0 : 1);
  w.text("$Elements\n");
  w.size(blocks);
  w.size(total);
  w.size(total > 0 ? 1 : 0);
  w.size(total);
  w.end_line();
  uint64_t tag = 1;
  if (!mesh.tris.empty()) write_block(w, 2, 2, mesh.tris, 3, tag);
  if (!mesh.tets.empty()) write_block(w, 3, 4, mesh.tets, 4, tag);
  w.end_section("$EndElements");
}

}  // namespace

TetMesh parse_gmsh(std::string_view bytes, const std::string& file, MeshRead what) {
  return GmshReader(bytes, file, what).read();
}

std::string format_gmsh(const TetMesh& mesh, bool binary) {
  GmshWriter w(binary);
  w.reserve(mesh.num_vertices() * (binary ? 32 : 80) + (mesh.tets.size() + mesh.tris.size()) * (binary ? 8 : 10) +
            1024);
  w.text(binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
  if (binary) {
    w.integer(1);
    w.text("\n");
  }
  w.text("$EndMeshFormat\n");
  write_entities(w, mesh);
  write_nodes(w, mesh);
  write_elements(w, mesh);
  return w.take();
}

}  // namespace partet
