// Other tools read what partet writes, and partet reads what they write:
// meshio (Python) reads our .vtu and .msh files; Gmsh loads our .msh and
// .mesh files and writes them back as files we read to the same mesh; VTK
// (Python) reads our .vtu and .pvtu files (global ids included) and writes
// .vtu files in each of its encodings that we read. Each test is skipped when
// its tool is not installed (Debian packages python3-meshio, gmsh and
// python3-vtk9).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/mesh_formats.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

// A Python interpreter that imports `module` ("" if none does): python3 on the
// PATH, else Debian's (a python3 from pyenv or a venv lacks Debian's modules).
std::string python_with(const std::string& module) {
  for (const char* py : {"python3", "/usr/bin/python3"}) {
    std::string cmd = std::string(py) + " -c 'import " + module + "' >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return py;
  }
  return "";
}

std::string run_command(const std::string& cmd) {
  std::string out;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  pclose(p);
  return out;
}

std::string join(const std::vector<uint32_t>& v) {
  std::string s;
  for (uint32_t x : v) s += " " + std::to_string(x);
  return s;
}

TEST(MeshFormatsMeshio, ReadsOurVtuAndGmshFiles) {
  std::string py = python_with("meshio");
  if (py.empty()) GTEST_SKIP() << "no python3 with meshio (Debian package python3-meshio)";
  std::string dir = test::scratch_dir("meshio");
  TetMesh cube = test::cube_tets();
  cube.global_ids = {70, 71, 72, 73, 74, 75, 76, 77};
  test::write_text(dir + "/cube.vtu", format_vtu(cube));
  test::write_text(dir + "/cube.msh", format_gmsh(cube, true));
  test::write_text(dir + "/cube_ascii.msh", format_gmsh(cube, false));
  test::write_text(dir + "/check.py", R"(import sys
import meshio
for path in sys.argv[1:]:
    m = meshio.read(path, file_format="gmsh" if path.endswith(".msh") else "vtu")
    out = [path.rsplit("/", 1)[-1], "points " + " ".join(repr(float(x)) for x in m.points.flatten())]
    for c in m.cells:
        out.append(c.type + " " + " ".join(str(int(v)) for v in c.data.flatten()))
    if "GlobalNodeId" in m.point_data:
        out.append("ids " + " ".join(str(int(v)) for v in m.point_data["GlobalNodeId"]))
    print("; ".join(out))
)");
  std::string points = "points";
  for (double x : cube.xyz) points += x == 0 ? " 0.0" : " 1.0";
  std::string want = "cube.vtu; " + points + "; tetra" + join(cube.tets) + "; ids 70 71 72 73 74 75 76 77\n";
  for (const char* msh : {"cube.msh", "cube_ascii.msh"})
    want += std::string(msh) + "; " + points + "; triangle" + join(cube.tris) + "; tetra" + join(cube.tets) + "\n";
  EXPECT_EQ(
      run_command(py + " " + dir + "/check.py " + dir + "/cube.vtu " + dir + "/cube.msh " + dir + "/cube_ascii.msh"),
      want);
}

// Runs `command`; false when it fails or is not installed.
bool succeeds(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()) == 0; }

TEST(MeshFormatsGmshApp, LoadsOurFilesAndWritesThemBack) {
  if (!succeeds("gmsh --version")) GTEST_SKIP() << "gmsh is not installed (Debian package gmsh)";
  std::string dir = test::scratch_dir("gmsh_app");
  TetMesh cube = test::cube_tets();
  test::write_text(dir + "/bin.msh", format_gmsh(cube, true));
  test::write_text(dir + "/ascii.msh", format_gmsh(cube, false));
  test::write_text(dir + "/cube.mesh", format_medit(cube));
  for (const char* in : {"bin.msh", "ascii.msh", "cube.mesh"}) {
    for (const char* out : {"out.msh", "out.mesh"}) {
      std::string path = dir + "/" + out;
      std::remove(path.c_str());
      std::string cmd = "gmsh " + dir + "/" + in + " -0 -o " + path;
      ASSERT_TRUE(succeeds(cmd)) << cmd;
      std::string bytes = test::read_text(path);
      TetMesh back = std::string(out) == "out.msh" ? parse_gmsh(bytes, path, MeshRead::kVolume)
                                                   : parse_medit(bytes, path, MeshRead::kVolume);
      EXPECT_EQ(back.xyz, cube.xyz) << cmd;
      EXPECT_EQ(back.tets, cube.tets) << cmd;
      EXPECT_EQ(back.tris, cube.tris) << cmd;
    }
  }
}

TEST(MeshFormatsVtk, ReadsOurPiecesAndWritesEncodingsWeRead) {
  std::string py = python_with("vtk");
  if (py.empty()) GTEST_SKIP() << "no python3 with VTK (Debian package python3-vtk9)";
  std::string dir = test::scratch_dir("vtk");
  TetMesh a;
  a.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  a.tets = {0, 1, 2, 3};
  a.global_ids = {0, 1, 2, 3};
  TetMesh b;
  b.xyz = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  b.tets = {0, 1, 2, 3};
  b.global_ids = {1, 2, 3, 4};
  test::write_text(dir + "/p_0.vtu", format_vtu(a));
  test::write_text(dir + "/p_1.vtu", format_vtu(b));
  test::write_text(dir + "/p.pvtu", format_pvtu({"p_0.vtu", "p_1.vtu"}, true));
  test::write_text(dir + "/check.py", R"(import sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
d = sys.argv[1]
for name, reader in (("p_0.vtu", vtk.vtkXMLUnstructuredGridReader), ("p.pvtu", vtk.vtkXMLPUnstructuredGridReader)):
    r = reader()
    r.SetFileName(d + "/" + name)
    r.Update()
    g = r.GetOutput()
    ids = g.GetPointData().GetGlobalIds()
    print(name, g.GetNumberOfPoints(), [g.GetCellType(i) for i in range(g.GetNumberOfCells())],
          vtk_to_numpy(g.GetPoints().GetData()).flatten().tolist(), ids.GetClassName(), vtk_to_numpy(ids).tolist())
for name, mode, encode in (("ascii", 0, 0), ("binary", 1, 0), ("raw", 2, 0), ("base64", 2, 1)):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(d + "/vtk_" + name + ".vtu")
    w.SetInputData(r.GetOutput())
    w.SetDataMode(mode)
    w.SetEncodeAppendedData(encode)
    w.SetCompressorTypeToNone()
    w.Write()
)");
  EXPECT_EQ(run_command(py + " " + dir + "/check.py " + dir),
            "p_0.vtu 4 [10] [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0] vtkIdTypeArray [0, 1, 2, 3]\n"
            "p.pvtu 8 [10, 10] [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, "
            "0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0] vtkIdTypeArray [0, 1, 2, 3, 1, 2, 3, 4]\n");
  TetMesh both = a;
  both.xyz.insert(both.xyz.end(), b.xyz.begin(), b.xyz.end());
  both.tets.insert(both.tets.end(), {4, 5, 6, 7});
  both.global_ids.insert(both.global_ids.end(), b.global_ids.begin(), b.global_ids.end());
  for (const char* name : {"ascii", "binary", "raw", "base64"}) {
    std::string path = dir + "/vtk_" + name + ".vtu";
    TetMesh m = parse_vtu(test::read_text(path), path);
    EXPECT_EQ(m.xyz, both.xyz) << name;
    EXPECT_EQ(m.tets, both.tets) << name;
    EXPECT_EQ(m.global_ids, both.global_ids) << name;
  }
}

}  // namespace
}  // namespace partet
