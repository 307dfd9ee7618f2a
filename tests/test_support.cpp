// Shared test helpers (see test_support.hpp).
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace partet::test {

std::string data_path(const std::string& name) { return std::string(PARTET_DATA_DIR) + "/" + name; }

std::string scratch_dir(const std::string& name) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string owner = test ? std::string(test->test_suite_name()) + "." + test->name() + "_" : std::string();
  auto dir = std::filesystem::temp_directory_path() / ("partet_test_" + owner + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

RunResult run_partet(const std::string& args) {
  RunResult r;
  std::string cmd = std::string(PARTET_BINARY) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

nlohmann::json report_step(const nlohmann::json& report, const std::string& name) {
  for (const auto& step : report["steps"])
    if (step["name"] == name) return step;
  return nullptr;
}

SurfaceMesh flat_tet_of_seed_1790() {
  SurfaceMesh s;
  s.xyz = {-0.24090284901187772, -0.15037344580850626, 0.17218002581386063,
           -0.23875456366867143, -0.15298006311673162, 0.17305060897182561,
           -0.12522639673175975, -0.13959095825943135, -0.067007589601047038,
           -0.12952296741817235, -0.13437772364298059, -0.068748755916977045};
  s.tris = {0, 2, 1, 3, 1, 2, 3, 0, 1, 0, 3, 2};
  return s;
}

SurfaceMesh box_surface(double a, double b, double c) {
  SurfaceMesh s;
  for (int i = 0; i < 8; ++i) {
    s.xyz.push_back((i & 1) ? a : 0);
    s.xyz.push_back((i & 2) ? b : 0);
    s.xyz.push_back((i & 4) ? c : 0);
  }
  // Outward (counterclockwise seen from outside); each face is split by the
  // diagonal through corner 0 or corner 7, as cube_tets() splits it.
  s.tris = {0, 3, 1, 0, 2, 3,   // z = 0
            4, 5, 7, 4, 7, 6,   // z = c
            0, 1, 5, 0, 5, 4,   // y = 0
            2, 7, 3, 2, 6, 7,   // y = b
            0, 6, 2, 0, 4, 6,   // x = 0
            1, 3, 7, 1, 7, 5};  // x = a
  return s;
}

SurfaceMesh shifted_box(double lo, double size) {
  SurfaceMesh s = box_surface(size, size, size);
  for (double& c : s.xyz) c += lo;
  return s;
}

void append(SurfaceMesh& a, const SurfaceMesh& b) {
  const uint32_t base = static_cast<uint32_t>(a.num_vertices());
  a.xyz.insert(a.xyz.end(), b.xyz.begin(), b.xyz.end());
  for (uint32_t v : b.tris) a.tris.push_back(v + base);
}

TetMesh cube_tets() {
  TetMesh m;
  SurfaceMesh box = box_surface();
  m.xyz = box.xyz;
  m.tris = box.tris;
  // Kuhn triangulation: the 6 paths 0 -> 7 through the cube's vertices.
  m.tets = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};
  return m;
}

}  // namespace partet::test
