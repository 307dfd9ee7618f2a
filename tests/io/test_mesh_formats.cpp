// Tests of the mesh formats (Medit, Gmsh 4.1, VTU, PVTU): every writer/reader
// pair round-trips the cube and a mesh of awkward coordinates bit for bit,
// and hand-written files in the other encodings (VTU ascii, appended raw and
// base64, UInt32 headers, big-endian; Gmsh ASCII with entities, physical
// tags, sparse node tags and lower-dimensional elements; byte-swapped binary
// Gmsh; Medit with extra sections) read as expected. Malformed inputs are in
// test_mesh_formats_malformed.cpp, other tools reading our files in
// test_mesh_formats_tools.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/base64.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_file.hpp"
#include "io/mesh_formats.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

void expect_identical(const TetMesh& got, const TetMesh& want, bool with_tris = true) {
  ASSERT_EQ(got.xyz.size(), want.xyz.size());
  for (size_t i = 0; i < want.xyz.size(); ++i)
    ASSERT_EQ(std::bit_cast<uint64_t>(got.xyz[i]), std::bit_cast<uint64_t>(want.xyz[i]))
        << "coordinate " << i << ": " << got.xyz[i] << " vs " << want.xyz[i];
  EXPECT_EQ(got.tets, want.tets);
  if (with_tris) {
    EXPECT_EQ(got.tris, want.tris);
  }
  EXPECT_EQ(got.global_ids, want.global_ids);
}

// Awkward coordinates: decimal fractions, thirds, extremes, subnormals, -0,
// and random bit patterns (finite ones), on random tets and triangles.
TetMesh awkward_mesh() {
  std::vector<double> special = {0.1,
                                 1.0 / 3.0,
                                 -2.0 / 3.0,
                                 1e-300,
                                 -1e300,
                                 4.9406564584124654e-324,
                                 2.2250738585072009e-308,
                                 -1.5e-310,
                                 -0.0,
                                 std::numeric_limits<double>::max(),
                                 std::numeric_limits<double>::lowest(),
                                 std::numeric_limits<double>::min(),
                                 std::nextafter(1.0, 2.0),
                                 123456789.123456789,
                                 3.141592653589793};
  std::mt19937_64 rng(12345);
  TetMesh m;
  for (double v : special) m.xyz.push_back(v);
  while (m.xyz.size() < 3 * 40) {
    double v = std::bit_cast<double>(rng());
    if (std::isfinite(v)) m.xyz.push_back(v);
  }
  uint32_t nv = static_cast<uint32_t>(m.num_vertices());
  for (int i = 0; i < 4 * 30; ++i) m.tets.push_back(static_cast<uint32_t>(rng() % nv));
  for (int i = 0; i < 3 * 10; ++i) m.tris.push_back(static_cast<uint32_t>(rng() % nv));
  return m;
}

