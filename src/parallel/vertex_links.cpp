// link_shared_vertices (see vertex_links.hpp): two rendezvous exchanges of
// fixed-size records through migrate.
#include "parallel/vertex_links.hpp"

#include <algorithm>
#include <tuple>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
#include "parallel/migrate.hpp"

namespace partet {

namespace {

struct Copy {  // one rank's copy of an id, at its home rank
  uint64_t id;
  uint32_t index;
  int32_t rank;
};

struct Link {  // for a holder: its vertex `index` has a copy at (rank, other)
  uint32_t index;
  int32_t rank;
  uint32_t other;
};

}  // namespace

size_t VertexLinks::num_shared() const {
  size_t shared = 0;
  for (size_t v = 0; v < num_vertices(); ++v) shared += first[v + 1] > first[v];
  return shared;
}

VertexLinks link_shared_vertices(const Comm& comm, const std::vector<uint64_t>& global_ids) {
  const size_t n = global_ids.size();
  PARTET_ASSERT(n < UINT32_MAX, "too many vertices on one rank to link");
  std::vector<int32_t> home(n);
  std::vector<Copy> mine(n);
  for (size_t v = 0; v < n; ++v) {
    home[v] = static_cast<int32_t>(hash_mix(global_ids[v]) % static_cast<uint64_t>(comm.size()));
    mine[v] = {global_ids[v], static_cast<uint32_t>(v), comm.rank()};
  }
  std::vector<Copy> copies = migrate(comm, home, mine);
  std::sort(copies.begin(), copies.end(), [](const Copy& a, const Copy& b) {
    return std::tie(a.id, a.rank) < std::tie(b.id, b.rank);
  });

  // Every copy of a shared id learns where the others are.
  std::vector<int32_t> to;
  std::vector<Link> links;
  for (size_t i = 0; i < copies.size();) {
    size_t j = i + 1;
    while (j < copies.size() && copies[j].id == copies[i].id) ++j;
    for (size_t a = i; a < j && j - i > 1; ++a)
      for (size_t b = i; b < j; ++b) {
        if (a == b) continue;
        PARTET_ASSERT(copies[a].rank != copies[b].rank, "a global id appears twice on one rank");
        to.push_back(copies[a].rank);
        links.push_back({copies[a].index, copies[b].rank, copies[b].index});
      }
    i = j;
  }
  std::vector<Link> received = migrate(comm, to, links);
  std::sort(received.begin(), received.end(), [](const Link& a, const Link& b) {
    return std::tie(a.index, a.rank) < std::tie(b.index, b.rank);
  });

  VertexLinks out;
  out.first.assign(n + 1, 0);
  for (const Link& l : received) ++out.first[l.index + 1];
  for (size_t v = 0; v < n; ++v) out.first[v + 1] += out.first[v];
  out.rank.reserve(received.size());
  out.index.reserve(received.size());
  for (const Link& l : received) {
    out.rank.push_back(l.rank);
    out.index.push_back(l.other);
  }
  return out;
}

}  // namespace partet
