// The run report's records of a meshing run's options and of the surface's
// diagnosis, as JSON.
#pragma once

#include "pipeline/options.hpp"
#include "pipeline/report.hpp"
#include "surface/diagnose.hpp"

namespace partet {

// Every meshing option, by its command-line name.
ojson options_json(const MeshOptions& o);

// The diagnosis's counts (triangles, vertices, shells, cavities,
// reoriented shells, volume, unused vertices, self-intersection check time).
ojson summary_json(const SurfaceSummary& s);

}  // namespace partet
