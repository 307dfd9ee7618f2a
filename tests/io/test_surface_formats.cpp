// Tests of the surface readers (STL, OFF, OBJ, PLY): the bundled data files,
// the same box written in every format variant and read back bit for bit,
// and malformed inputs, whose errors must name the file and a line or byte.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/surface_formats.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using Parser = SurfaceMesh (*)(std::string_view, const std::string&);

// Coordinates that survive text only when printed with 17 digits.
SurfaceMesh odd_box() { return test::box_surface(0.1, 1.0 / 3.0, 2.5e-7); }
// Coordinates exactly representable as float32.
SurfaceMesh float_box() { return test::box_surface(0.5, 1.25, 3.0); }

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

void expect_identical(const SurfaceMesh& got, const SurfaceMesh& want) {
  ASSERT_EQ(got.xyz.size(), want.xyz.size());
  for (size_t i = 0; i < want.xyz.size(); ++i)
    EXPECT_EQ(std::bit_cast<uint64_t>(got.xyz[i]), std::bit_cast<uint64_t>(want.xyz[i])) << "coordinate " << i;
  EXPECT_EQ(got.tris, want.tris);
}

// Same triangles with the same corner coordinates, vertices possibly renumbered.
void expect_same_shape(const SurfaceMesh& got, const SurfaceMesh& want) {
  ASSERT_EQ(got.num_vertices(), want.num_vertices());
  ASSERT_EQ(got.num_triangles(), want.num_triangles());
  for (size_t c = 0; c < want.tris.size(); ++c)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(std::bit_cast<uint64_t>(got.point(got.tris[c])[i]),
                std::bit_cast<uint64_t>(want.point(want.tris[c])[i]))
          << "corner " << c;
}

// The parse fails with an InputError whose message holds every piece.
void expect_error(Parser parse, const std::string& bytes, const std::string& file,
                  const std::vector<std::string>& pieces) {
  try {
    parse(bytes, file);
    ADD_FAILURE() << "no error for " << file;
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.rfind(file, 0), 0u) << m;
    for (const std::string& p : pieces) EXPECT_NE(m.find(p), std::string::npos) << "'" << p << "' not in: " << m;
  }
}

// ---- writers -------------------------------------------------------------

std::string stl_ascii(const SurfaceMesh& m) {
  std::string s = "solid box\n";
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    s += "  facet normal 0 0 1\n    outer loop\n";
    for (int k = 0; k < 3; ++k) {
      const double* p = m.point(m.tris[3 * t + k]);
      s += "      vertex " + num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + "\n";
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid box\n";
}

template <class T>
void put(std::string& out, T v, bool big = false) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (big != (std::endian::native == std::endian::big))
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out.append(b, sizeof(T));
}

std::string stl_binary(const SurfaceMesh& m, const std::string& header) {
  std::string s = header;
  s.resize(80, '\0');
  put<uint32_t>(s, static_cast<uint32_t>(m.num_triangles()));
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    for (int i = 0; i < 3; ++i) put<float>(s, 0.0f);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) put<float>(s, static_cast<float>(m.point(m.tris[3 * t + k])[i]));
    put<uint16_t>(s, 0);
  }
  return s;
}

std::string off_text(const SurfaceMesh& m, const std::string& keyword, bool colours) {
  std::string s = "# a comment before the header\n" + keyword + "\n\n# counts\n" +
                  std::to_string(m.num_vertices()) + " " + std::to_string(m.num_triangles()) + " 0\n";
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    const double* p = m.point(v);
    s += num(p[0]) + " " + num(p[1]) + "\t" + num(p[2]);
    s += colours ? " 0.5 0.25 1 1 # rgba\n" : "\n";
  }
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    s += "3 " + std::to_string(m.tris[3 * t]) + " " + std::to_string(m.tris[3 * t + 1]) + " " +
         std::to_string(m.tris[3 * t + 2]);
    s += colours ? " 255 0 0\n" : "\n";
  }
  return s;
}

