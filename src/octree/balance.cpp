// 2:1 face and edge balance by required-octant closure, level by level (see
// balance.hpp).
#include "octree/balance.hpp"

#include <algorithm>
#include <array>
#include <bit>

#include "octree/neighbours.hpp"

namespace partet {

namespace {

// Octants of level L - 1 around a grandparent G (level L - 2) as a 4 x 4 x 4
// block: position (bx, by, bz) in 0..3, G's children at 1..2, bit
// bx + 4 by + 16 bz. kAround[c]: child c of G and its 18 face and edge
// neighbours.
constexpr std::array<uint64_t, 8> kAround = [] {
  std::array<uint64_t, 8> masks{};
  for (int c = 0; c < 8; ++c) {
    const int px = 1 + (c & 1), py = 1 + (c >> 1 & 1), pz = 1 + (c >> 2 & 1);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx != 0) + (dy != 0) + (dz != 0) == 3) continue;  // corners do not count
          masks[c] |= uint64_t{1} << ((px + dx) + 4 * (py + dy) + 16 * (pz + dz));
        }
  }
  return masks;
}();

// Appends to `up` the anchor keys of the octants in `mask` around the
// grandparent with anchor g whose children have edge h, skipping those
// outside the root cube.
void emit_block(const uint32_t* g, uint32_t h, uint64_t mask, std::vector<uint64_t>& up) {
  while (mask) {
    const int bit = std::countr_zero(mask);
    mask &= mask - 1;
    const int b[3] = {bit & 3, bit >> 2 & 3, bit >> 4 & 3};
    uint32_t a[3];
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i) {
      // g + (b - 1) h, within [0, kGridSize).
      if (b[i] == 0) {
        inside = g[i] >= h;
        a[i] = g[i] - h;
      } else {
        a[i] = g[i] + (b[i] - 1) * h;
        inside = a[i] < kGridSize;
      }
    }
    if (inside) up.push_back(morton_key(a[0], a[1], a[2]));
  }
}

bool by_key(const RefineRequest& a, const RefineRequest& b) { return a.key < b.key; }

}  // namespace

void balance_octree(LinearOctree& tree) { refine_octree(tree, balance_requests(tree)); }

std::vector<RefineRequest> balance_requests(const LinearOctree& tree) {
  // required[L]: anchor keys of the octants that must exist at level L.
  std::vector<std::vector<uint64_t>> required(kMaxLevel + 1);
  for (size_t i = 0; i < tree.size(); ++i) required[tree.level[i]].push_back(tree.key[i]);
  std::vector<RefineRequest> requests;  // sorted by key
  for (int level = kMaxLevel; level >= 1; --level) {
    std::vector<uint64_t>& here = required[level];
    std::sort(here.begin(), here.end());
    here.erase(std::unique(here.begin(), here.end()), here.end());
    const size_t old = requests.size();
    for (uint64_t key : here) requests.push_back({key, static_cast<uint8_t>(level)});
    std::inplace_merge(requests.begin(), requests.begin() + static_cast<std::ptrdiff_t>(old), requests.end(), by_key);
    if (level >= 2) {
      // Group the parents (level - 1) by grandparent (level - 2); sorted keys
      // make both groups consecutive.
      std::vector<uint64_t>& up = required[level - 1];
      const uint64_t parent_mask = ~(octant_key_span(level - 1) - 1);
      const uint64_t grand_mask = ~(octant_key_span(level - 2) - 1);
      const int child_shift = 3 * (kMaxLevel - level + 1);
      const uint32_t h = octant_edge(level - 1);
      size_t k = 0;
      while (k < here.size()) {
        const uint64_t grand = here[k] & grand_mask;
        uint64_t mask = 0;
        for (; k < here.size() && (here[k] & grand_mask) == grand; ++k)
          mask |= kAround[(here[k] & parent_mask) >> child_shift & 7];
        uint32_t g[3];
        morton_decode(grand, g[0], g[1], g[2]);
        emit_block(g, h, mask, up);
      }
    }
    here.clear();
    here.shrink_to_fit();
  }
  return requests;
}

bool is_balanced(const LinearOctree& tree) {
  // Each pair is checked from its finer leaf, which sees a coarser leaf
  // sharing its face (or edge) as the one leaf across it (or at the start of
  // the edge in that region).
  std::vector<size_t> across;
  for (size_t i = 0; i < tree.size(); ++i) {
    const int coarsest = tree.level[i] - 1;
    for (int f = 0; f < kFaceCount; ++f) {
      across.clear();
      append_face_neighbours(tree, i, f, across);
      for (size_t j : across)
        if (tree.level[j] < coarsest) return false;
    }
    for (int e = 0; e < kEdgeCount; ++e) {
      for (int region = 1; region < 4; ++region) {
        const size_t j = edge_region_leaf(tree, i, e, region);
        if (j != kNoLeaf && tree.level[j] < coarsest) return false;
      }
    }
  }
  return true;
}

}  // namespace partet
