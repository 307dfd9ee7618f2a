// Per-rank classification on the partition view, with the coarsest level
// per triangle agreed over ranks (see distributed_classify.hpp).
#include "octree/distributed_classify.hpp"

#include <algorithm>

namespace partet {

ClassCounts classify_distributed(const Comm& comm, DistributedOctree& tree, const SurfaceMesh& surface,
                                 const RootCube& root, const std::vector<double>& vertex_size,
                                 const ClassifyOptions& options, LeafTriangles* own_rows) {
  const int rank = comm.rank();
  LinearOctree view = partition_view(tree.leaves, tree.ranges, rank);
  LeafTriangles bins = bin_triangles(view, surface, root);
  std::vector<double> coarsest(surface.num_triangles(), kMaxLevel);  // levels are exact in doubles
  for (size_t i = 0; i < view.size(); ++i) {
    if (view.owner[i] != rank) continue;
    for (uint32_t k = bins.first[i]; k < bins.first[i + 1]; ++k)
      coarsest[bins.tris[k]] = std::min<double>(coarsest[bins.tris[k]], view.level[i]);
  }
  comm.min(coarsest.data(), coarsest.size());
  for (size_t t = 0; t < coarsest.size(); ++t) bins.coarsest[t] = static_cast<uint8_t>(coarsest[t]);
  const ClassCounts local = classify_leaves(view, surface, root, vertex_size, bins, options);
  if (own_rows) {
    *own_rows = LeafTriangles{};
    own_rows->first.push_back(0);
    for (size_t i = 0; i < view.size(); ++i) {
      if (view.owner[i] != rank) continue;
      own_rows->tris.insert(own_rows->tris.end(), bins.tris.begin() + bins.first[i], bins.tris.begin() + bins.first[i + 1]);
      own_rows->first.push_back(static_cast<uint32_t>(own_rows->tris.size()));
    }
  }
  tree.leaves = leaves_of(view, rank);
  int64_t n[5] = {0, 0, 0, 0, static_cast<int64_t>(local.groups)};
  for (LeafClass c : tree.leaves.cls) {
    n[0] += c == LeafClass::kBoundary;
    n[1] += c == LeafClass::kTooClose;
    n[2] += c == LeafClass::kInterior;
    n[3] += c == LeafClass::kOutside;
  }
  comm.sum(n, 5);
  ClassCounts counts;
  counts.boundary = static_cast<size_t>(n[0]);
  counts.too_close = static_cast<size_t>(n[1]);
  counts.interior = static_cast<size_t>(n[2]);
  counts.outside = static_cast<size_t>(n[3]);
  counts.groups = static_cast<size_t>(n[4]);
  return counts;
}

}  // namespace partet