std::string obj_text(const SurfaceMesh& m) {
  std::string s = "# box\nmtllib box.mtl\no box\ng side\n";
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    const double* p = m.point(v);
    s += "v " + num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + (v % 2 ? " 1.0\n" : "\n");
  }
  s += "vt 0 0\nvn 0 0 1\nusemtl red\ns off\nl 1 2\np 3\nxyzzy unknown statement\n";
  long nv = static_cast<long>(m.num_vertices());
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    s += t == 5 ? "f \\\n" : "f";
    for (int k = 0; k < 3; ++k) {
      long v = m.tris[3 * t + k];
      std::string index = (t + k) % 2 ? std::to_string(v - nv) : std::to_string(v + 1);
      const char* tails[4] = {"", "/1", "//1", "/1/1"};
      s += " " + index + tails[(t + k) % 4];
    }
    s += "\n";
  }
  return s;
}

// A PLY with extra elements and properties; coordinates typed `coord`, face
// lists typed `count`/`index`. `format` is ascii, binary_little_endian or
// binary_big_endian.
std::string ply_bytes(const SurfaceMesh& m, const std::string& format, const std::string& coord = "double",
                      const std::string& count = "uchar", const std::string& index = "int") {
  std::string s = "ply\nformat " + format + " 1.0\ncomment written by a test\nobj_info nothing\n";
  s += "element material 2\nproperty uchar red\nproperty list uchar int ids\n";
  s += "element vertex " + std::to_string(m.num_vertices()) + "\n";
  s += "property float nx\nproperty " + coord + " z\nproperty uchar red\nproperty " + coord +
       " x\nproperty list ushort short ring\nproperty " + coord + " y\n";
  s += "element face " + std::to_string(m.num_triangles()) + "\n";
  s += "property uint8 flags\nproperty list " + count + " " + index +
       " vertex_indices\nproperty list uchar float texcoord\n";
  s += "element edge 1\nproperty int vertex1\nproperty int32 vertex2\nend_header\n";
  bool ascii = format == "ascii", big = format == "binary_big_endian";
  auto value = [&](const std::string& type, double v) {
    if (ascii) {
      s += num(v) + " ";
    } else if (type == "uchar" || type == "uint8") {
      put<uint8_t>(s, static_cast<uint8_t>(v), big);
    } else if (type == "char" || type == "int8") {
      put<int8_t>(s, static_cast<int8_t>(v), big);
    } else if (type == "short" || type == "int16") {
      put<int16_t>(s, static_cast<int16_t>(v), big);
    } else if (type == "ushort" || type == "uint16") {
      put<uint16_t>(s, static_cast<uint16_t>(v), big);
    } else if (type == "int" || type == "int32") {
      put<int32_t>(s, static_cast<int32_t>(v), big);
    } else if (type == "uint" || type == "uint32") {
      put<uint32_t>(s, static_cast<uint32_t>(v), big);
    } else if (type == "float" || type == "float32") {
      put<float>(s, static_cast<float>(v), big);
    } else {
      put<double>(s, v, big);
    }
  };
  auto end_record = [&] {
    if (ascii) s += "\n";
  };
  for (int r = 0; r < 2; ++r) {
    value("uchar", 200 + r);
    value("uchar", 2), value("int", 7), value("int", -8);
    end_record();
  }
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    const double* p = m.point(v);
    value("float", 0.5), value(coord, p[2]), value("uchar", 255), value(coord, p[0]);
    value("ushort", v % 3);
    for (size_t k = 0; k < v % 3; ++k) value("short", -1);
    value(coord, p[1]);
    end_record();
  }
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    value("uint8", 1), value(count, 3);
    for (int k = 0; k < 3; ++k) value(index, m.tris[3 * t + k]);
    value("uchar", 2), value("float", 0.25), value("float", 0.75);
    end_record();
  }
  value("int", 0), value("int32", 1);
  end_record();
  return s;
}

