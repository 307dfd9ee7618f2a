// rank_of_point and set_leaf_owners (see leaf_owners.hpp).
#include "partition/leaf_owners.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "partition/boundary_partition.hpp"

namespace partet {

int rank_of_point(const std::vector<Separator>& separators, int ranks, const double* p) {
  int first = 0, last = ranks;
  while (last - first > 1) {
    const auto cut = std::find_if(separators.begin(), separators.end(), [&](const Separator& s) {
      return s.first_rank == first && s.last_rank == last;
    });
    PARTET_ASSERT(cut != separators.end(), "no separator splits ranks " + std::to_string(first) + " to " +
                                               std::to_string(last - 1));
    if (project(cut->normal, p) <= cut->offset)
      last = cut->mid_rank;
    else
      first = cut->mid_rank;
  }
  return first;
}

void set_leaf_owners(const Comm& comm, const LinearOctree& own, const std::vector<Separator>& separators,
                     const RootCube& root, LinearOctree& tree) {
  std::string keys(own.key.size() * sizeof(uint64_t), '\0');
  if (!own.key.empty()) std::memcpy(keys.data(), own.key.data(), keys.size());
  std::string all;
  std::vector<std::string> per_rank = comm.gather(keys, 0);
  if (comm.rank() == 0)
    for (const std::string& k : per_rank) {
      const uint64_t n = k.size();
      all.append(reinterpret_cast<const char*>(&n), sizeof n);
      all += k;
    }
  comm.broadcast(all, 0);
  // (key, rank) of every boundary leaf, sorted by key.
  std::vector<std::pair<uint64_t, int32_t>> boundary;
  size_t pos = 0;
  for (int32_t r = 0; r < comm.size(); ++r) {
    uint64_t n = 0;
    PARTET_ASSERT(pos + sizeof n <= all.size(), "truncated leaf owners");
    std::memcpy(&n, all.data() + pos, sizeof n);
    pos += sizeof n;
    for (size_t i = 0; i < n / sizeof(uint64_t); ++i) {
      uint64_t key = 0;
      std::memcpy(&key, all.data() + pos + i * sizeof key, sizeof key);
      boundary.emplace_back(key, r);
    }
    pos += n;
  }
  std::sort(boundary.begin(), boundary.end());
  tree.owner.resize(tree.size());
  for (size_t i = 0; i < tree.size(); ++i) {
    const auto it = std::lower_bound(boundary.begin(), boundary.end(), std::make_pair(tree.key[i], int32_t{-1}));
    if (it != boundary.end() && it->first == tree.key[i]) {
      tree.owner[i] = it->second;
    } else {
      double centre[3];
      octant_centre(root, tree.key[i], tree.level[i], centre);
      tree.owner[i] = rank_of_point(separators, comm.size(), centre);
    }
  }
}

}  // namespace partet
