// The run report's options and surface records (see run_json.hpp).
#include "pipeline/run_json.hpp"

#include "pipeline/partition_step.hpp"

namespace partet {

namespace {

const char* stop_name(StopAfter s) {
  switch (s) {
    case StopAfter::kSurface: return "surface";
    case StopAfter::kTemplates: return "templates";
    case StopAfter::kNone: break;
  }
  return "none";
}

}  // namespace

ojson options_json(const MeshOptions& o) {
  ojson j;
  j["input"] = o.input;
  j["output"] = o.output;
  j["stop_after"] = stop_name(o.stop_after);
  j["max_size"] = o.max_size;
  j["size_factor"] = o.size_factor;
  j["max_level"] = o.max_level;
  j["too_close"] = o.too_close;
  j["grading"] = o.grading;
  j["min_core"] = o.min_core;
  j["partitioner"] = bisection_name(o.partitioner);
  j["gap_vertices"] = o.gap_vertices;
  j["offset_vertices"] = o.offset_vertices;
  j["delaunay_fill"] = o.delaunay_fill;
  j["treeless"] = o.treeless;
  j["tree_removals_on_ranks"] = o.tree_removals_on_ranks;
  j["treeless_on_ranks"] = o.treeless_on_ranks;
  j["optimize"] = o.optimize_passes;
  j["quality_target"] = o.quality_target;
  j["ascii"] = o.ascii;
  if (!o.front_out.empty()) j["front_out"] = o.front_out;
  return j;
}

ojson summary_json(const SurfaceSummary& s) {
  ojson j;
  j["triangles"] = s.triangles;
  j["vertices"] = s.vertices;
  j["shells"] = s.shells;
  j["cavities"] = s.cavities;
  j["reoriented"] = s.reoriented;
  j["volume"] = s.volume;
  j["unused_vertices"] = s.unused_vertices;
  j["self_intersection_check_s"] = s.seconds_self_intersections;
  return j;
}

}  // namespace partet
