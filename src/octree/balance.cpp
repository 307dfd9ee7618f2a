// 2:1 face and edge balance, and the wider grading radii, by required-octant
// closure, level by level (see balance.hpp).
#include "octree/balance.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>

#include "core/error.hpp"
#include "core/hash_mix.hpp"
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

// Where the required octants of the next level go: `up`, each key at most
// once among the last few thousand (a direct-mapped table of recent keys).
// The blocks of neighbouring grandparents overlap, and the grandparents
// come in key order, so most repeats are recent: femur r2 pushed 2.49 M
// keys for 390 k distinct ones, and sorting the repeats was two thirds of
// the balance. Repeats the table misses are removed by the sort as before.
class KeySink {
 public:
  explicit KeySink(std::vector<uint64_t>& up) : up_(up), recent_(kSlots, kEmpty) {}
  void add(uint64_t key) {
    uint64_t& slot = recent_[hash_mix(key) & (kSlots - 1)];
    if (slot == key) return;
    slot = key;
    up_.push_back(key);
  }

 private:
  static constexpr size_t kSlots = size_t{1} << 13;
  static constexpr uint64_t kEmpty = UINT64_MAX;  // no anchor key (63 bits)
  std::vector<uint64_t>& up_;
  std::vector<uint64_t> recent_;
};

// Adds to `up` the anchor keys of the octants in `mask` around the
// grandparent with anchor g whose children have edge h, skipping those
// outside the root cube.
void emit_block(const uint32_t* g, uint32_t h, uint64_t mask, KeySink& up) {
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
    if (inside) up.add(morton_key(a[0], a[1], a[2]));
  }
}

bool by_key(const RefineRequest& a, const RefineRequest& b) { return a.key < b.key; }

// The wider blocks of grading R >= 2 around a grandparent G: the (2R + 2)^3
// octants of level L - 1 at offsets -R..R + 1 (G's children at 0..1), as a
// bit set; cover[p] has bit c when position p lies in child c's block.
struct WideBlock {
  int radius, side;
  std::vector<uint8_t> cover;

  explicit WideBlock(int r) : radius(r), side(2 * r + 2), cover(size_t(side) * side * side, 0) {
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
          for (int c = 0; c < 8; ++c) {
            const int d[3] = {x - r - (c & 1), y - r - (c >> 1 & 1), z - r - (c >> 2 & 1)};
            if (std::abs(d[0]) <= r && std::abs(d[1]) <= r && std::abs(d[2]) <= r)
              cover[size_t(x) + size_t(side) * (size_t(y) + size_t(side) * size_t(z))] |= uint8_t(1u << c);
          }
  }

  // Adds the anchors of the octants of the children in `children` (a bit
  // per child) around the grandparent with anchor g whose children have
  // edge h, skipping those outside the root cube.
  void emit(const uint32_t* g, uint32_t h, uint8_t children, KeySink& up) const {
    size_t p = 0;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x, ++p) {
          if (!(cover[p] & children)) continue;
          const int b[3] = {x - radius, y - radius, z - radius};
          uint32_t a[3];
          bool inside = true;
          for (int i = 0; i < 3 && inside; ++i) {
            const int64_t at = int64_t{g[i]} + int64_t{b[i]} * h;
            inside = at >= 0 && at < int64_t{kGridSize};
            a[i] = static_cast<uint32_t>(at);
          }
          if (inside) up.add(morton_key(a[0], a[1], a[2]));
        }
  }
};

}  // namespace

void balance_octree(LinearOctree& tree, int grading) { refine_octree(tree, balance_requests(tree, grading)); }

std::vector<RefineRequest> balance_requests(const LinearOctree& tree, int grading) {
  PARTET_ASSERT(grading >= 1 && grading <= kMaxGrading, "grading radius out of range");
  // Grading 1 uses the 18-neighbour masks (kAround), the wider radii the block.
  const bool wide = grading > 1;
  const WideBlock block(grading);
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
      KeySink up(required[level - 1]);
      const uint64_t parent_mask = ~(octant_key_span(level - 1) - 1);
      const uint64_t grand_mask = ~(octant_key_span(level - 2) - 1);
      const int child_shift = 3 * (kMaxLevel - level + 1);
      const uint32_t h = octant_edge(level - 1);
      size_t k = 0;
      while (k < here.size()) {
        const uint64_t grand = here[k] & grand_mask;
        uint8_t children = 0;  // a bit per child of the grandparent in `here`
        for (; k < here.size() && (here[k] & grand_mask) == grand; ++k)
          children |= uint8_t(1u << ((here[k] & parent_mask) >> child_shift & 7));
        uint32_t g[3];
        morton_decode(grand, g[0], g[1], g[2]);
        if (wide) {
          block.emit(g, h, children, up);
        } else {
          uint64_t mask = 0;
          for (int c = 0; c < 8; ++c)
            if (children >> c & 1) mask |= kAround[c];
          emit_block(g, h, mask, up);
        }
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

bool is_graded(const LinearOctree& tree, int grading) {
  if (grading <= 1) return is_balanced(tree);
  // Each octant of a leaf's block exists when the leaf holding its centre
  // is no coarser than it.
  for (size_t i = 0; i < tree.size(); ++i) {
    const int level = tree.level[i];
    if (level < 1) continue;
    const uint32_t h = octant_edge(level - 1);
    uint32_t p[3];
    morton_decode(tree.key[i] & ~(octant_key_span(level - 1) - 1), p[0], p[1], p[2]);
    for (int dz = -grading; dz <= grading; ++dz)
      for (int dy = -grading; dy <= grading; ++dy)
        for (int dx = -grading; dx <= grading; ++dx) {
          const int64_t c[3] = {int64_t{p[0]} + int64_t{dx} * h + h / 2, int64_t{p[1]} + int64_t{dy} * h + h / 2,
                                int64_t{p[2]} + int64_t{dz} * h + h / 2};
          if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[0] >= kGridSize || c[1] >= kGridSize || c[2] >= kGridSize)
            continue;
          const size_t j = tree.locate(uint32_t(c[0]), uint32_t(c[1]), uint32_t(c[2]));
          if (tree.level[j] < level - 1) return false;
        }
  }
  return true;
}

}  // namespace partet
