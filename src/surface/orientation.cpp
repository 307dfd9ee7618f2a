// orient_shells: breadth-first propagation of orientation across manifold
// edges, then whole-shell flips so that signs follow the nesting depth.
#include "surface/orientation.hpp"

#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "surface/entity_text.hpp"
#include "surface/shell_nesting.hpp"

namespace partet {

namespace {

void flip_triangle(SurfaceMesh& s, size_t t) { std::swap(s.tris[3 * t + 1], s.tris[3 * t + 2]); }

// Signed volume enclosed by each shell: sum of det(a-o, b-o, c-o)/6 with o a
// vertex of the shell (fewer cancellations), Neumaier-compensated. Also the
// sum of the determinants' permanents (their six products in absolute
// value) over 6, for the size of the rounding error: each determinant's is
// a few ulps of its permanent, which can dwarf the determinant itself (a
// tet 1e-18 high across 0.27, whose volume's sign in doubles is noise).
void shell_volumes(const SurfaceMesh& s, const ShellInfo& info, std::vector<double>& vol,
                   std::vector<double>& magnitude) {
  vol.assign(info.count, 0.0);
  magnitude.assign(info.count, 0.0);
  std::vector<double> comp(info.count, 0.0);
  std::vector<uint32_t> origin(info.count, UINT32_MAX);
  for (size_t t = 0; t < s.num_triangles(); ++t) {
    uint32_t sh = info.shell_of_triangle[t];
    if (origin[sh] == UINT32_MAX) origin[sh] = s.tris[3 * t];
    const double* o = s.point(origin[sh]);
    const double* a = s.point(s.tris[3 * t]);
    const double* b = s.point(s.tris[3 * t + 1]);
    const double* c = s.point(s.tris[3 * t + 2]);
    double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
    double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
    double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
    double term = (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
    const double permanent = std::fabs(ax) * (std::fabs(by * cz) + std::fabs(bz * cy)) +
                             std::fabs(ay) * (std::fabs(bx * cz) + std::fabs(bz * cx)) +
                             std::fabs(az) * (std::fabs(bx * cy) + std::fabs(by * cx));
    double sum = vol[sh] + term;
    comp[sh] += std::fabs(vol[sh]) >= std::fabs(term) ? (vol[sh] - sum) + term : (term - sum) + vol[sh];
    vol[sh] = sum;
    magnitude[sh] += permanent / 6.0;
  }
  for (uint32_t sh = 0; sh < info.count; ++sh) vol[sh] += comp[sh];
}

}  // namespace

ShellInfo orient_shells(SurfaceMesh& surface, const EdgeTable& edges, const std::string& file) {
  const size_t nt = surface.num_triangles();
  ShellInfo info;
  info.shell_of_triangle.assign(nt, UINT32_MAX);
  std::vector<uint8_t> flip(nt, 0);
  std::vector<uint32_t> queue;
  queue.reserve(nt);

  for (uint32_t seed = 0; seed < nt; ++seed) {
    if (info.shell_of_triangle[seed] != UINT32_MAX) continue;
    uint32_t shell = info.count++;
    info.shell_of_triangle[seed] = shell;
    queue.clear();
    queue.push_back(seed);
    for (size_t qi = 0; qi < queue.size(); ++qi) {
      uint32_t t = queue[qi];
      for (uint32_t k = 0; k < 3; ++k) {
        uint32_t h = 3 * t + k;
        uint32_t g = edges.twin[h];
        PARTET_ASSERT(g != EdgeTable::kNone, "orient_shells needs a closed manifold surface");
        uint32_t u = g / 3;
        // Consistent neighbours traverse the shared edge in opposite directions.
        bool same_direction = half_edge_from(surface, h) == half_edge_from(surface, g);
        uint8_t want = static_cast<uint8_t>(flip[t] ^ (same_direction ? 1 : 0));
        if (info.shell_of_triangle[u] == UINT32_MAX) {
          info.shell_of_triangle[u] = shell;
          flip[u] = want;
          queue.push_back(u);
        } else if (flip[u] != want) {
          throw InputError(file + ": the surface is not orientable (like a Moebius strip or Klein bottle): " +
                           triangle_text(surface, t) + " and " + triangle_text(surface, u) +
                           " cannot be oriented consistently across their shared edge");
        }
      }
    }
  }
  for (size_t t = 0; t < nt; ++t)
    if (flip[t]) flip_triangle(surface, t);

  info.depth = shell_depths(surface, info.shell_of_triangle, info.count);

  std::vector<double> magnitude;
  shell_volumes(surface, info, info.volume, magnitude);
  std::vector<uint8_t> flip_shell(info.count, 0);
  for (uint32_t sh = 0; sh < info.count; ++sh) {
    // The rounding error of the sum is far below 1e-12 of its magnitude; a
    // closed non-self-intersecting shell encloses a volume far above that
    // (one that does not is flat to doubles: its orientation would be a
    // guess, and so would every volume check on its mesh).
    if (!(std::fabs(info.volume[sh]) > 1e-12 * magnitude[sh])) {
      uint32_t t0 = 0;
      while (info.shell_of_triangle[t0] != sh) ++t0;
      throw InputError(file + ": shell " + std::to_string(sh) + " (with " + triangle_text(surface, t0) +
                       ") encloses no volume: it is flat");
    }
    bool want_positive = info.depth[sh] % 2 == 0;
    if ((info.volume[sh] > 0) != want_positive) {
      flip_shell[sh] = 1;
      info.volume[sh] = -info.volume[sh];
    }
  }
  for (size_t t = 0; t < nt; ++t) {
    uint8_t final_flip = flip[t] ^ flip_shell[info.shell_of_triangle[t]];
    if (flip_shell[info.shell_of_triangle[t]]) flip_triangle(surface, t);
    if (final_flip) ++info.reoriented;
  }
  return info;
}

}  // namespace partet