// ---- bundled data --------------------------------------------------------

// Vertex and face counts from an OFF header (skipping comments).
std::pair<size_t, size_t> off_counts(const std::string& text) {
  std::istringstream in(text);
  std::string line, word;
  std::vector<size_t> counts;
  while (counts.size() < 2 && std::getline(in, line)) {
    std::istringstream words(line.substr(0, line.find('#')));
    while (counts.size() < 2 && words >> word)
      if (word != "OFF") counts.push_back(std::stoul(word));
  }
  return {counts.at(0), counts.at(1)};
}

TEST(SurfaceFormatsData, EveryTriangleOffFileParses) {
  int files = 0;
  for (const char* dir : {"good", "fixable", "bad"}) {
    for (const auto& entry : std::filesystem::directory_iterator(test::data_path(dir))) {
      std::string path = entry.path().string();
      if (entry.path().extension() != ".off" || entry.path().filename() == "cube_quad.off") continue;
      std::string text = test::read_text(path);
      SurfaceMesh m = parse_off(text, path);
      auto [nv, nf] = off_counts(text);
      EXPECT_EQ(m.num_vertices(), nv) << path;
      EXPECT_EQ(m.num_triangles(), nf) << path;
      ++files;
    }
  }
  EXPECT_GE(files, 20);
}

TEST(SurfaceFormatsData, CubeOffIsExact) {
  SurfaceMesh m = parse_off(test::read_text(test::data_path("good/cube.off")), "cube.off");
  ASSERT_EQ(m.num_vertices(), 8u);
  ASSERT_EQ(m.num_triangles(), 12u);
  for (double x : m.xyz) EXPECT_TRUE(x == 1.0 || x == -1.0);
}

TEST(SurfaceFormatsData, LeverIsBinaryDespiteSolidHeader) {
  std::string bytes = test::read_text(test::data_path("good/lever.stl"));
  ASSERT_EQ(bytes.rfind("solid", 0), 0u);
  SurfaceMesh m = parse_stl(bytes, "lever.stl");
  EXPECT_EQ(m.num_triangles(), (bytes.size() - 84) / 50);
  // Closed surface: merging must leave V = F/2 + 2 - 2g vertices, far fewer than 3F.
  EXPECT_LE(m.num_vertices(), m.num_triangles() / 2 + 2);
  EXPECT_GT(m.num_vertices(), m.num_triangles() / 4);
}

TEST(SurfaceFormatsData, LeverTruncatedIsReportedAsTruncatedBinary) {
  std::string bytes = test::read_text(test::data_path("good/lever.stl"));
  bytes.resize(bytes.size() - 7);
  expect_error(parse_stl, bytes, "lever.stl",
               {"byte 80", "truncated binary STL", std::to_string(bytes.size() + 7), std::to_string(bytes.size())});
}

TEST(SurfaceFormatsData, AsciiStlFilesParse) {
  for (const char* name : {"bad/object.stl", "bad/surface1.stl"}) {
    SurfaceMesh m = parse_stl(test::read_text(test::data_path(name)), name);
    EXPECT_GE(m.num_triangles(), 80u) << name;
    EXPECT_LT(m.num_vertices(), m.num_triangles()) << name;
  }
}

TEST(SurfaceFormatsData, QuadCubeIsRefusedNamingTheFace) {
  std::string bytes = test::read_text(test::data_path("bad/cube_quad.off"));
  expect_error(parse_off, bytes, "cube_quad.off",
               {"cube_quad.off:11: face 0 has 4 vertices", "triangle", "6 faces are not triangles",
                "face 1 at line 12"});
}

// ---- round trips ---------------------------------------------------------

TEST(SurfaceFormatsStl, AsciiRoundTrip) {
  SurfaceMesh box = odd_box();
  expect_same_shape(parse_stl(stl_ascii(box), "box.stl"), box);
}

