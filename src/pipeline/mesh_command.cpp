// run_mesh: read and diagnose the surface, then the meshing steps. Volume
// meshing is not in this version yet: after the diagnosis the run says so and
// exits 3 (meshing could not finish), writing nothing but the report.
#include "pipeline/mesh_command.hpp"

#include "core/error.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_file.hpp"
#include "parallel/collective_step.hpp"
#include "pipeline/report.hpp"
#include "surface/diagnose.hpp"

namespace partet {

namespace {

ojson options_json(const MeshOptions& o) {
  ojson j;
  j["input"] = o.input;
  j["output"] = o.output;
  j["ascii"] = o.ascii;
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

}  // namespace

int run_mesh(const MeshOptions& options, const Comm& comm, const Log& log) {
  RunReport report(comm, log);
  report.set("input", options.input);
  report.set("options", options_json(options));
  int code = kExitOk;
  std::string message;
  try {
    SurfaceMesh surface;
    SurfaceSummary summary;
    report.run_step("check options", [&] {
      require_extension(options.output, volume_extensions(), "output");
      require_extension(options.input, surface_extensions(), "input surface");
      return ojson::object();
    });
    report.run_step("read surface", [&] {
      if (comm.rank() != 0) return ojson::object();
      surface = read_surface_file(options.input);
      ojson c;
      c["triangles"] = surface.num_triangles();
      c["vertices"] = surface.num_vertices();
      return c;
    });
    report.run_step("diagnose surface", [&] {
      if (comm.rank() != 0) return ojson::object();
      summary = diagnose_surface(surface, options.input, [&](double f) { log.progress("diagnose surface", f); });
      for (const auto& note : summary.notes) log.note(file_basename(options.input) + ": " + note);
      ojson c;
      c["shells"] = summary.shells;
      c["cavities"] = summary.cavities;
      c["reoriented"] = summary.reoriented;
      c["volume"] = summary.volume;
      return c;
    });
    if (comm.rank() == 0) report.set("surface", summary_json(summary));
    throw MeshingError(options.input + ": the surface is valid (" + std::to_string(summary.triangles) +
                       " triangles, " + std::to_string(summary.shells) +
                       " shells), but volume meshing is not available in this version yet; nothing was written");
  } catch (const Error& e) {
    code = e.exit_code();
    message = e.what();
  }
  report.finish(code, message);
  if (!options.report.empty()) collective_step(comm, [&] { report.write(options.report); });
  if (code != kExitOk) throw Error(code, message);
  return code;
}

}  // namespace partet
