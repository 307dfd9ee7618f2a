// The Delaunay fill (see delaunay_fill.hpp).
#include "front/delaunay_fill.hpp"

#include <algorithm>
#include <vector>

#include "core/error.hpp"
#include "core/flat_hash_map.hpp"
#include "core/predicates.hpp"
#include "core/shape_measure.hpp"
#include "core/tet_mesh.hpp"
#include "core/vertex_triple.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/edge_recovery.hpp"
#include "delaunay/tet_triangle_contact.hpp"

namespace partet {
namespace {

// Tets a recovery flip made on four surface vertices under this shape
// measure are removed (remove_flat_flipped).
constexpr double kFlippedShape = 0.3;

// The tets around each vertex of [lo, hi) (the surface's), compressed.
struct VertexTets {
  uint32_t lo;
  std::vector<uint32_t> first, tets;
  VertexTets(const DelaunayTets& d, uint32_t lo, uint32_t hi) : lo(lo), first(hi - lo + 1, 0) {
    auto in = [&](uint32_t v) { return v >= lo && v < hi; };
    for (uint32_t v : d.tets)
      if (in(v)) ++first[v - lo + 1];
    for (size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
    tets.resize(first.back());
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (size_t i = 0; i < d.tets.size(); ++i)
      if (in(d.tets[i])) tets[next[d.tets[i] - lo]++] = static_cast<uint32_t>(i / 4);
  }
  const uint32_t* begin(uint32_t v) const { return tets.data() + first[v - lo]; }
  const uint32_t* end(uint32_t v) const { return tets.data() + first[v - lo + 1]; }
};

class Fill {
 public:
  Fill(InitialFront& front, TetMesh& mesh) : front_(front), mesh_(mesh) {}

  DelaunayFillCounts run(size_t leaves) {
    surface_vertices_ = front_.xyz.size() / 3 - front_.core_vertices - front_.free_vertices;
    d_ = delaunay_tetrahedralize(front_.xyz);
    for (size_t t = 0; t < d_.num_tets(); ++t) counts_.delaunay_tets += d_.finite(t);
    counts_.walk_steps = d_.walk_steps;
    counts_.cavity_tets = d_.cavity_tets;
    std::vector<uint8_t> flipped;
    const EdgeRecoveryCounts recovery =
        recover_input_edges(d_, std::span<const uint32_t>(front_.faces.data(), 3 * front_.surface_faces), flipped);
    counts_.recovered_edges = recovery.recovered_edges;
    counts_.recovered_faces = recovery.recovered_faces;
    const size_t nt = d_.num_tets();
    removed_.assign(nt, 0);
    walls_.assign(nt, 0);
    find_walls();
    remove_flat_flipped(flipped);
    remove_across_missing();
    keep_components();
    rebuild(leaves);
    return counts_;
  }

 private:
  const double* pt(uint32_t v) const { return &d_.xyz[3 * size_t{v}]; }

  // The input triangles (the front's first surface_faces faces, facing the
  // material) that are Delaunay faces become walls on both sides, with the
  // tet on the material side recorded; the others are listed as missing.
  void find_walls() {
    const uint32_t lo = static_cast<uint32_t>(front_.core_vertices);
    const uint32_t hi = lo + static_cast<uint32_t>(surface_vertices_);
    auto on_surface = [&](uint32_t v) { return v >= lo && v < hi; };
    FlatHashMap<VertexTriple, uint32_t, VertexTripleTraits> faces;
    faces.reserve(front_.surface_faces * 2);
    for (size_t t = 0; t < d_.num_tets(); ++t) {
      const uint32_t* v = &d_.tets[4 * t];
      for (int i = 0; i < 4; ++i) {
        const uint32_t a = v[kOutwardFace[i][0]], b = v[kOutwardFace[i][1]], c = v[kOutwardFace[i][2]];
        if (on_surface(a) && on_surface(b) && on_surface(c))
          faces.get_or_insert(sorted_triple(a, b, c), static_cast<uint32_t>(4 * t + i));
      }
    }
    inner_of_.assign(front_.surface_faces, kNoNeighbour);
    for (size_t s = 0; s < front_.surface_faces; ++s) {
      const uint32_t* f = &front_.faces[3 * s];
      const uint32_t* found = faces.find(sorted_triple(f[0], f[1], f[2]));
      if (!found) {
        missing_.push_back(static_cast<uint32_t>(s));
        continue;
      }
      const uint32_t t = *found / 4, i = *found % 4;
      const uint32_t other = d_.neighbours[*found];
      PARTET_ASSERT(other != kNoNeighbour, "an input triangle is a face of the enclosing tet");
      walls_[t] |= uint8_t(1u << i);
      walls_[other / 4] |= uint8_t(1u << (other % 4));
      const bool t_inside = orient3d(pt(f[0]), pt(f[1]), pt(f[2]), pt(d_.tets[4 * t + i])) > 0;
      inner_of_[s] = t_inside ? *found : other;
    }
    counts_.missing_triangles = missing_.size();
  }