TEST(MeshFormatsBase64, Rfc4648Vectors) {
  const char* plain[] = {"", "f", "fo", "foo", "foob", "fooba", "foobar"};
  const char* coded[] = {"", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy"};
  for (int i = 0; i < 7; ++i) {
    std::string out;
    Base64Encoder enc(out);
    for (const char* p = plain[i]; *p; ++p) enc.write(p, 1);  // byte by byte: streaming
    enc.finish();
    EXPECT_EQ(out, coded[i]);
    std::string text = std::string(" ") + coded[i] + "\n";
    Base64Decoder dec(text, 0);
    std::string back(std::strlen(plain[i]), '\0');
    EXPECT_TRUE(dec.read(back.size(), back.data()));
    EXPECT_EQ(back, plain[i]);
  }
  // Two padded streams back to back read as one byte sequence.
  std::string text = "Zg==Zm8=";
  Base64Decoder dec(text, 0);
  char three[3];
  ASSERT_TRUE(dec.read(3, three));
  EXPECT_EQ(std::string(three, 3), "ffo");
  EXPECT_FALSE(dec.read(1, three));
}

TEST(MeshFormatsRoundTrip, CubeThroughEveryFormat) {
  TetMesh cube = test::cube_tets();
  expect_identical(parse_medit(format_medit(cube), "c.mesh", MeshRead::kVolume), cube);
  expect_identical(parse_gmsh(format_gmsh(cube, false), "c.msh", MeshRead::kVolume), cube);
  expect_identical(parse_gmsh(format_gmsh(cube, true), "c.msh", MeshRead::kVolume), cube);
  TetMesh vtu = parse_vtu(format_vtu(cube), "c.vtu");
  expect_identical(vtu, cube, false);
  EXPECT_TRUE(vtu.tris.empty()) << "boundary triangles are not VTU cells";
}

TEST(MeshFormatsRoundTrip, AwkwardCoordinatesBitExact) {
  TetMesh m = awkward_mesh();
  expect_identical(parse_medit(format_medit(m), "a.mesh", MeshRead::kVolume), m);
  expect_identical(parse_gmsh(format_gmsh(m, false), "a.msh", MeshRead::kVolume), m);
  expect_identical(parse_gmsh(format_gmsh(m, true), "a.msh", MeshRead::kVolume), m);
  expect_identical(parse_vtu(format_vtu(m), "a.vtu"), m, false);
}

TEST(MeshFormatsRoundTrip, VtuGlobalIds) {
  TetMesh m = awkward_mesh();
  for (size_t i = 0; i < m.num_vertices(); ++i) m.global_ids.push_back(1000000007ull * (i + 1));
  m.global_ids.back() = (1ull << 63) | 5;  // partet's surface vertex ids use the top bit
  std::string text = format_vtu(m);
  EXPECT_NE(text.find("Name=\"GlobalNodeId\""), std::string::npos);
  expect_identical(parse_vtu(text, "g.vtu"), m, false);
}

// A .vtu file is streamed to disk in pieces of about a megabyte: the file
// of a mesh spanning several pieces holds exactly format_vtu's text, and
// reads back bit-exact.
TEST(MeshFormatsRoundTrip, StreamedVtuFileEqualsFormattedText) {
  std::mt19937_64 rng(7);
  TetMesh m;
  for (int i = 0; i < 3 * 20000; ++i) m.xyz.push_back(std::ldexp(static_cast<double>(rng() >> 11), -40));
  for (int i = 0; i < 4 * 60000; ++i) m.tets.push_back(static_cast<uint32_t>(rng() % 20000));
  const std::string path = test::scratch_dir("streamed_vtu") + "/big.vtu";
  write_volume_file(m, path, {});
  const std::string bytes = read_file_bytes(path);
  EXPECT_GT(bytes.size(), size_t{3} << 20);
  EXPECT_TRUE(bytes == format_vtu(m));
  expect_identical(parse_vtu(bytes, path), m, false);
}

TEST(MeshFormatsRoundTrip, SurfaceReadsKeepTrianglesOnly) {
  TetMesh cube = test::cube_tets();
  for (const TetMesh& s : {parse_medit(format_medit(cube), "c.mesh", MeshRead::kSurface),
                           parse_gmsh(format_gmsh(cube, false), "c.msh", MeshRead::kSurface),
                           parse_gmsh(format_gmsh(cube, true), "c.msh", MeshRead::kSurface)}) {
    EXPECT_EQ(s.xyz, cube.xyz);
    EXPECT_EQ(s.tris, cube.tris);
    EXPECT_TRUE(s.tets.empty());
  }
}

TEST(MeshFormatsRoundTrip, EmptyAndTrianglelessMeshes) {
  TetMesh empty;
  expect_identical(parse_medit(format_medit(empty), "e.mesh", MeshRead::kVolume), empty);
  expect_identical(parse_gmsh(format_gmsh(empty, false), "e.msh", MeshRead::kVolume), empty);
  expect_identical(parse_gmsh(format_gmsh(empty, true), "e.msh", MeshRead::kVolume), empty);
  expect_identical(parse_vtu(format_vtu(empty), "e.vtu"), empty);
  TetMesh cube = test::cube_tets();
  cube.tris.clear();
  expect_identical(parse_gmsh(format_gmsh(cube, true), "c.msh", MeshRead::kVolume), cube);
  expect_identical(parse_medit(format_medit(cube), "c.mesh", MeshRead::kVolume), cube);
}

TEST(MeshFormatsRoundTrip, PvtuIndexListsPieces) {
  std::vector<std::string> pieces = {"out_0.vtu", "dir/out_1.vtu", "odd & \"quoted\" <name>.vtu"};
  for (bool ids : {false, true}) {
    std::string text = format_pvtu(pieces, ids);
    EXPECT_EQ(parse_pvtu_pieces(text, "i.pvtu"), pieces);
    EXPECT_EQ(text.find("PPointData") != std::string::npos, ids);
    EXPECT_NE(text.find("type=\"PUnstructuredGrid\""), std::string::npos);
  }
}

// The unit cube as the hand-written files below list it: corner i at
// (i&1, i&2, i&4), 6 tets around the 0-7 diagonal, 12 outward triangles.
TetMesh hand_cube() {
  TetMesh m = test::cube_tets();
  m.tets = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};
  m.tris = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return m;
}

