// Options of a meshing run, as given on the command line; one struct handed
// to the pipeline (no globals).
#pragma once

#include <limits>
#include <string>

#include "partition/recursive_bisection.hpp"

namespace partet {

// Where a run may stop early, writing what it has.
enum class StopAfter { kNone, kSurface, kTemplates };

struct MeshOptions {
  std::string input;      // surface file
  std::string output;     // volume mesh file (.mesh .msh .vtu .pvtu)
  std::string report;     // --report FILE.json, empty for none
  std::string front_out;  // --front-out FILE: the initial front as a surface
  StopAfter stop_after = StopAfter::kNone;
  double max_size = std::numeric_limits<double>::infinity();  // --max-size H
  double size_factor = 1;                                     // --size-factor F
  int max_level = 20;                                         // --max-level L
  double too_close = 0.5;                                     // --too-close T
  // --grading R: the octree's grading radius (octree/balance.hpp): around
  // an octant split finer, its size holds for R octants before a coarser
  // leaf; 1 is the plain 2:1 balance.
  int grading = 2;
  // --min-core C: when the templated core fills less than this share of the
  // volume, the sizes are refined (see refine_thin_core); 0 turns it off.
  double min_core = 0.1;
  BisectionMethod partitioner = BisectionMethod::kMrob;       // --partitioner rob|rib|mrob: boundary leaves (P > 1)
  int optimize_passes = 3;     // --optimize N: quality optimization passes (0, or --no-optimize: none)
  double quality_target = 40;  // --quality-target X: degrees; tets with all dihedral angles in [X, 180-X] are left alone
  bool gap_vertices = true;   // --no-gap-vertices: no vertices at leaf centres in the gap (gap_vertices.hpp)
  bool offset_vertices = true;  // --no-offset-vertices: none offset inward from the surface (offset_vertices.hpp)
  bool delaunay_fill = true;  // --no-delaunay-fill: the face removals fill the whole gap (delaunay_fill.hpp)
  bool treeless = true;       // --no-treeless: stop after the tree-supported removals
  // --tree-removals-on-ranks: on P > 1 ranks the boundary leaves are
  // partitioned and every rank makes the tree-supported removals of its own
  // leaves in rounds (tree_removal_step.hpp); else rank 0 makes them alone
  // and the tree and core are gathered on rank 0 only.
  bool tree_removals_on_ranks = false;
  // --treeless-on-ranks: on P > 1 ranks the tree-less removals run on every
  // rank in rounds before rank 0 finishes (treeless_step.hpp); else rank 0
  // makes them alone. They start from every rank's copy of the front, so
  // the tree-supported removals run on the ranks too.
  bool treeless_on_ranks = false;

  // Whether the face removals run on the ranks (either option above).
  bool removals_on_ranks() const { return tree_removals_on_ranks || treeless_on_ranks; }
  bool keep_partial = false;  // --keep-partial: on exit 3, write the tets made and the front left
  bool ascii = false;     // --ascii: text Gmsh output
  bool quiet = false;     // --quiet: errors only
  bool verbose = false;   // --verbose: every rank speaks
};

}  // namespace partet
