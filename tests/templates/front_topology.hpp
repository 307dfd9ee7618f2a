// Test helper: the topology of a set of oriented triangles (a front), by
// sorting, with no geometry. A closed, consistently oriented 2-manifold has
// every directed edge used by exactly one face and its reverse by exactly
// one other, and the faces around every vertex form one fan: the link of the
// vertex (for each face (v, b, c) around v, the link edge b -> c) is one
// cycle. Counts what breaks that.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet::test {

struct FrontTopology {
  size_t faces = 0;
  size_t vertices = 0;     // used by some face
  size_t bad_edges = 0;    // directed edges used more than once, or whose reverse is not used once
  size_t pinched = 0;      // vertices whose faces form more than one fan

  bool manifold() const { return bad_edges == 0 && pinched == 0; }
};

inline FrontTopology front_topology(const std::vector<uint32_t>& faces) {
  FrontTopology t;
  t.faces = faces.size() / 3;
  std::vector<uint64_t> edges;
  struct LinkEdge {
    uint32_t v, from, to;
  };
  std::vector<LinkEdge> link;
  edges.reserve(faces.size());
  link.reserve(faces.size());
  for (size_t f = 0; f + 2 < faces.size(); f += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = faces[f + k], b = faces[f + (k + 1) % 3], c = faces[f + (k + 2) % 3];
      edges.push_back(uint64_t{a} << 32 | b);
      link.push_back({a, b, c});
    }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0, j; i < edges.size(); i = j) {
    for (j = i; j < edges.size() && edges[j] == edges[i]; ++j) {
    }
    const uint64_t reverse = edges[i] << 32 | edges[i] >> 32;
    const auto range = std::equal_range(edges.begin(), edges.end(), reverse);
    t.bad_edges += j - i != 1 || range.second - range.first != 1;
  }
  // Cycles of each vertex's link, following from -> to.
  std::sort(link.begin(), link.end(), [](const LinkEdge& p, const LinkEdge& q) {
    return p.v != q.v ? p.v < q.v : p.from < q.from;
  });
  std::vector<char> seen(link.size(), 0);
  for (size_t i = 0, j; i < link.size(); i = j) {
    for (j = i; j < link.size() && link[j].v == link[i].v; ++j) {
    }
    ++t.vertices;
    size_t cycles = 0;
    for (size_t s = i; s < j; ++s) {
      if (seen[s]) continue;
      ++cycles;
      for (size_t e = s; e < j && !seen[e];) {
        seen[e] = 1;
        const uint32_t next = link[e].to;
        auto it = std::lower_bound(link.begin() + i, link.begin() + j, next,
                                   [](const LinkEdge& p, uint32_t from) { return p.from < from; });
        e = it != link.begin() + j && it->from == next ? static_cast<size_t>(it - link.begin()) : j;
      }
    }
    t.pinched += cycles > 1;
  }
  return t;
}

}  // namespace partet::test
