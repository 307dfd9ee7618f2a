// rank_of_point and set_leaf_owners (see leaf_owners.hpp).
#include "partition/leaf_owners.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "parallel/byte_image.hpp"
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
  // Every rank's boundary leaf keys, on every rank: (key, rank), sorted by key.
  std::string keys;
  put_array(keys, own.key);
  const std::vector<std::string> per_rank = comm.all_gather(keys);
  std::vector<std::pair<uint64_t, int32_t>> boundary;
  for (int32_t r = 0; r < comm.size(); ++r) {
    size_t pos = 0;
    for (uint64_t key : get_array<uint64_t>(per_rank[static_cast<size_t>(r)], pos)) boundary.emplace_back(key, r);
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
