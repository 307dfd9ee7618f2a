// Shared test helpers: paths to bundled data, scratch directories, running
// the partet binary, and small generated shapes.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/tet_mesh.hpp"
#include "surface/surface_mesh.hpp"

namespace partet::test {

// Path of a file in the project's data/ folder.
std::string data_path(const std::string& name);

// A fresh empty directory for one test (removed and recreated), named
// after the running test as well as `name`: ctest runs tests in parallel,
// and two tests asking for the same name must not share it.
std::string scratch_dir(const std::string& name);

std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};
// Runs the partet binary with `args` (a shell-quoted string).
RunResult run_partet(const std::string& args);
// The step `name` of a run report (--report), or null.
nlohmann::json report_step(const nlohmann::json& report, const std::string& name);

// An axis-aligned box [0,a]x[0,b]x[0,c] as 12 outward triangles; vertex i
// is (a if i&1, b if i&2, c if i&4).
SurfaceMesh box_surface(double a = 1, double b = 1, double c = 1);
// The cube [lo, lo+size]^3 as box_surface() triangles.
SurfaceMesh shifted_box(double lo, double size);
// Appends `b` to `a` as a separate shell (its vertices renumbered).
void append(SurfaceMesh& a, const SurfaceMesh& b);

// The four faces a 2-rank run left on stress-check seed 1790, reversed
// into an outward surface: a tet positive by exact orient3d (3e-21) but
// about 1e-18 high across 0.27, under the rounding of its coordinates.
SurfaceMesh flat_tet_of_seed_1790();

// The unit cube [0,1]^3 split into 6 positive tets around the 0-7 diagonal,
// with its 12 boundary triangles (those of box_surface()).
TetMesh cube_tets();

}  // namespace partet::test