// Index of a unit-cube corner from its coordinates (as in hand_cube()).
uint32_t corner(const TetMesh& m, uint32_t v) {
  const double* p = m.point(v);
  return static_cast<uint32_t>(p[0] + 2 * p[1] + 4 * p[2]);
}

// The elements of a unit-cube mesh renumbered by corner, for comparison with
// hand_cube() whatever the vertex order of the file.
std::vector<uint32_t> by_corner(const TetMesh& m, const std::vector<uint32_t>& elements) {
  std::vector<uint32_t> out;
  for (uint32_t v : elements) out.push_back(corner(m, v));
  return out;
}

TEST(MeshFormatsGmsh, Ascii41WithEntitiesPhysicalTagsSparseNodesAndLowerElements) {
  const std::string text = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 7 "edge"
2 1 "skin of $EndEntities"
3 2 "body"
$EndPhysicalNames
$Comments
a comment section holding a line that reads
$Nodes
$EndComments
$Entities
1 1 2 1
1 0 0 0 0
1 0 0 0 1 0 0 1 7 2 1 -1
1 0 0 0 1 1 0 1 1 1 1
2 0 0 0 1 1 1 0 0
1 0 0 0 1 1 1 1 2 2 1 2
$EndEntities
$Nodes
3 8 10 80
0 1 0 1
10
0 0 0
2 1 1 3
20
40
30
1 0 0 0.5 0.5
1 1 0 0.25 0.75
0 1 0 0 1
3 1 0 4
80
50
60
70
1 1 1
0 0 1
1 0 1
0 1 1
$EndNodes
$Elements
5 21 1 521
0 1 15 1
1 10
1 1 1 2
2 10 20
3 20 40
2 1 2 6
100 10 30 20
101 20 30 40
102 50 60 70
103 60 80 70
104 10 20 50
105 20 60 50
2 2 2 6
200 30 70 40
201 40 70 80
202 10 50 30
203 30 50 70
204 20 40 60
205 40 80 60
3 1 4 6
500 10 20 40 80
510 10 40 30 80
511 10 30 70 80
512 10 70 50 80
520 10 50 60 80
521 10 60 20 80
$EndElements
$NodeData
1
"temperature"
1
0.0
3
0
1
8
10 1.0
$EndNodeData
)";
  TetMesh cube = hand_cube();
  TetMesh m = parse_gmsh(text, "hand.msh", MeshRead::kVolume);
  ASSERT_EQ(m.num_vertices(), 8u);
  EXPECT_EQ(m.point(1)[0], 1.0);  // file order is kept: tag 20 is the second node
  EXPECT_EQ(by_corner(m, m.tets), cube.tets);
  EXPECT_EQ(by_corner(m, m.tris), cube.tris);
  TetMesh s = parse_gmsh(text, "hand.msh", MeshRead::kSurface);
  EXPECT_EQ(by_corner(s, s.tris), cube.tris);
  EXPECT_TRUE(s.tets.empty());
}

