// Options of a meshing run, as given on the command line; one struct handed
// to the pipeline (no globals).
#pragma once

#include <string>

namespace partet {

struct MeshOptions {
  std::string input;    // surface file
  std::string output;   // volume mesh file (.mesh .msh .vtu .pvtu)
  std::string report;   // --report FILE.json, empty for none
  bool ascii = false;   // --ascii: text Gmsh output
  bool quiet = false;   // --quiet: errors only
  bool verbose = false; // --verbose: every rank speaks
};

}  // namespace partet
