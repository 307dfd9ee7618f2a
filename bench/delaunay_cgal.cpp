// bench/delaunay_cgal.cpp: partet's Delaunay tetrahedralization
// (delaunay/delaunay.hpp) against CGAL's Delaunay_triangulation_3 (exact
// predicates, inexact constructions; its range constructor, which sorts the
// points spatially) on the same points: 30,000 uniform random points in a
// cube, then the vertices of each Medit .mesh named on the command line
// (meshes partet wrote with --no-optimize hold the points the Delaunay fill
// tetrahedralizes: the core's lattice points, the surface's vertices, the
// gap vertices). Best of five runs each, CPU of this process only; built and
// run by bench/delaunay-cgal.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "delaunay/delaunay.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Delaunay_triangulation_3<Kernel>;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void compare(const std::string& name, const std::vector<double>& xyz) {
  const size_t n = xyz.size() / 3;
  double ours = 1e300, cgal = 1e300;
  size_t our_tets = 0, cgal_tets = 0;
  for (int run = 0; run < 5; ++run) {
    auto start = std::chrono::steady_clock::now();
    const partet::DelaunayTets tets = partet::delaunay_tetrahedralize(xyz);
    ours = std::min(ours, seconds_since(start));
    our_tets = 0;
    for (size_t t = 0; t < tets.num_tets(); ++t) our_tets += tets.finite(t);
    std::vector<Kernel::Point_3> points;
    points.reserve(n);
    for (size_t i = 0; i < n; ++i) points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    start = std::chrono::steady_clock::now();
    const Triangulation triangulation(points.begin(), points.end());
    cgal = std::min(cgal, seconds_since(start));
    cgal_tets = triangulation.number_of_finite_cells();
  }
  std::printf("| %s | %zu | %zu | %.4f | %.2f | %zu | %.4f | %.2f | %.2f |\n", name.c_str(), n, our_tets, ours,
              ours / static_cast<double>(n) * 1e6, cgal_tets, cgal, cgal / static_cast<double>(n) * 1e6, ours / cgal);
}

// The vertices of a Medit .mesh (x y z ref per line after "Vertices" and a count).
std::vector<double> medit_vertices(const std::string& path) {
  std::ifstream in(path);
  std::string word;
  while (in >> word && word != "Vertices") {
  }
  size_t count = 0;
  in >> count;
  std::vector<double> xyz;
  for (size_t i = 0; i < count && in; ++i) {
    double x, y, z;
    long ref;
    in >> x >> y >> z >> ref;
    xyz.insert(xyz.end(), {x, y, z});
  }
  if (!in || xyz.size() != 3 * count) throw std::runtime_error(path + ": not a Medit mesh with vertices");
  return xyz;
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("| points | count | partet finite tets | partet s | partet us/point | CGAL finite tets | CGAL s | CGAL us/point "
              "| partet / CGAL |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> xyz(3 * 30000);
  for (double& x : xyz) x = unit(random);
  compare("uniform random", xyz);
  for (int a = 1; a < argc; ++a) compare(argv[a], medit_vertices(argv[a]));
}
