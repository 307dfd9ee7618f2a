// interface_faces and reown_leaves_by_faces (see interface_owners.hpp).
#include "partition/interface_owners.hpp"

#include <algorithm>

#include "partition/boundary_partition.hpp"
#include "partition/leaf_owners.hpp"
#include "partition/recursive_bisection.hpp"

namespace partet {

InterfaceFaces interface_faces(const Front& front, const LinearOctree& tree, const RootCube& root,
                               const RemovalOptions& options) {
  InterfaceFaces out;
  std::vector<size_t> leaves;
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    removal_neighbourhood_leaves(front, root, f, options, leaves);
    int32_t low = tree.owner[leaves.front()], high = low;
    for (size_t leaf : leaves) {
      low = std::min(low, tree.owner[leaf]);
      high = std::max(high, tree.owner[leaf]);
    }
    if (low == high) continue;
    out.faces.push_back(f);
    out.lowest.push_back(low);
  }
  return out;
}

void reown_leaves_by_faces(const Comm& comm, const Front& front, const std::vector<uint32_t>& faces,
                           const std::vector<int32_t>& contributor, const RootCube& root, LinearOctree& tree) {
  std::vector<double> xyz, weight;
  for (size_t i = 0; i < faces.size(); ++i) {
    if (contributor[i] != comm.rank()) continue;
    const uint32_t* t = front.face(faces[i]);
    for (int k = 0; k < 3; ++k)
      xyz.push_back((front.point(t[0])[k] + front.point(t[1])[k] + front.point(t[2])[k]) / 3);
    weight.push_back(1);
  }
  const PartitionResult cut = partition_points(comm, xyz.data(), weight.data(), weight.size(), BisectionMethod::kRib);
  for (size_t i = 0; i < tree.size(); ++i) {
    double centre[3];
    octant_centre(root, tree.key[i], tree.level[i], centre);
    tree.owner[i] = rank_of_point(cut.separators, comm.size(), centre);
  }
}

}  // namespace partet
