// Malformed inputs to the mesh format readers (Medit, Gmsh 4.1, VTU, PVTU):
// each must be refused with an InputError that names the file and the line
// or byte, and no input, however hostile (truncations, random byte changes),
// may crash, hang or throw anything but InputError.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>

#include "core/error.hpp"
#include "io/mesh_formats.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

// The message of the InputError that `f` throws ("" and a failure if none).
std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

std::string medit_cube() { return format_medit(test::cube_tets()); }

void replace_once(std::string& s, const std::string& from, const std::string& to) {
  size_t at = s.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
}

TEST(MeshFormatsMalformed, MeditIndexOutOfRange) {
  std::string text = medit_cube();
  replace_once(text, "Triangles\n12\n", "Triangles\n12\n1 9 ");
  std::string e = input_error([&] { parse_medit(text, "bad.mesh", MeshRead::kVolume); });
  EXPECT_CONTAINS(e, "bad.mesh:18:");
  EXPECT_CONTAINS(e, "triangle 1: vertex index 9 is out of range 1..8");
}

TEST(MeshFormatsMalformed, MeditCountBiggerThanFile) {
  std::string text = "MeshVersionFormatted 2\nDimension 3\nVertices\n1000000000000\n0 0 0 1\nEnd\n";
  std::string e = input_error([&] { parse_medit(text, "huge.mesh", MeshRead::kVolume); });
  EXPECT_CONTAINS(e, "huge.mesh:4: number of vertices 1000000000000 is more than the file can hold");
  text = "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 1\n";
  e = input_error([&] { parse_medit(text, "short.mesh", MeshRead::kVolume); });
  EXPECT_CONTAINS(e, "short.mesh:");
}

TEST(MeshFormatsMalformed, MeditRefusesQuadrilateralsOnSurfaceReads) {
  std::string text = medit_cube();
  replace_once(text, "Triangles\n", "Quadrilaterals\n2\n1 2 4 3 0\n5 6 8 7 0\nTriangles\n");
  std::string e = input_error([&] { parse_medit(text, "quad.mesh", MeshRead::kSurface); });
  EXPECT_CONTAINS(e, "quad.mesh:");
  EXPECT_CONTAINS(e, "2 faces are quadrilaterals; partet meshes triangle surfaces only");
  EXPECT_EQ(parse_medit(text, "quad.mesh", MeshRead::kVolume).num_tets(), 6u);
  replace_once(text, "Quadrilaterals\n2", "Hexahedra\n1\n1 2 3 4 5 6 7 8 0\nQuadrilaterals\n2");
  e = input_error([&] { parse_medit(text, "hex.mesh", MeshRead::kVolume); });
  EXPECT_CONTAINS(e, "1 elements are hexahedra; partet reads tetrahedral meshes only");
}

TEST(MeshFormatsMalformed, MeditHeaderProblems) {
  EXPECT_CONTAINS(input_error([] { parse_medit("solid x\n", "a.mesh", MeshRead::kVolume); }),
                  "a.mesh:1: not a Medit mesh");
  EXPECT_CONTAINS(
      input_error([] { parse_medit("MeshVersionFormatted 2\nDimension 2\n", "b.mesh", MeshRead::kVolume); }),
      "b.mesh:2: Dimension 2 mesh");
  EXPECT_CONTAINS(
      input_error([] { parse_medit("MeshVersionFormatted 2\nDimension 3\nVerts 0\n", "c.mesh", MeshRead::kVolume); }),
      "c.mesh:3: unknown Medit keyword 'Verts'");
  EXPECT_CONTAINS(
      input_error([] { parse_medit("MeshVersionFormatted 2\nDimension 3\nEnd\n", "d.mesh", MeshRead::kVolume); }),
      "no Vertices section");
}

const char* kSmallMsh = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
1 4 1 4
3 1 0 4
1
2
3
4
0 0 0
1 0 0
0 1 0
0 0 1
$EndNodes
$Elements
1 1 1 1
3 1 4 1
1 1 2 3 4
$EndElements
)";