// A binary Gmsh file built value by value, in either byte order.
class BinaryMsh {
 public:
  BinaryMsh(bool swap, int size_bytes) : swap_(swap), size_bytes_(size_bytes) {}
  void text(const std::string& s) { out_ += s; }
  void i32(int32_t v) { put(v); }
  void f64(double v) { put(v); }
  void size(uint64_t v) {
    if (size_bytes_ == 4)
      put(static_cast<uint32_t>(v));
    else
      put(v);
  }
  std::string take() { return std::move(out_); }

 private:
  template <class T>
  void put(T v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    if (swap_) std::reverse(b, b + sizeof v);
    out_.append(b, sizeof v);
  }
  bool swap_;
  int size_bytes_;
  std::string out_;
};

std::string binary_cube_msh(bool swap, int size_bytes) {
  TetMesh cube = test::cube_tets();
  BinaryMsh b(swap, size_bytes);
  b.text("$MeshFormat\n4.1 1 " + std::to_string(size_bytes) + "\n");
  b.i32(1);
  b.text("\n$EndMeshFormat\n$PhysicalNames\n1\n3 2 \"body\"\n$EndPhysicalNames\n$Entities\n");
  for (uint64_t n : {1, 0, 1, 1}) b.size(n);
  b.i32(1);
  for (int k = 0; k < 3; ++k) b.f64(0);
  b.size(1);
  b.i32(5);
  b.i32(1);  // surface: no physical tags, no bounding curves
  for (int k = 0; k < 6; ++k) b.f64(k < 3 ? 0 : 1);
  b.size(0);
  b.size(0);
  b.i32(1);  // volume: physical tags 1 and 2, bounded by surface 1
  for (int k = 0; k < 6; ++k) b.f64(k < 3 ? 0 : 1);
  b.size(2);
  b.i32(1);
  b.i32(2);
  b.size(1);
  b.i32(1);
  b.text("\n$EndEntities\n$PartitionedEntities\n");
  b.size(2);  // partitions
  b.size(1);  // one ghost entity: tag, partition
  b.i32(3);
  b.i32(2);
  for (uint64_t n : {0, 0, 0, 1}) b.size(n);
  b.i32(4);  // volume 4 of volume 1, in partition 1
  b.i32(3);
  b.i32(1);
  b.size(1);
  b.i32(1);
  for (int k = 0; k < 6; ++k) b.f64(k < 3 ? 0 : 1);
  b.size(0);
  b.size(0);
  b.text("\n$EndPartitionedEntities\n$Nodes\n");
  for (uint64_t n : {2, 8, 10, 80}) b.size(n);
  for (int block = 0; block < 2; ++block) {
    b.i32(block == 0 ? 2 : 3);
    b.i32(1);
    b.i32(0);
    b.size(4);
    for (int v = 4 * block; v < 4 * block + 4; ++v) b.size(10 * (v + 1));
    for (int v = 4 * block; v < 4 * block + 4; ++v)
      for (int k = 0; k < 3; ++k) b.f64(cube.xyz[3 * v + k]);
  }
  b.text("\n$EndNodes\n$Elements\n");
  for (uint64_t n : {2, 7, 1, 7}) b.size(n);
  b.i32(1);  // one line
  b.i32(1);
  b.i32(1);
  b.size(1);
  for (uint64_t v : {1, 10, 20}) b.size(v);
  b.i32(3);
  b.i32(1);
  b.i32(4);
  b.size(6);
  for (int t = 0; t < 6; ++t) {
    b.size(2 + t);
    for (int k = 0; k < 4; ++k) b.size(10 * (cube.tets[4 * t + k] + 1));
  }
  b.text("\n$EndElements\n");
  return b.take();
}

TEST(MeshFormatsGmsh, BinaryInBothByteOrdersAndSizeWidths) {
  TetMesh cube = test::cube_tets();
  cube.tris.clear();
  for (bool swap : {false, true}) {
    for (int size_bytes : {4, 8}) {
      TetMesh m = parse_gmsh(binary_cube_msh(swap, size_bytes), "b.msh", MeshRead::kVolume);
      expect_identical(m, cube);
    }
  }
}