  // Tets a recovery flip made on four surface vertices whose shape is
  // under kFlippedShape are removed: the optimizer cannot move their
  // vertices, the front's removals place their own.
  void remove_flat_flipped(const std::vector<uint8_t>& flipped) {
    const uint32_t lo = static_cast<uint32_t>(front_.core_vertices);
    const uint32_t hi = lo + static_cast<uint32_t>(surface_vertices_);
    for (size_t t = 0; t < d_.num_tets(); ++t) {
      if (!flipped[t]) continue;
      const uint32_t* v = &d_.tets[4 * t];
      bool surface = true;
      for (int k = 0; k < 4; ++k) surface = surface && v[k] >= lo && v[k] < hi;
      if (!surface || !(shape_measure(pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3])) < kFlippedShape)) continue;
      if (!removed_[t]) ++counts_.removed_tets;
      removed_[t] = 1;
    }
  }

  bool meets(uint32_t t, const uint32_t* tri) const {
    const uint32_t* v = &d_.tets[4 * size_t{t}];
    const double* tp[4] = {pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3])};
    const double* rp[3] = {pt(tri[0]), pt(tri[1]), pt(tri[2])};
    return tet_meets_triangle_beyond_shared(tp, v, rp, tri);
  }

  void remove_across_missing() {
    const uint32_t lo = static_cast<uint32_t>(front_.core_vertices);
    const VertexTets around(d_, lo, lo + static_cast<uint32_t>(surface_vertices_));
    std::vector<uint32_t> seen(d_.num_tets(), UINT32_MAX), queue;
    for (uint32_t s : missing_) {
      const uint32_t* tri = &front_.faces[3 * size_t{s}];
      queue.clear();
      auto visit = [&](uint32_t t) {
        if (seen[t] == s) return;
        seen[t] = s;
        if (meets(t, tri)) queue.push_back(t);
      };
      for (int k = 0; k < 3; ++k)
        for (const uint32_t* t = around.begin(tri[k]); t != around.end(tri[k]); ++t) visit(*t);
      for (size_t q = 0; q < queue.size(); ++q) {
        const uint32_t t = queue[q];
        if (!removed_[t]) ++counts_.removed_tets;
        removed_[t] = 1;
        for (int i = 0; i < 4; ++i) {
          const uint32_t across = d_.neighbours[4 * size_t{t} + i];
          if (across != kNoNeighbour) visit(across / 4);
        }
      }
    }
  }

  // Components of the tets left, across faces that are not walls; kept
  // as delaunay_fill.hpp says.
  void keep_components() {
    const size_t nt = d_.num_tets();
    std::vector<uint8_t> side(nt, 0);  // per tet behind a wall: bit 0 on its material side, bit 1 on the other
    for (size_t s = 0; s < inner_of_.size(); ++s) {
      if (inner_of_[s] == kNoNeighbour) continue;
      side[inner_of_[s] / 4] |= 1;
      side[d_.neighbours[inner_of_[s]] / 4] |= 2;
    }
    kept_.assign(nt, 0);
    std::vector<uint8_t> done(nt, 0);
    std::vector<uint32_t> component;
    for (size_t start = 0; start < nt; ++start) {
      if (done[start] || removed_[start]) continue;
      component.assign(1, static_cast<uint32_t>(start));
      done[start] = 1;
      bool corner = false;
      int sides = 0;
      for (size_t c = 0; c < component.size(); ++c) {
        const uint32_t t = component[c];
        corner |= !d_.finite(t);
        sides |= side[t];
        for (int i = 0; i < 4; ++i) {
          const uint32_t across = d_.neighbours[4 * size_t{t} + i];
          if (across == kNoNeighbour || (walls_[t] >> i & 1)) continue;
          const uint32_t u = across / 4;
          if (done[u] || removed_[u]) continue;
          done[u] = 1;
          component.push_back(u);
        }
      }
      if (!corner && sides == 1) {
        for (uint32_t t : component) kept_[t] = 1;
        counts_.kept_tets += component.size();
      } else if (!corner && sides != 2) {
        ++counts_.dropped_components;  // no wall, or walls on both sides
      }
    }
  }

  // The mesh and the front from the kept tets (see delaunay_fill.hpp).
  void rebuild(size_t leaves) {
    const size_t n = front_.xyz.size() / 3;
    std::vector<uint32_t> faces;
    for (size_t s = 0; s < front_.surface_faces; ++s) {
      const uint32_t inner = inner_of_[s];
      if (inner != kNoNeighbour && kept_[inner / 4]) continue;
      faces.insert(faces.end(), &front_.faces[3 * s], &front_.faces[3 * s] + 3);
    }
    const size_t surface_left = faces.size() / 3;
    std::vector<uint32_t> tets;
    std::vector<uint8_t> used(n, 0);
    for (size_t t = 0; t < d_.num_tets(); ++t) {
      if (!kept_[t]) continue;
      const uint32_t* v = &d_.tets[4 * t];
      tets.insert(tets.end(), v, v + 4);
      for (int k = 0; k < 4; ++k) used[v[k]] = 1;
      for (int i = 0; i < 4; ++i) {
        const uint32_t across = d_.neighbours[4 * t + i];
        if ((walls_[t] >> i & 1) || (across != kNoNeighbour && kept_[across / 4])) continue;
        faces.insert(faces.end(), {v[kOutwardFace[i][0]], v[kOutwardFace[i][1]], v[kOutwardFace[i][2]]});
      }
    }
    // Gap vertices: the used ones keep their order, the free ones follow.
    std::vector<uint32_t> index(n);
    for (uint32_t v = 0; v < n; ++v) index[v] = v;
    const size_t first_gap = n - front_.free_vertices;
    uint32_t next = static_cast<uint32_t>(first_gap);
    for (size_t v = first_gap; v < n; ++v)
      if (used[v]) index[v] = next++;
    const size_t free_left = n - next;
    for (size_t v = first_gap; v < n; ++v)
      if (!used[v]) index[v] = next++;
    for (uint32_t& v : tets) v = index[v];
    for (uint32_t& v : faces) v = index[v];
    std::vector<double> xyz(3 * n);
    std::vector<uint64_t> ids(n);
    std::vector<uint32_t> leaf(n);
    for (size_t v = 0; v < n; ++v) {
      std::copy(&front_.xyz[3 * v], &front_.xyz[3 * v] + 3, &xyz[3 * size_t{index[v]}]);
      ids[index[v]] = front_.global_ids[v];
      leaf[index[v]] = front_.vertex_leaf[v];
    }
    front_.xyz = std::move(xyz);
    front_.global_ids = std::move(ids);
    front_.vertex_leaf = std::move(leaf);
    front_.faces = std::move(faces);
    front_.surface_faces = surface_left;
    front_.free_vertices = free_left;
    list_front_vertices(front_, leaves);
    mesh_ = TetMesh{};
    mesh_.xyz = front_.xyz;
    mesh_.global_ids = front_.global_ids;
    mesh_.tets = std::move(tets);
  }

  InitialFront& front_;
  TetMesh& mesh_;
  DelaunayTets d_;
  DelaunayFillCounts counts_;
  size_t surface_vertices_ = 0;  // between the core's vertices and the free ones
  std::vector<uint8_t> removed_, walls_, kept_;
  std::vector<uint32_t> missing_;   // input triangles (front face indices) that are not Delaunay faces
  std::vector<uint32_t> inner_of_;  // per input triangle: 4 t + i of its face on the material side, or kNoNeighbour
};

}  // namespace

DelaunayFillCounts delaunay_fill(InitialFront& front, const LinearOctree& tree, TetMesh& mesh) {
  PARTET_ASSERT(mesh.num_vertices() == front.core_vertices, "the core and the front disagree on the core's vertices");
  return Fill(front, mesh).run(tree.size());
}

}  // namespace partet