TEST(SurfaceFormatsStl, AsciiKeywordsAnyCaseAndSeveralSolids) {
  SurfaceMesh box = odd_box();
  std::string s = stl_ascii(box);
  std::string upper;
  for (char c : s) upper += static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  SurfaceMesh twice = parse_stl(s + upper, "two.stl");
  EXPECT_EQ(twice.num_vertices(), 8u);
  ASSERT_EQ(twice.num_triangles(), 24u);
  for (size_t i = 0; i < 36; ++i) EXPECT_EQ(twice.tris[i], twice.tris[36 + i]);
  expect_same_shape(parse_stl(upper, "upper.stl"), box);
}

TEST(SurfaceFormatsStl, BinaryRoundTripBothHeaders) {
  SurfaceMesh box = float_box();
  for (const char* header : {"binary box", "solid box"}) {
    SurfaceMesh m = parse_stl(stl_binary(box, header), "box.stl");
    expect_same_shape(m, box);
  }
}

TEST(SurfaceFormatsStl, BinaryFloatsConvertExactly) {
  SurfaceMesh box = test::box_surface(0.1, 0.2, 0.3);
  SurfaceMesh m = parse_stl(stl_binary(box, ""), "box.stl");
  ASSERT_EQ(m.num_vertices(), 8u);
  for (size_t c = 0; c < box.tris.size(); ++c)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(m.point(m.tris[c])[i], static_cast<double>(static_cast<float>(box.point(box.tris[c])[i])));
}

TEST(SurfaceFormatsStl, MergesMinusZeroWithZeroNumberingByFirstAppearance) {
  std::string s = "solid s\nfacet normal 0 0 0\nouter loop\nvertex -0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                  "endloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 1 0\nvertex 0 -0.0 0\n"
                  "vertex 0 0 1\nendloop\nendfacet\nendsolid s\n";
  SurfaceMesh m = parse_stl(s, "zero.stl");
  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.tris, (std::vector<uint32_t>{0, 1, 2, 2, 0, 3}));
}

TEST(SurfaceFormatsOff, PlainAndVariantHeaders) {
  SurfaceMesh box = odd_box();
  expect_identical(parse_off(off_text(box, "OFF", false), "box.off"), box);
  expect_identical(parse_off(off_text(box, "COFF", true), "box.off"), box);
  expect_identical(parse_off(off_text(box, "STCNOFF", true), "box.off"), box);
  std::string same_line = off_text(box, "OFF", false);
  same_line.replace(same_line.find("OFF\n\n# counts\n"), 14, "OFF ");
  expect_identical(parse_off(same_line, "box.off"), box);
  std::string no_keyword = off_text(box, "", false);
  expect_identical(parse_off(no_keyword, "box.off"), box);
}

TEST(SurfaceFormatsOff, NonFiniteCoordinatesAreKept) {
  SurfaceMesh m = parse_off("OFF\n3 1 0\nnan 0 0\ninf 1 0\n0 -inf +1\n3 0 1 2\n", "nan.off");
  EXPECT_TRUE(std::isnan(m.xyz[0]));
  EXPECT_EQ(m.xyz[3], std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.xyz[7], -std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.xyz[8], 1.0);
}

// Regression: "+-5" was read as -5, and an overflowing number without an
// exponent (or with a negative one) as 0 instead of infinity.
TEST(SurfaceFormatsOff, OutOfRangeNumbersAndDoubleSigns) {
  std::string big(400, '9');
  SurfaceMesh m = parse_off("OFF\n3 1 0\n" + big + " -" + big + "e-5 1e-999\n0.5e400 -0." +
                                std::string(400, '0') + "1e5 0\n0 0 0\n3 0 1 2\n",
                            "range.off");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(m.xyz[0], inf);
  EXPECT_EQ(m.xyz[1], -inf);
  EXPECT_EQ(m.xyz[2], 0.0);
  EXPECT_EQ(m.xyz[3], inf);
  EXPECT_EQ(m.xyz[4], 0.0);
  EXPECT_TRUE(std::signbit(m.xyz[4]));
  std::string pad(100, '\n');
  expect_error(parse_off, "OFF\n3 1 0\n+-5 0 0\n" + pad, "sign.off", {"sign.off:3: vertex 0: expected a coordinate, found '+-5'"});
  expect_error(parse_off, "OFF\n+-3 1 0\n" + pad, "count.off", {"count.off:2: expected the vertex count, found '+-3'"});
}

