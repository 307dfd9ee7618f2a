// The front's cavities and the wedges around its edges (see
// front_cavities.hpp).
#include "front/front_cavities.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/predicates.hpp"

namespace partet {

bool pair_faces_around_edge(const Front& front, uint32_t x, uint32_t y, const std::vector<uint32_t>& faces,
                            std::vector<uint32_t>& partner) {
  const size_t n = faces.size();
  if (n < 3 || n % 2 != 0) return false;
  // Per face: its third vertex and whether it runs x -> y (its unmeshed side
  // then lies at increasing angles around the edge, as defined below).
  std::vector<const double*> apex(n);
  std::vector<uint8_t> forward(n);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t* t = front.face(faces[i]);
    int k = 0;
    while (k < 3 && (t[k] == x || t[k] == y)) ++k;
    if (k == 3) return false;
    apex[i] = front.point(t[k]);
    forward[i] = t[(k + 1) % 3] == x;  // (w, x, y) in cyclic order: x -> y
  }
  const double *px = front.point(x), *py = front.point(y);
  // Angle around the edge from the first face's half-plane: the side
  // orient3d(x, y, apex[0], .) > 0 is (0, pi), the other (pi, 2 pi); within
  // a half, j follows i when orient3d(x, y, apex[i], apex[j]) > 0.
  std::vector<int> half(n, 0);
  for (size_t i = 1; i < n; ++i) {
    const int s = orient3d(px, py, apex[0], apex[i]);
    if (s == 0) return false;
    half[i] = s > 0 ? 0 : 1;
  }
  for (size_t i = 1; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      if (half[i] == half[j] && orient3d(px, py, apex[i], apex[j]) == 0) return false;
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin() + 1, order.end(), [&](size_t i, size_t j) {
    if (half[i] != half[j]) return half[i] < half[j];
    return orient3d(px, py, apex[i], apex[j]) > 0;
  });
  for (size_t k = 0; k < n; ++k)
    if (forward[order[k]] == forward[order[(k + 1) % n]]) return false;
  partner.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    const size_t j = forward[i] ? order[(k + 1) % n] : order[(k + n - 1) % n];
    partner[i] = faces[j];
  }
  return true;
}

void faces_across_edge(const Front& front, uint32_t f, uint32_t x, uint32_t y, std::vector<uint32_t>& on_edge) {
  on_edge.clear();
  if (front.edge_uses(x, y) <= 2) {
    front.for_each_other_face_on_edge(f, x, y, [&](uint32_t g) { on_edge.push_back(g); });
    return;
  }
  front.for_each_face_on_edge(x, y, [&](uint32_t g) { on_edge.push_back(g); });
  std::vector<uint32_t> partner;
  if (pair_faces_around_edge(front, x, y, on_edge, partner)) {
    on_edge.assign(1, partner[std::find(on_edge.begin(), on_edge.end(), f) - on_edge.begin()]);
    return;
  }
  std::erase(on_edge, f);
}

void front_cavities(const Front& front, std::vector<uint32_t>& faces, std::vector<size_t>& first) {
  std::vector<std::pair<uint64_t, uint32_t>> edge_face;
  std::vector<uint32_t> parent(front.num_face_slots());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto unite = [&](uint32_t f, uint32_t g) {
    const uint32_t x = find(f), y = find(g);
    parent[std::max(x, y)] = std::min(x, y);  // the root is the lowest face index
  };
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    const uint32_t* t = front.face(f);
    for (int i = 0; i < 3; ++i) {
      const uint32_t x = std::min(t[i], t[(i + 1) % 3]), y = std::max(t[i], t[(i + 1) % 3]);
      edge_face.emplace_back((uint64_t{x} << 32) | y, f);
    }
  }
  std::sort(edge_face.begin(), edge_face.end());
  std::vector<uint32_t> on_edge, partner;
  for (size_t i = 0, j = 0; i < edge_face.size(); i = j) {
    while (j < edge_face.size() && edge_face[j].first == edge_face[i].first) ++j;
    on_edge.clear();
    for (size_t k = i; k < j; ++k) on_edge.push_back(edge_face[k].second);
    const auto x = static_cast<uint32_t>(edge_face[i].first >> 32), y = static_cast<uint32_t>(edge_face[i].first);
    const bool paired = on_edge.size() > 2 && pair_faces_around_edge(front, x, y, on_edge, partner);
    for (size_t k = 0; k < on_edge.size(); ++k) unite(on_edge[k], paired ? partner[k] : on_edge[0]);
  }
  // Faces by (root, index): cavities in order of their lowest face.
  std::vector<std::pair<uint32_t, uint32_t>> by_root;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f)
    if (front.alive(f)) by_root.emplace_back(find(f), f);
  std::sort(by_root.begin(), by_root.end());
  faces.clear();
  first.clear();
  for (size_t i = 0; i < by_root.size(); ++i) {
    if (i == 0 || by_root[i].first != by_root[i - 1].first) first.push_back(i);
    faces.push_back(by_root[i].second);
  }
  first.push_back(faces.size());
}

}  // namespace partet
