// Medit .mesh (ASCII) reader and writer.
// Reads MeshVersionFormatted 1-4 with Dimension 3: Vertices (x y z ref),
// Triangles (a b c ref), Tetrahedra (a b c d ref); the other sections of the
// format are skipped by their record length; '#' starts a comment; keywords
// are case-sensitive; "End" (or the end of the file) ends the mesh. A surface
// read keeps vertices and triangles and refuses non-triangle faces; a volume
// read keeps tets and triangles too and refuses non-tet volume elements.
// Indices are 1-based in the file, checked against the vertex count; counts
// are checked against the bytes left before anything is allocated.
#include <cstdint>
#include <string>

#include "io/mesh_formats.hpp"
#include "io/text_cursor.hpp"
#include "io/text_writer.hpp"

namespace partet {

namespace {

enum class Role {
  kSkip,        // known section, skipped record by record
  kVertices,    // x y z ref
  kTriangles,   // a b c ref
  kTets,        // a b c d ref
  kOtherFaces,  // faces a surface read refuses
  kOtherCells,  // volume elements a volume read refuses
};

struct Section {
  const char* keyword;
  int tokens;  // per record
  Role role;
  const char* noun;  // plural, for messages
};

// Record lengths for Dimension 3 (libMeshb's keyword table).
constexpr Section kSections[] = {
    {"Vertices", 4, Role::kVertices, "vertices"},
    {"Triangles", 4, Role::kTriangles, "triangles"},
    {"Tetrahedra", 5, Role::kTets, "tetrahedra"},
    {"Edges", 3, Role::kSkip, "edges"},
    {"Quadrilaterals", 5, Role::kOtherFaces, "quadrilaterals"},
    {"TrianglesP2", 7, Role::kOtherFaces, "second-order triangles"},
    {"QuadrilateralsQ2", 10, Role::kOtherFaces, "second-order quadrilaterals"},
    {"Hexahedra", 9, Role::kOtherCells, "hexahedra"},
    {"Prisms", 7, Role::kOtherCells, "prisms"},
    {"Pyramids", 6, Role::kOtherCells, "pyramids"},
    {"TetrahedraP2", 11, Role::kOtherCells, "second-order tetrahedra"},
    {"HexahedraQ2", 28, Role::kOtherCells, "second-order hexahedra"},
    {"EdgesP2", 4, Role::kSkip, "second-order edges"},
    {"Corners", 1, Role::kSkip, "corners"},
    {"Ridges", 1, Role::kSkip, "ridges"},
    {"RequiredVertices", 1, Role::kSkip, "required vertices"},
    {"RequiredEdges", 1, Role::kSkip, "required edges"},
    {"RequiredTriangles", 1, Role::kSkip, "required triangles"},
    {"RequiredQuadrilaterals", 1, Role::kSkip, "required quadrilaterals"},
    {"Normals", 3, Role::kSkip, "normals"},
    {"NormalAtVertices", 2, Role::kSkip, "normals at vertices"},
    {"NormalAtTriangleVertices", 3, Role::kSkip, "normals at triangle vertices"},
    {"NormalAtQuadrilateralVertices", 3, Role::kSkip, "normals at quadrilateral vertices"},
    {"Tangents", 3, Role::kSkip, "tangents"},
    {"TangentAtVertices", 2, Role::kSkip, "tangents at vertices"},
    {"TangentAtEdges", 3, Role::kSkip, "tangents at edges"},
};

const Section* find_section(std::string_view keyword) {
  for (const Section& s : kSections)
    if (keyword == s.keyword) return &s;
  return nullptr;
}

class MeditReader {
 public:
  MeditReader(std::string_view bytes, const std::string& file, MeshRead what) : tc_(bytes, file, '#'), what_(what) {}

  TetMesh read();

 private:
  void header();
  void section(const Section& s);
  void vertices(uint64_t n);
  void elements(uint64_t n, int corners, std::vector<uint32_t>& out, const char* noun);
  void skip_records(uint64_t n, int tokens);
  void skip_string();

