// The linear octree: leaves as (Morton key, level) on an integer grid over
// the root cube, sorted, with class and owner per leaf (flat arrays).
//
// Conventions (used unchanged by the distributed version):
// - Grid: the root cube is [0, 2^kMaxLevel)^3 grid units; a leaf of level l
//   (root = 0) has edge 2^(kMaxLevel - l) units and its anchor (min corner)
//   is a multiple of that edge.
// - Lattice: mesh vertices made from the tree (octant corners, edge
//   midpoints, face and octant centres) live on the lattice of doubled grid
//   coordinates, so that the centre of a deepest leaf is a lattice point:
//   lattice = 2 * grid. Lattice coordinates of vertices strictly inside the
//   root cube are below 2^(kMaxLevel+1) and fit 21 bits; their Morton key
//   (63 bits) is the vertex's global id in the octree vertex space.
// - Space: point = origin + lattice * (unit / 2), with `unit` (one grid
//   unit) a power of two and `origin` a multiple of unit/2, so that every
//   lattice point has exactly representable coordinates.
// - Leaves are sorted by the Morton key of their anchor; in a complete
//   octree they tile the root cube, so the leaf containing a grid point is
//   the last leaf whose key is not above the point's key.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace partet {

constexpr int kMaxLevel = 20;
constexpr uint32_t kGridSize = 1u << kMaxLevel;

// Edge of a level-l octant in grid units.
inline uint32_t octant_edge(int level) { return 1u << (kMaxLevel - level); }
// Number of Morton keys (grid points) inside a level-l octant: the keys of
// the octant with anchor key k are [k, k + octant_key_span(l)).
inline uint64_t octant_key_span(int level) { return uint64_t{1} << (3 * (kMaxLevel - level)); }

// Morton key: bits of x, y, z (each below 2^21) interleaved, x lowest.
uint64_t morton_key(uint32_t x, uint32_t y, uint32_t z);
void morton_decode(uint64_t key, uint32_t& x, uint32_t& y, uint32_t& z);

enum class LeafClass : uint8_t {
  kUnclassified = 0,
  kBoundary,  // the closed leaf box meets a surface triangle
  kTooClose,  // nearer to a surface triangle than the threshold times its size
  kInterior,  // inside the domain: filled by a template
  kOutside,   // outside the domain: ignored
  kDone,      // boundary leaf whose front is gone
};

struct LinearOctree {
  std::vector<uint64_t> key;    // Morton key of each leaf's anchor (grid units), ascending
  std::vector<uint8_t> level;   // per leaf
  std::vector<LeafClass> cls;   // per leaf
  std::vector<int32_t> owner;   // per leaf: owning rank

  size_t size() const { return key.size(); }
  // Index of the leaf containing grid point (x, y, z) (boxes half-open);
  // the tree must be complete. Binary search.
  size_t locate(uint32_t x, uint32_t y, uint32_t z) const;
  // Anchor of leaf i in grid units.
  void anchor(size_t i, uint32_t& x, uint32_t& y, uint32_t& z) const { morton_decode(key[i], x, y, z); }
};

// Where the root cube sits in space.
struct RootCube {
  double origin[3] = {0, 0, 0};
  double unit = 1;  // one grid unit, a power of two

  double edge() const { return unit * kGridSize; }
  // Coordinates of lattice point (doubled grid coordinates).
  void lattice_point(uint32_t lx, uint32_t ly, uint32_t lz, double* p) const {
    p[0] = origin[0] + lx * (0.5 * unit);
    p[1] = origin[1] + ly * (0.5 * unit);
    p[2] = origin[2] + lz * (0.5 * unit);
  }
};

// The root cube around a bounding box (min xyz, max xyz): cubic, enlarged so
// that the box lies strictly inside with a margin of 1/16 of its largest
// extent on each side (less at most half a grid unit), edge a power of two,
// origin a multiple of unit/2. A box of zero extent gets an edge of 2.
RootCube make_root_cube(const double* bbox);

// Closed box [lo, hi] of the octant with anchor (x, y, z) (grid units) and
// level `level`; the corners are lattice points, hence exact.
void octant_box(const RootCube& root, uint32_t x, uint32_t y, uint32_t z, int level, double* lo, double* hi);
// The same for leaf i of `tree`.
void leaf_box(const LinearOctree& tree, const RootCube& root, size_t i, double* lo, double* hi);

}  // namespace partet
