// Centres and work of the boundary leaves handed to partition_points, and the
// load imbalance of a front part.
#include "partition/boundary_partition.hpp"

namespace partet {

void octant_centre(const RootCube& root, uint64_t key, int level, double* centre) {
  uint32_t x, y, z;
  morton_decode(key, x, y, z);
  const uint32_t half = octant_edge(level);  // half an edge in lattice units
  root.lattice_point(2 * x + half, 2 * y + half, 2 * z + half, centre);
}

PartitionResult partition_front_leaves(const Comm& comm, const FrontPart& part, const RootCube& root,
                                       BisectionMethod method) {
  const size_t n = part.leaves.size();
  std::vector<double> centre(3 * n), weight(n);
  for (size_t i = 0; i < n; ++i) {
    octant_centre(root, part.leaves.key[i], part.leaves.level[i], &centre[3 * i]);
    weight[i] = part.leaf_work(i);
  }
  return partition_points(comm, centre.data(), weight.data(), n, method);
}

double work_imbalance(const Comm& comm, const FrontPart& part) {
  const int64_t mine = static_cast<int64_t>(part.num_faces());
  const int64_t most = comm.max(mine), total = comm.sum(mine);
  if (total == 0) return 1.0;
  return static_cast<double>(most) * comm.size() / static_cast<double>(total);
}

}  // namespace partet
