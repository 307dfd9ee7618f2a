// Optimization-based smoothing of one vertex (after Freitag, Jones and
// Plassmann, as used by Klingner and Shewchuk): raise the worst tet_quality
// of the vertex's star by a few steps of non-smooth ascent. Each step takes
// the analytic gradients (tet_quality_gradient) of the star's tets within
// 0.1 of the worst quality, the search direction as the point of least norm
// in the convex hull of the gradients of the active (near-worst) tets, a
// first step length where the linear models predict another modelled tet
// becomes the worst, and halves it until the worst quality strictly
// improves (a trial measures the near-worst tets first, one by one, then
// the rest together: star_points.hpp) and every star tet is positive by
// exact orient3d. The vertex moves only then:
// never to a worse or invalid place.
//
// Also here: the radius-ratio relaxation of one vertex (relax_vertex) and
// the ascent direction (least_norm_direction).
//
// Contract: v is not on the boundary (its star is closed) and not frozen;
// the caller decides which vertices may move.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "optimize/star_points.hpp"
#include "optimize/tet_topology.hpp"

namespace partet {

// Scratch space reused across calls (no allocation per vertex).
struct SmoothingScratch {
  std::vector<uint32_t> star;
  std::vector<uint32_t> quads;   // the star's vertex quadruples
  std::vector<double> quality;   // per star tet
  std::vector<double> trial;     // per star tet, at a trial point
  std::vector<double> trial_ratio;  // per star tet, its radius ratio at a trial point (relax_vertex)
  std::vector<double> gradient;  // 3 per star tet
  std::vector<size_t> active;    // star tets near the worst
  StarPoints points;             // the star's corners, measured together at trial points
  std::vector<double> odt_terms;  // relax_vertex's circumcentre terms (StarPoints::circumcentre_terms)
};

// Moves v when that raises the worst quality of its star; true if it moved.
bool smooth_vertex(TetTopology& topo, uint32_t v, SmoothingScratch& scratch);

// smooth_vertex for a vertex no tet has yet (an insertion trial's, before
// it joins the mesh): its star is to be `quads` (vertex quadruples, each
// having v, positive at v's point), which the topology does not hold. v's
// point moves (TetTopology::place_vertex) as smooth_vertex would move it
// in that star, and scratch.quality is left holding the tet_quality of
// each of `quads` at v's final point. True if v moved.
bool smooth_new_vertex(TetTopology& topo, uint32_t v, std::span<const uint32_t> quads, SmoothingScratch& scratch);

// Smart Laplacian relaxation: moves v to the volume-weighted mean of its
// tets' circumcentres (the optimal Delaunay triangulation point), else to
// the centroid of its neighbours, or a half or a quarter of the way, when
// every star tet stays positive (exact orient3d), no star tet's quality
// falls below min(the star's worst quality, `floor`), no more of its tets
// have an angle under 10 degrees, and the sum of its tets' radius ratios
// grows. The optimizer's passes maximise the worst dihedral angle, which
// leaves the mean radius ratio where it was; this lifts it. With `floor` at
// +infinity the star's worst tet never drops; below it, a star whose worst
// tet is above the floor may trade some of that margin for radius ratio
// (the optimizer passes the quality of its relaxation floor angle, or of
// the mesh's smallest angle when that is larger: optimize.cpp). `star` is
// v's tets, `neighbours` the vertices sharing one with v, ascending, each
// once (vertex_incidence.hpp). True if v moved.
bool relax_vertex(TetTopology& topo, uint32_t v, std::span<const uint32_t> star, std::span<const uint32_t> neighbours,
                  SmoothingScratch& scratch, double floor);

// The point of least norm in the convex hull of the vectors gradient[3k ..
// 3k + 2] for k in `active` (not empty), in d: the steepest common ascent
// direction of the active tets. Exact (up to rounding) for up to six
// vectors; Gilbert's iterations, at most 64, for more. The zero vector
// when `active` is empty or no candidate point is a number.
void least_norm_direction(const std::vector<double>& gradient, const std::vector<size_t>& active, double d[3]);

}  // namespace partet