TEST(SurfaceFormatsObj, SlashesNegativeIndicesAndContinuations) {
  SurfaceMesh box = odd_box();
  expect_identical(parse_obj(obj_text(box), "box.obj"), box);
}

TEST(SurfaceFormatsPly, AsciiAndBinaryBothEndiannesses) {
  SurfaceMesh box = odd_box();
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"})
    expect_identical(parse_ply(ply_bytes(box, format), std::string("box_") + format + ".ply"), box);
}

TEST(SurfaceFormatsPly, EveryIntegerTypeForFaceLists) {
  SurfaceMesh box = float_box();
  const char* counts[] = {"uchar", "char", "ushort", "int16", "uint", "int32", "uint8", "int8"};
  const char* indices[] = {"int", "uint32", "short", "uint16", "char", "uchar", "int8", "ushort"};
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"})
    for (int t = 0; t < 8; ++t)
      for (const char* coord : {"float", "float32", "double", "float64"})
        expect_identical(parse_ply(ply_bytes(box, format, coord, counts[t], indices[t]), "types.ply"), box);
}

TEST(SurfaceFormatsPly, IntegerCoordinates) {
  SurfaceMesh box = test::box_surface(3, 100, 7);
  for (const char* format : {"ascii", "binary_big_endian"})
    for (const char* coord : {"uchar", "char", "short", "ushort", "int", "uint"})
      expect_identical(parse_ply(ply_bytes(box, format, coord), "ints.ply"), box);
}

// ---- malformed input -----------------------------------------------------

TEST(SurfaceFormatsStl, TruncatedBinary) {
  std::string bytes = stl_binary(float_box(), "binary");
  std::string cut = bytes.substr(0, bytes.size() - 10);
  expect_error(parse_stl, cut, "cut.stl",
               {"cut.stl: byte 80: truncated binary STL", "12 facets", "684 bytes", "has 674"});
}

TEST(SurfaceFormatsStl, AsciiErrorsNameTheLine) {
  std::string s = stl_ascii(odd_box());
  std::string no_endloop = s;
  no_endloop.erase(no_endloop.find("    endloop\n"), 12);
  expect_error(parse_stl, no_endloop, "a.stl", {"a.stl:7: facet 0: expected 'endloop', found 'endfacet'"});
  std::string quad = s;
  quad.insert(quad.find("    endloop\n"), "vertex 0 0 0\n");
  expect_error(parse_stl, quad, "q.stl", {"q.stl:7: facet 0 has more than 3 vertices"});
  std::string bad_number = s;
  bad_number.replace(bad_number.find("vertex ") + 7, 1, "x");
  expect_error(parse_stl, bad_number, "n.stl", {"n.stl:4: expected a vertex coordinate"});
  expect_error(parse_stl, s.substr(0, s.size() - 13), "e.stl", {"e.stl:", "expected 'facet' or 'endsolid'"});
  expect_error(parse_stl, "solid empty\nendsolid empty\n", "empty.stl", {"empty.stl:2: no triangles"});
  expect_error(parse_stl, "hello\n", "h.stl", {"h.stl:1: expected 'solid', found 'hello'"});
}

TEST(SurfaceFormatsStl, GarbageAndEmptyBinary) {
  std::string garbage(200, '\0');
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 37 + 11) % 256);
  expect_error(parse_stl, garbage, "g.stl", {"g.stl: byte 80: truncated binary STL"});
  expect_error(parse_stl, garbage.substr(0, 50), "short.stl", {"short.stl: byte 0: not an STL file"});
  expect_error(parse_stl, stl_binary(SurfaceMesh{}, "solid"), "none.stl", {"none.stl: byte 84: no triangles"});
}