TEST(MeshFormatsGmsh, WriterLayout) {
  TetMesh cube = hand_cube();
  std::string ascii = format_gmsh(cube, false);
  EXPECT_EQ(ascii.rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 1\n", 0), 0u);
  EXPECT_NE(ascii.find("$Nodes\n1 8 1 8\n3 1 0 8\n1\n2\n"), std::string::npos);
  EXPECT_NE(ascii.find("$Elements\n2 18 1 18\n2 1 2 12\n1 1 3 2\n"), std::string::npos);
  EXPECT_NE(ascii.find("3 1 4 6\n13 1 2 4 8\n"), std::string::npos);
  std::string binary = format_gmsh(cube, true);
  const char head[] = "$MeshFormat\n4.1 1 8\n\1\0\0\0\n$EndMeshFormat\n$Entities\n";
  EXPECT_EQ(binary.rfind(std::string(head, sizeof head - 1), 0), 0u);
}

TEST(MeshFormatsMedit, ExtraSectionsCommentsAndLayout) {
  const std::string text = R"(# written by hand
MeshVersionFormatted 1
Dimension
3
Identifier "a cube, with spaces"
Vertices
8
0 0 0 1
1 0 0 1
0 1 0 1
1 1 0 1
0 0 1 1
1 0 1 1
0 1 1 1
1 1 1   1   # a comment after a record
Edges 1
1 2 3
Corners 2 1 8
Ridges
1
1
RequiredVertices 1 3
Normals
1
0 0 1
NormalAtVertices
1
1 1
Quadrilaterals
0
Triangles
12
1 3 2 0  2 3 4 0  5 6 7 0  6 8 7 0  1 2 5 0  2 6 5 0
3 7 4 0  4 7 8 0  1 5 3 0  3 5 7 0  2 4 6 0  4 8 6 0
Tetrahedra
6
1 2 4 8 3
1 4 3 8 3
1 3 7 8 3
1 7 5 8 3
1 5 6 8 3
1 6 2 8 3
End
)";
  TetMesh cube = hand_cube();
  expect_identical(parse_medit(text, "hand.mesh", MeshRead::kVolume), cube);
  TetMesh s = parse_medit(text, "hand.mesh", MeshRead::kSurface);
  EXPECT_EQ(s.tris, cube.tris);
  EXPECT_TRUE(s.tets.empty());
  std::string out = format_medit(cube);
  EXPECT_EQ(out.rfind("MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n8\n0 0 0 1\n1 0 0 1\n", 0), 0u);
  EXPECT_NE(out.find("Triangles\n12\n1 3 2 1\n2 3 4 1\n"), std::string::npos);
  EXPECT_NE(out.find("Tetrahedra\n6\n1 2 4 8 1\n"), std::string::npos);
  EXPECT_EQ(out.substr(out.size() - 4), "End\n");
}

// What meshio 5 writes (binary, UInt32 header encoded with the data; no
// header_type: version 0.1): one tet and one triangle, Int64 types.
const char* kMeshioVtu = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<!--This file was created by meshio v5.0.0-->
<UnstructuredGrid>
<Piece NumberOfPoints="4" NumberOfCells="2">
<Points>
<DataArray type="Float64" Name="Points" NumberOfComponents="3" format="binary">
YAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAPA/AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA8D8AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAADwPw==
</DataArray>
</Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="binary">
OAAAAAAAAAAAAAAAAQAAAAAAAAACAAAAAAAAAAMAAAAAAAAAAAAAAAAAAAACAAAAAAAAAAEAAAAAAAAA
</DataArray>
<DataArray type="Int64" Name="offsets" format="binary">
EAAAAAQAAAAAAAAABwAAAAAAAAA=
</DataArray>
<DataArray type="Int64" Name="types" format="binary">
EAAAAAoAAAAAAAAABQAAAAAAAAA=
</DataArray>
</Cells>
</Piece>
</UnstructuredGrid>
</VTKFile>
)";

TetMesh one_tet() {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.tets = {0, 1, 2, 3};
  m.tris = {0, 2, 1};
  return m;
}

TEST(MeshFormatsVtu, MeshioBinaryWithUInt32Header) { expect_identical(parse_vtu(kMeshioVtu, "meshio.vtu"), one_tet()); }