TEST(MeshFormatsMalformed, GmshNodeTagMissing) {
  EXPECT_EQ(parse_gmsh(kSmallMsh, "ok.msh", MeshRead::kVolume).num_tets(), 1u);
  std::string text = kSmallMsh;
  replace_once(text, "1 1 2 3 4\n", "1 1 2 3 99\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "tag.msh", MeshRead::kVolume); }),
                  "tag.msh:19: element 1 refers to node tag 99, which is not in $Nodes");
  text = kSmallMsh;
  replace_once(text, "1\n2\n3\n4\n", "1\n2\n3\n2\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "dup.msh", MeshRead::kVolume); }), "node tag 2 appears twice");
}

TEST(MeshFormatsMalformed, GmshElementTypes) {
  std::string text = kSmallMsh;
  replace_once(text, "3 1 4 1\n", "3 1 77 1\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "type.msh", MeshRead::kVolume); }),
                  "type.msh:18: unknown element type 77");
  text = kSmallMsh;
  replace_once(text, "3 1 4 1\n", "2 1 3 1\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "quad.msh", MeshRead::kSurface); }),
                  "1 faces are of type 3 (4-node quadrangle); partet meshes triangle surfaces only");
  EXPECT_TRUE(parse_gmsh(text, "quad.msh", MeshRead::kVolume).tets.empty());
  text = kSmallMsh;
  replace_once(text, "3 1 4 1\n1 1 2 3 4\n", "3 1 11 1\n1 1 2 3 4 1 2 3 4 1 2\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "tet10.msh", MeshRead::kVolume); }),
                  "(10-node tetrahedron); partet reads linear tetrahedral meshes only");
  EXPECT_TRUE(parse_gmsh(text, "tet10.msh", MeshRead::kSurface).tris.empty());
}

TEST(MeshFormatsMalformed, GmshVersionsAndSections) {
  std::string text = kSmallMsh;
  replace_once(text, "4.1 0 8", "2.2 0 8");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "old.msh", MeshRead::kVolume); }),
                  "old.msh:2: Gmsh format 2.2 is not supported");
  text = kSmallMsh;
  replace_once(text, "$EndNodes", "$EndNode");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "end.msh", MeshRead::kVolume); }), "expected $EndNodes");
  text = std::string(kSmallMsh).substr(0, std::string(kSmallMsh).find("$Elements"));
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "noel.msh", MeshRead::kVolume); }), "no $Elements section");
  text = kSmallMsh;
  replace_once(text, "$Nodes\n", "$Comments\nnever closed\n$Nodes\n");
  EXPECT_CONTAINS(input_error([&] { parse_gmsh(text, "cmt.msh", MeshRead::kVolume); }),
                  "section $Comments has no $EndComments");
}

TEST(MeshFormatsMalformed, GmshBinaryTruncatedAnywhere) {
  std::string full = format_gmsh(test::cube_tets(), true);
  size_t complete = full.size() - std::strlen("$EndElements\n");
  for (size_t n = 0; n < complete; ++n) {
    std::string e = input_error([&] { parse_gmsh(full.substr(0, n), "cut.msh", MeshRead::kVolume); });
    ASSERT_EQ(e.rfind("cut.msh:", 0), 0u) << "prefix of " << n << " bytes: " << e;
  }
  size_t nodes = full.find("$Nodes\n") + 7;
  std::string text = full;
  uint64_t huge = uint64_t{1} << 60;
  std::memcpy(&text[nodes + 8], &huge, 8);
  std::string e = input_error([&] { parse_gmsh(text, "count.msh", MeshRead::kVolume); });
  EXPECT_CONTAINS(e, "count.msh: byte ");
  EXPECT_CONTAINS(e, "truncated: number of nodes");
}

const char* kAsciiVtu = R"(<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">10</DataArray>
</Cells></Piece></UnstructuredGrid></VTKFile>
)";

TEST(MeshFormatsMalformed, VtuProblems) {
  EXPECT_EQ(parse_vtu(kAsciiVtu, "ok.vtu").num_tets(), 1u);
  auto variant = [](const std::string& from, const std::string& to) {
    std::string text = kAsciiVtu;
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  std::string text = variant("byte_order", "compressor=\"vtkZLibDataCompressor\" byte_order");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "z.vtu"); }), "z.vtu: byte 0: compressed VTU is not supported");
  text = variant("format=\"ascii\">10<", "format=\"ascii\">12<");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "hex.vtu"); }),
                  "cell 0 has VTK type 12 (hexahedron); partet reads tetrahedra (10) and triangles (5) only");
  text = variant("0 1 2 3<", "0 1 2 4<");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "idx.vtu"); }), "is point 4, out of range");
  text = variant("NumberOfPoints=\"4\"", "NumberOfPoints=\"4000000000\"");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "np.vtu"); }), "np.vtu: byte ");
  text = variant(">4<", ">5<");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "off.vtu"); }), "spans connectivity");
  text = variant("UnstructuredGrid\" version", "PolyData\" version");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "poly.vtu"); }), "partet reads UnstructuredGrid");
  text = variant("0 0 0 1 0 0", "0 0 zero 1 0 0");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "nan.vtu"); }), "'zero' is not a number");
  text = variant("</Cells>", "</Cell>");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "tag.vtu"); }), "</Cell> closes no open element");
  text = variant("format=\"ascii\">4</DataArray>", "format=\"appended\" offset=\"0\"/>");
  EXPECT_CONTAINS(input_error([&] { parse_vtu(text, "app.vtu"); }), "the file has no AppendedData");
}

