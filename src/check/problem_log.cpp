// Problem lines and entity texts for the validator (see problem_log.hpp).
#include "check/problem_log.hpp"

#include "core/point_text.hpp"

namespace partet {

void ProblemKind::report(std::vector<std::string>& lines) const {
  if (count_ == 0) return;
  std::string line = std::to_string(count_) + " " + what_;
  for (size_t i = 0; i < cases_.size(); ++i) line += (i == 0 ? ": " : "; ") + cases_[i];
  if (count_ > cases_.size()) line += " (and " + std::to_string(count_ - cases_.size()) + " more)";
  lines.push_back(std::move(line));
}

std::string mesh_vertex_text(const TetMesh& mesh, uint32_t v) {
  std::string text = "vertex " + std::to_string(v) + " ";
  return text + (v < mesh.num_vertices() ? point_text(mesh.point(v)) : "out of range");
}

namespace {

std::string vertices_text(const TetMesh& mesh, const uint32_t* v, int n) {
  std::string text = "[";
  for (int i = 0; i < n; ++i) text += (i ? " " : "") + std::to_string(v[i]);
  text += "]";
  for (int i = 0; i < n; ++i)
    text +=
        " " + (v[i] < mesh.num_vertices() ? point_text(mesh.point(v[i])) : "out of range");
  return text;
}

}  // namespace

std::string tet_text(const TetMesh& mesh, size_t t) {
  return "tet " + std::to_string(t) + " " + vertices_text(mesh, &mesh.tets[4 * t], 4);
}

std::string triangle_text(const TetMesh& mesh, const uint32_t* v) {
  return vertices_text(mesh, v, 3);
}

}  // namespace partet
