// Leaf classification against the surface (LeafClass): boundary first,
// then interior or outside, then too close among the interior leaves.
//
// - Boundary: the closed leaf box meets a surface triangle (exact;
//   bin_triangles).
// - Interior / outside: the other leaves, in connected groups across faces.
//   Two such leaves sharing a face are on the same side of the surface (a
//   triangle meeting the shared closed face would make both boundary), so
//   one exact inside test per group (ray parity from the centre of its first
//   leaf, a lattice point, against all triangles; inside = odd, so cavities,
//   nested shells and disjoint bodies work) decides the whole group (groups
//   by union-find over face neighbours).
// - Too close: an interior leaf L (edge h) is too close when, for some
//   triangle t (size s_t: the mean of its vertices' target sizes), the
//   floating-point distance from L's box to t is below
//       too_close * max(s_t, min(h / 2, b_t)),
//   b_t being the edge of the coarsest leaf t meets. Outside leaves near the
//   surface stay outside: too-close leaves are inside the domain.
//
// Why that gap. The leaves left interior are filled by templates; the gap
// between them and the surface is filled by the advancing front. The front
// builds its first layer of tets on surface triangles of size s, whose ideal
// apex lies at the height of a regular tet, sqrt(2/3) s = 0.82 s. A core
// much nearer than that forces flat tets (slivers) between the surface and
// the core faces; a core farther than two sizes only costs more front work
// and fills with worse tets than the core's. The gap actually left is
// between the threshold and the threshold plus one leaf edge, so the
// default 0.5 makes the thinnest gap about half an ideal layer and the
// typical gap about one: measured on the corpus (docs/decisions.md), 0.5
// beats 0.8 on the share of dihedral angles under 10 degrees and the mean
// radius ratio everywhere a core exists, and 0.4 starts to make slivers. The second term keeps large
// leaves away: a leaf more than twice the local surface size (2:1 balance
// allows that right next to a boundary leaf) exposes core faces of its own
// size h, whose tets need a height of about h / 2 to be well shaped; it
// matches the first term at h = 2 s_t, so the rule is continuous in h, and it
// is capped at b_t (what a face or edge neighbour of t's leaves can reach
// under 2:1 balance) so that the search around t stays local.
//
// Cost: one range query per triangle for the bins, one per batch of nearby
// triangles for too-close distances, six point locations per non-boundary
// leaf for the groups, and one accelerated exact ray test per group
// (RayParityIndex).
#pragma once

#include <cstddef>
#include <vector>

#include "octree/octree.hpp"
#include "octree/triangle_bins.hpp"
#include "surface/surface_mesh.hpp"

namespace partet {

struct ClassifyOptions {
  // Gap between the surface and the templated core, in target sizes (see
  // the file comment); 0 classifies no leaf too close.
  double too_close = 0.5;
};

struct ClassCounts {
  size_t boundary = 0;
  size_t too_close = 0;
  size_t interior = 0;
  size_t outside = 0;
  size_t groups = 0;  // connected groups of non-boundary leaves (one inside test each)
};

// Sets tree.cls for every leaf from scratch and returns the counts. `tree`
// is complete and covers the surface; `vertex_size` has a target size per
// surface vertex (VertexSizing::size); `bins` is bin_triangles(tree, ...).
ClassCounts classify_leaves(LinearOctree& tree, const SurfaceMesh& surface, const RootCube& root,
                            const std::vector<double>& vertex_size, const LeafTriangles& bins,
                            const ClassifyOptions& options = {});

// The same, binning the triangles first.
ClassCounts classify_leaves(LinearOctree& tree, const SurfaceMesh& surface, const RootCube& root,
                            const std::vector<double>& vertex_size, const ClassifyOptions& options = {});

}  // namespace partet