TEST(SurfaceFormatsOff, HugeCountsFailFast) {
  expect_error(parse_off, "OFF\n1000000000000 1 0\n0 0 0\n", "huge.off",
               {"huge.off:2: vertex count 1000000000000 is more than the file can hold"});
  std::string pad(100, '\n');
  expect_error(parse_off, "OFF\n3 1000000000000 0\n" + pad, "huge.off", {"huge.off:2: face count 1000000000000"});
  expect_error(parse_off, "OFF 3 -1 0\n" + pad, "neg.off", {"neg.off:1: face count is negative"});
  expect_error(parse_off, "OFF\n3 1 0\n0 0 0\n", "small.off", {"small.off:2: vertex count 3 is more than"});
}

TEST(SurfaceFormatsOff, RecordErrorsNameFaceAndLine) {
  std::string head = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n";
  std::string pad(100, ' ');
  expect_error(parse_off, head + "3 0 1 2\n3 0 1 3\n", "r.off",
               {"r.off:7: face 1: vertex index 3 is out of range (the file has 3 vertices)"});
  expect_error(parse_off, head + "3 0 1 -1\n3 0 1 2\n", "m.off", {"m.off:6: face 0: vertex index -1"});
  expect_error(parse_off, head + "3 0 1 2\n", "short.off", {"short.off:", "expected face 1 of 2"});
  expect_error(parse_off, head + "3 0 1\n3 0 1 2\n", "few.off", {"few.off:6: face 0 lists fewer"});
  expect_error(parse_off, head + "2 0 1\n5 0 1 2 0 1\n", "poly.off",
               {"poly.off:6: face 0 has 2 vertices", "2 faces are not triangles; also face 1 at line 7 (5 vertices)"});
  expect_error(parse_off, "OFF\n3 1 0\n0 0\n" + pad, "v.off", {"v.off:3: vertex 0 has fewer than 3 coordinates"});
  expect_error(parse_off, "OFF\n3 1 0\n0 0 x\n" + pad, "x.off", {"x.off:3: vertex 0: expected a coordinate, found 'x'"});
  expect_error(parse_off, "OFF\n0 0 0\n", "z.off", {"z.off:", "no triangles"});
  expect_error(parse_off, "4OFF\n1 1 0\n", "4.off", {"4.off:1:", "only 3-dimensional"});
  expect_error(parse_off, "OFF BINARY\n", "b.off", {"b.off:1: binary OFF"});
  expect_error(parse_off, "\n# nothing\n", "e.off", {"e.off:2: empty file"});
}

TEST(SurfaceFormatsObj, IndexErrorsNameTheLine) {
  std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error(parse_obj, verts + "f 0 1 2\n", "z.obj", {"z.obj:4: face 0: vertex index 0"});
  expect_error(parse_obj, verts + "f 1 2 3\nf 1 2 4\n", "r.obj", {"r.obj:5: face 1: vertex index 4 is out of range"});
  expect_error(parse_obj, verts + "f -4 1 2\n", "n.obj", {"n.obj:4: face 0: vertex index -4 is out of range"});
  expect_error(parse_obj, verts + "f 1/1 a/2 3\n", "a.obj", {"a.obj:4: face 0: expected a vertex index, found 'a/2'"});
  expect_error(parse_obj, "v 0 0\n", "v.obj", {"v.obj:1: vertex 0 has fewer than 3 coordinates"});
  expect_error(parse_obj, verts + "v 1 1 1\nf 1 2 3 4\nf 1 2\nf 1 2 3\n", "q.obj",
               {"q.obj:5: face 0 has 4 vertices", "2 faces are not triangles; also face 1 at line 6 (2 vertices)"});
  expect_error(parse_obj, verts, "none.obj", {"none.obj: no triangles"});
}

