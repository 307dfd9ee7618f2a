// nglib_driver IN.off OUT.mesh: Netgen's volume mesher on a closed triangle
// surface, for bench/run. Reads an OFF surface of triangles (outward), hands
// it to nglib unchanged, runs Ng_GenerateVolumeMesh with nglib's default
// parameters (fineness 0.5, grading 0.3, local h on, 3 optimization steps)
// except maxh = 1e300 (no global cap: the size comes from the surface) and
// writes Medit .mesh: vertices, Netgen's boundary triangles, and the tets
// reordered to partet's positive orientation (orient3d(v0,v1,v2,v3) > 0).
// Exit 2 on unreadable input, 3 when Netgen fails. Built by bench/run with
// g++ against libnglib-dev; not part of the CMake build.
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace nglib {
#include <nglib.h>
}

namespace {

struct Surface {
  std::vector<double> xyz;
  std::vector<int> tris;  // 0-based
};

// Next token of an OFF file, skipping '#' comments.
bool next_token(std::istream& in, std::string& token) {
  while (in >> token) {
    if (token[0] != '#') return true;
    std::string rest;
    std::getline(in, rest);
  }
  return false;
}

Surface read_off(const char* path) {
  std::ifstream in(path);
  std::string token;
  if (!next_token(in, token) || token != "OFF") throw std::runtime_error(std::string(path) + ": not an OFF file");
  size_t count[3] = {0, 0, 0};  // vertices, faces, edges (unused)
  for (size_t& c : count) next_token(in, token), c = std::stoul(token);
  const size_t nv = count[0], nf = count[1];
  Surface s;
  s.xyz.resize(3 * nv);
  for (double& x : s.xyz) next_token(in, token), x = std::stod(token);
  for (size_t f = 0; f < nf; ++f) {
    next_token(in, token);
    if (token != "3") throw std::runtime_error(std::string(path) + ": a face is not a triangle");
    for (int k = 0; k < 3; ++k) next_token(in, token), s.tris.push_back(std::stoi(token));
  }
  if (!in) throw std::runtime_error(std::string(path) + ": truncated");
  return s;
}

// Meshes the surface and writes OUT; throws on any failure.
void mesh_volume(const Surface& s, const char* out_path) {
  nglib::Ng_Mesh* mesh = nglib::Ng_NewMesh();
  for (size_t v = 0; v < s.xyz.size() / 3; ++v) nglib::Ng_AddPoint(mesh, const_cast<double*>(&s.xyz[3 * v]));
  // nglib takes the triangles as they are, outward (reversed, it finds no
  // volume to mesh).
  for (size_t t = 0; t < s.tris.size(); t += 3) {
    int pi[3] = {s.tris[t] + 1, s.tris[t + 1] + 1, s.tris[t + 2] + 1};
    nglib::Ng_AddSurfaceElement(mesh, nglib::NG_TRIG, pi);
  }
  nglib::Ng_Meshing_Parameters mp;
  mp.maxh = 1e300;
  if (nglib::Ng_GenerateVolumeMesh(mesh, &mp) != nglib::NG_OK) throw std::runtime_error("Ng_GenerateVolumeMesh failed");
  std::ofstream out(out_path);
  out.precision(17);
  const int np = nglib::Ng_GetNP(mesh), nse = nglib::Ng_GetNSE(mesh), ne = nglib::Ng_GetNE(mesh);
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << np << "\n";
  for (int v = 1; v <= np; ++v) {
    double x[3];
    nglib::Ng_GetPoint(mesh, v, x);
    out << x[0] << ' ' << x[1] << ' ' << x[2] << " 0\n";
  }
  out << "Triangles\n" << nse << "\n";
  for (int f = 1; f <= nse; ++f) {
    int pi[8];
    nglib::Ng_GetSurfaceElement(mesh, f, pi);
    out << pi[0] << ' ' << pi[1] << ' ' << pi[2] << " 1\n";
  }
  out << "Tetrahedra\n" << ne << "\n";
  for (int e = 1; e <= ne; ++e) {
    int pi[10];
    if (nglib::Ng_GetVolumeElement(mesh, e, pi) != nglib::NG_TET) throw std::runtime_error("an element is not a tet");
    // Netgen's tets are negatively oriented in partet's convention.
    out << pi[1] << ' ' << pi[0] << ' ' << pi[2] << ' ' << pi[3] << " 1\n";
  }
  out << "End\n";
  if (!out) throw std::runtime_error(std::string(out_path) + ": write failed");
  nglib::Ng_DeleteMesh(mesh);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: nglib_driver IN.off OUT.mesh\n");
    return 2;
  }
  try {
    const Surface s = read_off(argv[1]);
    nglib::Ng_Init();
    mesh_volume(s, argv[2]);
    nglib::Ng_Exit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nglib_driver: %s\n", e.what());
    return 3;
  }
  return 0;
}