  TextCursor tc_;
  MeshRead what_;
  TetMesh mesh_;
  bool have_vertices_ = false;
};

void MeditReader::header() {
  std::string_view t = tc_.token("MeshVersionFormatted");
  if (t != "MeshVersionFormatted")
    tc_.fail("not a Medit mesh: expected 'MeshVersionFormatted', found '" + std::string(t.substr(0, 40)) + "'");
  int64_t version = tc_.integer("mesh version");
  if (version < 1 || version > 4) tc_.fail("unsupported MeshVersionFormatted " + std::to_string(version));
}

void MeditReader::vertices(uint64_t n) {
  if (have_vertices_) tc_.fail("second Vertices section");
  have_vertices_ = true;
  if (n > UINT32_MAX) tc_.fail(std::to_string(n) + " vertices are more than partet can index");
  mesh_.xyz.resize(3 * n);
  for (uint64_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) mesh_.xyz[3 * i + k] = tc_.real("vertex coordinate");
    tc_.integer("vertex reference");
  }
}

void MeditReader::elements(uint64_t n, int corners, std::vector<uint32_t>& out, const char* noun) {
  if (!out.empty()) tc_.fail(std::string("second section of ") + noun);
  uint64_t nv = mesh_.num_vertices();
  out.resize(n * corners);
  for (uint64_t i = 0; i < n; ++i) {
    for (int k = 0; k < corners; ++k) {
      int64_t v = tc_.integer("vertex index");
      if (v < 1 || static_cast<uint64_t>(v) > nv)
        tc_.fail(std::string(noun) + " " + std::to_string(i + 1) + ": vertex index " + std::to_string(v) +
                 " is out of range 1.." + std::to_string(nv) + (have_vertices_ ? "" : " (no Vertices before it)"));
      out[corners * i + k] = static_cast<uint32_t>(v - 1);
    }
    tc_.integer("element reference");
  }
}

void MeditReader::skip_records(uint64_t n, int tokens) {
  for (uint64_t i = 0; i < n; ++i)
    for (int k = 0; k < tokens; ++k) tc_.token("section data");
}

// Identifier and Geometry hold one string, quoted when it has spaces.
void MeditReader::skip_string() {
  std::string_view t = tc_.token("string");
  if (t.front() != '"' || (t.size() > 1 && t.back() == '"')) return;
  do {
    t = tc_.token("closing quote");
  } while (t.back() != '"');
}

void MeditReader::section(const Section& s) {
  // Each token takes at least one character and one separator.
  uint64_t limit = (tc_.size() - tc_.offset()) / (2 * static_cast<uint64_t>(s.tokens)) + 1;
  uint64_t n = tc_.count((std::string("number of ") + s.noun).c_str(), limit);
  switch (s.role) {
    case Role::kVertices:
      vertices(n);
      return;
    case Role::kTriangles:
      elements(n, 3, mesh_.tris, "triangle");
      return;
    case Role::kTets:
      if (what_ == MeshRead::kVolume)
        elements(n, 4, mesh_.tets, "tetrahedron");
      else
        skip_records(n, s.tokens);
      return;
    case Role::kOtherFaces:
      if (what_ == MeshRead::kSurface && n > 0)
        tc_.fail(std::to_string(n) + " faces are " + s.noun + "; partet meshes triangle surfaces only");
      skip_records(n, s.tokens);
      return;
    case Role::kOtherCells:
      if (what_ == MeshRead::kVolume && n > 0)
        tc_.fail(std::to_string(n) + " elements are " + s.noun + "; partet reads tetrahedral meshes only");
      skip_records(n, s.tokens);
      return;
    case Role::kSkip:
      skip_records(n, s.tokens);
      return;
  }
}

TetMesh MeditReader::read() {
  header();
  bool have_dimension = false;
  while (tc_.has_token()) {
    std::string_view key = tc_.token("keyword");
    if (key == "End") break;
    if (key == "Dimension") {
      int64_t d = tc_.integer("dimension");
      if (d != 3) tc_.fail("Dimension " + std::to_string(d) + " mesh; partet reads 3D meshes only");
      have_dimension = true;
      continue;
    }
    if (key == "Identifier" || key == "Geometry") {
      skip_string();
      continue;
    }
    const Section* s = find_section(key);
    if (s == nullptr) tc_.fail("unknown Medit keyword '" + std::string(key.substr(0, 40)) + "'");
    if (!have_dimension) tc_.fail(std::string(s->keyword) + " before Dimension");
    section(*s);
  }
  if (!have_vertices_) tc_.fail("no Vertices section");
  return std::move(mesh_);
}

void append_elements(std::string& out, const char* keyword, const std::vector<uint32_t>& v, size_t corners) {
  size_t n = v.size() / corners;
  out += keyword;
  out += '\n';
  append_uint(out, n);
  out += '\n';
  for (size_t i = 0; i < n; ++i) {
    for (size_t k = 0; k < corners; ++k) {
      append_uint(out, static_cast<uint64_t>(v[corners * i + k]) + 1);
      out += ' ';
    }
    out += "1\n";
  }
  out += '\n';
}

}  // namespace

TetMesh parse_medit(std::string_view bytes, const std::string& file, MeshRead what) {
  return MeditReader(bytes, file, what).read();
}

std::string format_medit(const TetMesh& mesh) {
  std::string out = "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n";
  size_t nv = mesh.num_vertices();
  out.reserve(out.size() + nv * 75 + mesh.tets.size() * 10 + mesh.tris.size() * 10 + 64);
  append_uint(out, nv);
  out += '\n';
  for (size_t i = 0; i < nv; ++i) {
    for (int k = 0; k < 3; ++k) {
      append_real(out, mesh.xyz[3 * i + k]);
      out += ' ';
    }
    out += "1\n";
  }
  out += '\n';
  if (!mesh.tris.empty()) append_elements(out, "Triangles", mesh.tris, 3);
  append_elements(out, "Tetrahedra", mesh.tets, 4);
  out += "End\n";
  return out;
}

}  // namespace partet
