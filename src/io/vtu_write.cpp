// VTK XML UnstructuredGrid (.vtu) and parallel index (.pvtu) writers.
// A .vtu holds one Piece: Points (Float64 x 3), Cells (connectivity and
// offsets Int64, types UInt8 = 10, tetrahedra only: boundary triangles are
// not cells), and PointData "GlobalNodeId" (Int64) when the mesh has global
// ids. Arrays are inline base64 of [UInt64 byte count][data] in the host's
// byte order (declared in byte_order), as ParaView, VTK and meshio read.
#include <bit>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/base64.hpp"
#include "io/mesh_formats.hpp"
#include "io/xml_scan.hpp"

namespace partet {

namespace {

constexpr const char* kByteOrder = std::endian::native == std::endian::big ? "BigEndian" : "LittleEndian";

// `id_type`: VTK's mark of an id array (vtkIdTypeArray), as it writes global ids.
void open_array(std::string& out, const char* indent, const char* type, const char* name, int components,
                bool id_type = false) {
  out += indent;
  out += "<DataArray type=\"";
  out += type;
  if (id_type) out += "\" IdType=\"1";
  out += "\" Name=\"";
  out += name;
  out += "\"";
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  out += " format=\"binary\">\n";
  out += indent;
  out += "  ";
}

void close_array(std::string& out, const char* indent) {
  out += "\n";
  out += indent;
  out += "</DataArray>\n";
}

// Text passed on to a sink once it holds kPiece bytes (no sink: kept whole).
constexpr size_t kPiece = size_t{1} << 20;

void pass_on(std::string& out, const std::function<void(std::string_view)>* sink) {
  if (!sink || out.size() < kPiece) return;
  (*sink)(out);
  out.clear();
}

// Writes n values value(i) of type T, converted in chunks (no full copy).
template <class T, class F>
void write_values(std::string& out, size_t n, F value, const std::function<void(std::string_view)>* sink) {
  Base64Encoder enc(out);
  uint64_t bytes = n * sizeof(T);
  enc.write(&bytes, sizeof bytes);
  T chunk[1024];
  for (size_t i = 0; i < n;) {
    size_t k = 0;
    for (; k < 1024 && i < n; ++k, ++i) chunk[k] = value(i);
    enc.write(chunk, k * sizeof(T));
    pass_on(out, sink);
  }
  enc.finish();
}

// The .vtu text into `out`, passed on to `sink` in pieces when there is one.
void emit_vtu(const TetMesh& mesh, std::string& out, const std::function<void(std::string_view)>* sink) {
  size_t nv = mesh.num_vertices();
  size_t nt = mesh.num_tets();
  PARTET_ASSERT(mesh.global_ids.empty() || mesh.global_ids.size() == nv, "one global id per vertex");
  out.reserve(sink ? kPiece + 4096 : nv * 36 + mesh.global_ids.size() * 12 + nt * 56 + 1024);
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  out += kByteOrder;
  out += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(nv) + "\" NumberOfCells=\"" + std::to_string(nt) + "\">\n";
  const char* in = "        ";
  if (!mesh.global_ids.empty()) {
    out += "      <PointData GlobalIds=\"GlobalNodeId\">\n";
    open_array(out, in, "Int64", "GlobalNodeId", 1, true);
    write_values<int64_t>(out, nv, [&](size_t i) { return static_cast<int64_t>(mesh.global_ids[i]); }, sink);
    close_array(out, in);
    out += "      </PointData>\n";
  }
  out += "      <Points>\n";
  open_array(out, in, "Float64", "Points", 3);
  write_values<double>(out, 3 * nv, [&](size_t i) { return mesh.xyz[i]; }, sink);
  close_array(out, in);
  out += "      </Points>\n      <Cells>\n";
  open_array(out, in, "Int64", "connectivity", 1);
  write_values<int64_t>(out, 4 * nt, [&](size_t i) { return static_cast<int64_t>(mesh.tets[i]); }, sink);
  close_array(out, in);
  open_array(out, in, "Int64", "offsets", 1);
  write_values<int64_t>(out, nt, [](size_t i) { return static_cast<int64_t>(4 * (i + 1)); }, sink);
  close_array(out, in);
  open_array(out, in, "UInt8", "types", 1);
  write_values<uint8_t>(out, nt, [](size_t) { return uint8_t{10}; }, sink);
  close_array(out, in);
  out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  if (sink) {
    (*sink)(out);
    out.clear();
  }
}

}  // namespace

std::string format_vtu(const TetMesh& mesh) {
  std::string out;
  emit_vtu(mesh, out, nullptr);
  return out;
}

void write_vtu(const TetMesh& mesh, const std::function<void(std::string_view)>& sink) {
  std::string out;
  emit_vtu(mesh, out, &sink);
}

std::string format_pvtu(const std::vector<std::string>& piece_files, bool with_global_ids) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"";
  out += kByteOrder;
  out += "\" header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n";
  if (with_global_ids) {
    out += "    <PPointData GlobalIds=\"GlobalNodeId\">\n";
    out += "      <PDataArray type=\"Int64\" IdType=\"1\" Name=\"GlobalNodeId\"/>\n";
    out += "    </PPointData>\n";
  }
  out +=
      "    <PPoints>\n      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  out += "    <PCells>\n";
  out += "      <PDataArray type=\"Int64\" Name=\"connectivity\"/>\n";
  out += "      <PDataArray type=\"Int64\" Name=\"offsets\"/>\n";
  out += "      <PDataArray type=\"UInt8\" Name=\"types\"/>\n";
  out += "    </PCells>\n";
  for (const std::string& f : piece_files) out += "    <Piece Source=\"" + xml_escape(f) + "\"/>\n";
  out += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace partet