TEST(MeshFormatsVtu, HeaderEncodedApartFromData) {
  std::string text = kMeshioVtu;
  std::string old_types = "EAAAAAoAAAAAAAAABQAAAAAAAAA=";
  // base64([16 as UInt32]) then base64(data): as meshio 4+ writes it.
  std::string header = "EAAAAA==";
  std::string data;
  Base64Encoder enc(data);
  int64_t types[2] = {10, 5};
  enc.write(types, sizeof types);
  enc.finish();
  text.replace(text.find(old_types), old_types.size(), header + "\n  " + data);
  expect_identical(parse_vtu(text, "apart.vtu"), one_tet());
}

TEST(MeshFormatsVtu, AsciiWithExtraArraysAndInformationKeys) {
  const std::string text = R"(<?xml version="1.0"?>
<!-- ascii, as ParaView writes it, with arrays partet ignores -->
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <UnstructuredGrid>
    <FieldData>
      <DataArray type="Float64" Name="TimeValue" NumberOfTuples="1" format="ascii">0.5</DataArray>
    </FieldData>
    <Piece NumberOfPoints="4" NumberOfCells="2">
      <PointData Scalars="temperature">
        <DataArray type="Float32" Name="temperature" format="ascii">1 2 3 4</DataArray>
        <DataArray type="Int32" Name="GlobalNodeId" format="ascii">7 8 9 10</DataArray>
      </PointData>
      <CellData>
        <DataArray type="Int32" Name="region" format="ascii">1 2</DataArray>
      </CellData>
      <Points>
        <DataArray type="Float32" Name="Points" NumberOfComponents="3" format="ascii" RangeMin="0" RangeMax="1">
          <InformationKey name="L2_NORM_RANGE" location="vtkDataArray" length="2">
            <Value index="0">0</Value>
            <Value index="1">1</Value>
          </InformationKey>
          0 0 0  1 0 0
          0 1 0  0 0 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">
          0 1 2 3 0 2 1
        </DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4 7</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">10 5</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";
  TetMesh want = one_tet();
  want.global_ids = {7, 8, 9, 10};
  expect_identical(parse_vtu(text, "ascii.vtu"), want);
}

// An appended-data .vtu: Float32 points, Int32 cells, UInt32 headers, in
// either byte order, raw or base64.
std::string appended_vtu(bool big_endian, bool base64) {
  auto put = [&](std::string& out, auto v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    if (big_endian) std::reverse(b, b + sizeof v);
    out.append(b, sizeof v);
  };
  std::string data;
  std::vector<size_t> offsets;
  auto block = [&](const auto& values) {
    std::string raw;
    put(raw, static_cast<uint32_t>(values.size() * sizeof(values[0])));
    for (auto v : values) put(raw, v);
    offsets.push_back(data.size());
    if (!base64) {
      data += raw;
    } else {
      Base64Encoder enc(data);
      enc.write(raw.data(), raw.size());
      enc.finish();
    }
  };
  block(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  block(std::vector<int32_t>{0, 1, 2, 3, 0, 2, 1});
  block(std::vector<int32_t>{4, 7});
  block(std::vector<uint8_t>{10, 5});
  std::string enc = base64 ? "base64" : "raw";
  auto array = [&](const char* type, const char* name, int i, const char* extra) {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" " + extra +
           "format=\"appended\" offset=\"" + std::to_string(offsets[i]) + "\"/>\n";
  };
  return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"") +
         (big_endian ? "BigEndian" : "LittleEndian") +
         "\" header_type=\"UInt32\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n"
         "<Points>\n" +
         array("Float32", "Points", 0, "NumberOfComponents=\"3\" ") + "</Points>\n<Cells>\n" +
         array("Int32", "connectivity", 1, "") + array("Int32", "offsets", 2, "") + array("UInt8", "types", 3, "") +
         "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"" + enc + "\">\n   _" + data +
         "\n</AppendedData>\n</VTKFile>\n";
}

TEST(MeshFormatsVtu, AppendedRawAndBase64InBothByteOrders) {
  for (bool big : {false, true})
    for (bool b64 : {false, true}) expect_identical(parse_vtu(appended_vtu(big, b64), "app.vtu"), one_tet());
}

}  // namespace
}  // namespace partet
