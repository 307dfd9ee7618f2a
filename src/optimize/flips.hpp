// Topological improvement candidates: a cavity of tets and the tets that
// would replace it, with the worst quality (tet_quality) before and after.
//  - face_flip: the 2-3 flip of an interior face (two tets become three
//    around the edge joining their apexes);
//  - edge_removal: an interior edge whose ring of n = 3..7 tets closes is
//    removed, the ring polygon r_0..r_{n-1} retriangulated by the
//    Klincsek / Shewchuk dynamic program that maximises the worst new tet;
//    each polygon triangle (r_i, r_j, r_k) makes the tets (r_i, r_j, r_k, b)
//    and (r_i, r_k, r_j, a). n = 3 is the 3-2 flip, n = 4 the 4-4 flip;
//  - multi_face_removal: its inverse (Shewchuk's multi-face removal). The
//    faces sandwiched between two vertices d and e (each the common face of
//    a tet with apex d and one with apex e) that form a triangulated
//    polygon r_0..r_{n-1} with no vertex inside are removed: their 2(n - 2)
//    tets become the n tets (d, e, r_i, r_{i+1}) around the new edge de.
//    Grown greedily from one face, across the polygon edge whose growth
//    gives the best new tets, to n = 4..7; the best polygon is kept. The
//    segment de must cross the polygon (exact), so the new tets wind once
//    around it.
// Every new tet is positively oriented by exact orient3d (else no
// candidate), and the new tets' outer faces are the cavity's: boundary faces
// and faces shared with the rest of the mesh are untouched. A candidate is
// worth applying when new_quality > old_quality; nothing is changed here.
#pragma once

#include <cstdint>
#include <span>

#include "optimize/tet_topology.hpp"

namespace partet {

enum class FlipKind : uint8_t { k23, k32, k44, kEdgeRemoval, kMultiFace };

struct Flip {
  static constexpr int kMaxOld = 2 * (TetTopology::kMaxRing - 2);
  static constexpr int kMaxNew = 2 * (TetTopology::kMaxRing - 2);
  FlipKind kind = FlipKind::k23;
  double old_quality = 0;  // worst tet of the cavity
  double new_quality = 0;  // worst new tet
  int old_count = 0, new_count = 0;
  uint32_t old_tets[kMaxOld];
  uint32_t new_tets[4 * kMaxNew];

  std::span<const uint32_t> cavity() const { return {old_tets, static_cast<size_t>(old_count)}; }
  std::span<const uint32_t> replacement() const { return {new_tets, 4 * static_cast<size_t>(new_count)}; }
};

// The 2-3 flip of face `code` (face code 4*t + f); false on a boundary face
// or when a new tet would not be positive.
//
// With `beat` given, both look only for a flip whose worst new tet is above
// *beat and above the worst old tet (the only flips the optimizer takes),
// and return false when there is none: the search prunes everything else
// (the same flip as without it when there is one). Edge removal first
// bounds the whole ring: each ring tet's dihedral angle theta at its edge
// off the axis is split between two new tets, so no retriangulation beats
// kRegularSineScale * sin(theta / 2) there; a ring whose bound is below
// the bar is not searched (7-11 % of the topology step's time over the
// quick sets, 20 % on elephant r1).
bool face_flip(const TetTopology& topo, uint32_t code, Flip& flip, const double* beat = nullptr);

// Removal of the edge (v[i], v[j]) of tet t; false when its ring is open or
// longer than kMaxRing, or no retriangulation has only positive tets.
bool edge_removal(const TetTopology& topo, uint32_t t, int i, int j, Flip& flip, const double* beat = nullptr);

// Multi-face removal grown from face `code` (face code 4*t + f); false on a
// boundary face or when no polygon of 2 or more faces gives positive new
// tets (with `beat`, better ones, as above).
bool multi_face_removal(const TetTopology& topo, uint32_t code, Flip& flip, const double* beat = nullptr);

}  // namespace partet
