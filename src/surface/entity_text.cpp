// Entity descriptions for diagnosis messages.
#include "surface/entity_text.hpp"

namespace partet {

std::string vertex_text(const SurfaceMesh& s, uint32_t v) {
  return "vertex " + std::to_string(v) + " " + point_text(s.point(v));
}

std::string triangle_text(const SurfaceMesh& s, uint32_t t) {
  const uint32_t* v = &s.tris[3 * static_cast<size_t>(t)];
  return "triangle " + std::to_string(t) + " (vertices " + std::to_string(v[0]) + ", " +
         std::to_string(v[1]) + ", " + std::to_string(v[2]) + " at " + point_text(s.point(v[0])) +
         ", " + point_text(s.point(v[1])) + ", " + point_text(s.point(v[2])) + ")";
}

std::string case_list(const std::string& file, size_t count, const std::string& what,
                      const std::vector<std::string>& cases) {
  std::string msg = file + ": " + std::to_string(count) + " " + what;
  for (size_t i = 0; i < cases.size() && i < kListedCases; ++i) msg += "\n  " + cases[i];
  if (count > kListedCases) msg += "\n  (and " + std::to_string(count - kListedCases) + " more)";
  return msg;
}

}  // namespace partet