TEST(MeshFormatsMalformed, VtuTruncatedAnywhere) {
  std::string full = format_vtu(test::cube_tets());
  size_t complete = full.rfind("</Piece>");
  for (size_t n = 0; n < complete; ++n) {
    std::string e = input_error([&] { parse_vtu(full.substr(0, n), "cut.vtu"); });
    ASSERT_EQ(e.rfind("cut.vtu: byte ", 0), 0u) << "prefix of " << n << " bytes: " << e;
  }
}

TEST(MeshFormatsMalformed, PvtuProblems) {
  EXPECT_CONTAINS(input_error([] { parse_pvtu_pieces(format_pvtu({}, false), "none.pvtu"); }),
                  "none.pvtu: byte 0: the .pvtu index lists no Piece");
  EXPECT_CONTAINS(input_error([] { parse_pvtu_pieces(kAsciiVtu, "vtu.pvtu"); }), "a .pvtu index is PUnstructuredGrid");
  std::string text = format_pvtu({"a.vtu"}, false);
  text.replace(text.find("Source"), 6, "Sauce");
  EXPECT_CONTAINS(input_error([&] { parse_pvtu_pieces(text, "src.pvtu"); }), "Piece has no Source");
}

// Random byte changes, insertions and deletions of valid files: every parse
// must succeed or throw an InputError naming the file.
void fuzz(const std::string& valid, const std::string& file, const std::function<void(const std::string&)>& parse) {
  std::mt19937_64 rng(std::hash<std::string>{}(file));
  const char interesting[] = {'0', '1', '9', '-', ' ', '\n', '$', '<', '>', '"', '=', '/', '_', 'A', '\0', '\xff'};
  for (int round = 0; round < 3000; ++round) {
    std::string text = valid;
    int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits && !text.empty(); ++k) {
      size_t at = rng() % text.size();
      switch (rng() % 4) {
        case 0:
          text[at] = static_cast<char>(rng());
          break;
        case 1:
          text[at] = interesting[rng() % sizeof interesting];
          break;
        case 2:
          text.insert(at, 1 + rng() % 8, interesting[rng() % sizeof interesting]);
          break;
        default:
          text.erase(at, 1 + rng() % 16);
          break;
      }
    }
    try {
      parse(text);
    } catch (const InputError& e) {
      ASSERT_EQ(std::string(e.what()).rfind(file, 0), 0u) << e.what();
    } catch (const std::exception& e) {
      FAIL() << file << " round " << round << ": " << typeid(e).name() << ": " << e.what();
    }
  }
}

TEST(MeshFormatsFuzz, RandomEditsGiveInputErrorsOnly) {
  TetMesh cube = test::cube_tets();
  TetMesh ided = cube;
  ided.global_ids = {9, 8, 7, 6, 5, 4, 3, 2};
  fuzz(format_medit(cube), "f.mesh", [](const std::string& t) { parse_medit(t, "f.mesh", MeshRead::kVolume); });
  fuzz(format_gmsh(cube, false), "fa.msh", [](const std::string& t) { parse_gmsh(t, "fa.msh", MeshRead::kVolume); });
  fuzz(format_gmsh(cube, true), "fb.msh", [](const std::string& t) { parse_gmsh(t, "fb.msh", MeshRead::kSurface); });
  fuzz(format_vtu(ided), "f.vtu", [](const std::string& t) { parse_vtu(t, "f.vtu"); });
  fuzz(kAsciiVtu, "fa.vtu", [](const std::string& t) { parse_vtu(t, "fa.vtu"); });
  fuzz(format_pvtu({"a.vtu", "b.vtu"}, true), "f.pvtu", [](const std::string& t) { parse_pvtu_pieces(t, "f.pvtu"); });
}

}  // namespace
}  // namespace partet