TEST(SurfaceFormatsPly, HeaderErrors) {
  std::string good = ply_bytes(float_box(), "ascii");
  std::string unknown = good;
  unknown.replace(unknown.find("ascii"), 5, "binary_middle_endian");
  expect_error(parse_ply, unknown, "u.ply", {"u.ply:2: unknown PLY format 'binary_middle_endian'"});
  expect_error(parse_ply, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "h.ply",
               {"h.ply:4: unexpected end of file in the PLY header"});
  expect_error(parse_ply, "plyx\n", "p.ply", {"p.ply:1: not a PLY file"});
  expect_error(parse_ply, "ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n",
               "big.ply", {"big.ply:9: element 'vertex' (line 3) claims 1000000 entries"});
  expect_error(parse_ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
               "noz.ply", {"noz.ply:6: element 'vertex' has no 'z' property"});
  expect_error(parse_ply, "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 0\nproperty list uchar float vertex_indices\nend_header\n",
               "f.ply", {"f.ply:9: property 'vertex_indices' of 'face' must be a list of integers"});
  expect_error(parse_ply, "ply\nformat ascii 1.0\nproperty float x\n", "o.ply", {"o.ply:3: 'property' before any 'element'"});
  expect_error(parse_ply, "ply\nformat ascii 2.0\n", "v.ply", {"v.ply:2: unsupported PLY version"});
}

TEST(SurfaceFormatsPly, BodyErrors) {
  SurfaceMesh box = float_box();
  std::string bin = ply_bytes(box, "binary_little_endian");
  size_t body = bin.find("end_header\n") + 11;
  // Cut inside the last face: 1 flag + 1 count + 12 index bytes + 1 + 8 texcoord, then the edge's 8.
  std::string cut = bin.substr(0, bin.size() - 8 - 9 - 6);
  expect_error(parse_ply, cut, "cut.ply", {"cut.ply: byte ", "truncated"});
  EXPECT_GT(cut.size(), body);

  std::string quad = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
                     "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n4 0 1 2 3\n3 0 1 2\n";
  expect_error(parse_ply, quad, "quad.ply", {"quad.ply:15: face 1 has 4 vertices", "1 faces are not triangles"});
  std::string range = quad;
  range.replace(range.find("4 0 1 2 3"), 9, "3 0 1 4");
  expect_error(parse_ply, range, "range.ply", {"range.ply:15: face 1: vertex index 4 is out of range"});

  std::string header = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty uchar x\nproperty uchar y\n"
                       "property uchar z\nelement face 2\nproperty list uchar uchar vertex_indices\nend_header\n";
  std::string data = header + std::string("\0\0\0\1\0\0\0\1\0\3\0\1\2\4\0\1\2\0", 18);
  expect_error(parse_ply, data, "bq.ply", {"bq.ply: byte " + std::to_string(header.size() + 13) + ": face 1 has 4 vertices"});
  expect_error(parse_ply, header, "empty.ply", {"empty.ply:9: element 'vertex' (line 3) claims 3 entries"});
  expect_error(parse_ply, header + std::string(10, '\0'), "short.ply",
               {"short.ply: byte " + std::to_string(header.size() + 10), "truncated"});
  std::string no_faces = header;
  no_faces.replace(no_faces.find("face 2"), 6, "face 0");
  expect_error(parse_ply, no_faces + std::string(9, '\0'), "nf.ply", {"nf.ply: no triangles"});
}

TEST(SurfaceFormats, GarbageIsAnInputErrorEverywhere) {
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919 + 13) % 251);
  for (Parser parse : {parse_stl, parse_off, parse_obj, parse_ply}) {
    EXPECT_THROW(parse(garbage, "g"), InputError);
    EXPECT_THROW(parse("", "g"), InputError);
    EXPECT_THROW(parse(std::string(1000, '\n'), "g"), InputError);
  }
}

}  // namespace
}  // namespace partet
