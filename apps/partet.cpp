// partet command line: `partet INPUT -o OUTPUT [options]` meshes a closed
// surface; `partet check MESH [--surface S] [--json]` validates a mesh.
// Runs as one rank without a launcher, or under `mpirun -np N`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstring>
#include <string>

#include "check/check_command.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "parallel/comm.hpp"
#include "pipeline/mesh_command.hpp"

namespace {

const char* kFooter =
    "Surfaces: .stl (ASCII, binary) .off .obj .ply (ASCII, binary) .mesh (Medit) .msh (Gmsh 4.1)\n"
    "Volume meshes: .mesh .msh (binary unless --ascii) .vtu, and .pvtu (one .vtu piece per rank)\n"
    "Exit codes: 0 done, 2 bad input, 3 meshing could not finish, 4 internal error.\n"
    "Run on N ranks with: mpirun -np N partet INPUT -o OUTPUT";

// Parses the command line; -1 to go on, else the exit code (0 after --help
// or --version, 2 for a bad command line; only rank 0 prints).
int parse(CLI::App& app, int argc, char** argv, const partet::Comm& comm) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = comm.rank() == 0 ? app.exit(e) : e.get_exit_code();
    return code == 0 ? 0 : partet::kExitInput;
  }
  return -1;
}

int mesh_main(int argc, char** argv, const partet::Comm& comm) {
  partet::MeshOptions o;
  CLI::App app{"partet: parallel tetrahedral mesh generator (octree, templates, advancing front)", "partet"};
  app.set_version_flag("--version", std::string("partet ") + PARTET_VERSION);
  app.footer(std::string(kFooter) + "\nValidate a mesh with: partet check MESH [--surface SURFACE] [--json]");
  app.add_option("input", o.input, "Closed triangulated surface to mesh")->required();
  app.add_option("-o,--output", o.output, "Volume mesh to write; the format follows the extension")->required();
  app.add_option("--report", o.report, "Write a JSON report of the run (steps, times per rank, counts, memory)");
  app.add_option("--max-size", o.max_size, "No target edge length above H anywhere")->type_name("H");
  app.add_option("--size-factor", o.size_factor, "Scale every target edge length by F (below 1: finer)")
      ->type_name("F")->capture_default_str();
  app.add_option("--max-level", o.max_level, "Deepest octree level (guards the finest octants), 1 to 20")
      ->type_name("L")->capture_default_str();
  app.add_option("--too-close", o.too_close,
                 "Gap kept between the surface and the templated core, in target sizes")
      ->type_name("T")->capture_default_str();
  app.add_option("--grading", o.grading,
                 "How slowly the octree's sizes grow away from the surface: around an octant split finer, its "
                 "size holds for R octants before a coarser one (1: the plain 2:1 balance, the fewest tets; "
                 "larger: fewer size transitions, better tets, more of them), 1 to 4")
      ->type_name("R")->capture_default_str();
  app.add_option("--min-core", o.min_core,
                 "When the templated core fills less than this share of the volume (thin or coarsely "
                 "triangulated bodies), every target size is scaled by 0.7, at most twice, until it fills "
                 "more; 0 turns this off")
      ->type_name("C")->capture_default_str();
  std::string partitioner = "mrob";
  app.add_option("--partitioner", partitioner,
                 "How the boundary octants are split between ranks (with --tree-removals-on-ranks): recursive "
                 "bisection along the coordinate axes in turn (rob), the axis of inertia (rib), or the "
                 "coordinate axis closest to it (mrob)")
      ->check(CLI::IsMember({"rob", "rib", "mrob"}))->type_name("METHOD")->capture_default_str();
  std::string stop;
  app.add_option("--stop-after", stop,
                 "Stop after a step, writing what it has: surface (diagnosis only, writes nothing), "
                 "templates (writes the templated core to OUTPUT)")
      ->check(CLI::IsMember({"surface", "templates"}))->type_name("STEP");
  app.add_option("--front-out", o.front_out, "Write the initial front (surface + core faces) as a surface file")
      ->type_name("FILE");
  bool no_gap_vertices = false;
  app.add_flag("--no-gap-vertices", no_gap_vertices,
               "Give the face removals no vertices at the centres of the leaves between the surface and the "
               "templated core (faster on thin CAD walls, worse tets elsewhere)");
  bool no_offset_vertices = false;
  app.add_flag("--no-offset-vertices", no_offset_vertices,
               "Place no vertices inward from the surface vertices along their normals where the gap has room "
               "(they lift the first layer of tets, most on thin CAD walls)");
  bool no_delaunay_fill = false;
  app.add_flag("--no-delaunay-fill", no_delaunay_fill,
               "Do not fill the volume with a Delaunay tetrahedralization of the front's vertices before the face "
               "removals: they then mesh the whole gap between the surface and the templated core");
  bool no_treeless = false;
  app.add_flag("--no-treeless", no_treeless,
               "Skip the tree-less face removals (new vertices, tet deletion): what the tree-supported removals "
               "leave is reported as an unfinished front (exit 3); for diagnosis");
  app.add_flag("--tree-removals-on-ranks", o.tree_removals_on_ranks,
               "On several ranks, partition the boundary octants and make the tree-supported face removals on "
               "every rank, each on its own leaves, in rounds over the interfaces (the paper's steps 3-9); by "
               "default rank 0 makes them alone after the Delaunay fill, which measured faster on 2 ranks");
  app.add_flag("--treeless-on-ranks", o.treeless_on_ranks,
               "On several ranks, run the tree-less face removals on every rank in rounds before rank 0 "
               "finishes (the paper's step 10; implies --tree-removals-on-ranks); by default rank 0 makes "
               "them alone, which measured faster on 2 ranks");
  app.add_flag("--keep-partial", o.keep_partial,
               "When meshing cannot finish (exit 3), write the tets made to OUTPUT and the front left to "
               "OUTPUT's stem + .front.off");
  app.add_option("--optimize", o.optimize_passes,
                 "Quality optimization passes on the finished mesh (flips, edge removal, vertex insertion "
                 "but in the last of several, smoothing; the surface is never changed); 0 for none")
      ->type_name("N")->check(CLI::NonNegativeNumber)->capture_default_str();
  bool no_optimize = false;
  app.add_flag("--no-optimize", no_optimize, "Skip quality optimization (same as --optimize 0)");
  app.add_option("--quality-target", o.quality_target,
                 "Optimization target, in degrees: tets whose dihedral angles all lie in [X, 180 - X] are left "
                 "alone (0 to 90)")
      ->type_name("X")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  app.add_flag("--ascii", o.ascii, "Write Gmsh .msh as text instead of binary");
  app.add_flag("-q,--quiet", o.quiet, "Print errors only");
  app.add_flag("-v,--verbose", o.verbose, "Every rank prints its progress, not only rank 0");
  if (int code = parse(app, argc, argv, comm); code >= 0) return code;
  if (no_optimize) o.optimize_passes = 0;
  o.treeless = !no_treeless;
  o.gap_vertices = !no_gap_vertices;
  o.offset_vertices = !no_offset_vertices;
  o.delaunay_fill = !no_delaunay_fill;
  if (partitioner == "rob") o.partitioner = partet::BisectionMethod::kRob;
  if (partitioner == "rib") o.partitioner = partet::BisectionMethod::kRib;
  if (stop == "surface") o.stop_after = partet::StopAfter::kSurface;
  if (stop == "templates") o.stop_after = partet::StopAfter::kTemplates;
  partet::Log log(comm.rank(), o.quiet, o.verbose);
  return partet::run_mesh(o, comm, log);
}

int check_main(int argc, char** argv, const partet::Comm& comm) {
  partet::CheckOptions o;
  CLI::App app{"partet check: validate a tetrahedral mesh and measure its quality", "partet check"};
  app.footer(
      "Valid: every tet positively oriented (exact), every face shared by at most two tets lying on opposite\n"
      "sides; with --surface, the boundary faces are exactly the surface's triangles and the volume matches.\n"
      "Reads .mesh .msh .vtu .pvtu. Exit codes: 0 valid, 1 invalid, 2 unreadable.");
  app.add_option("mesh", o.mesh, "Volume mesh to check")->required();
  app.add_option("--surface", o.surface, "Surface the mesh must be bounded by exactly");
  app.add_flag("--json", o.json, "Print the result as JSON");
  if (int code = parse(app, argc, argv, comm); code >= 0) return code;
  if (comm.rank() != 0) return 0;
  return partet::run_check(o);
}

}  // namespace

int main(int argc, char** argv) {
  partet::MpiSession mpi(&argc, &argv);
  partet::Comm comm = partet::Comm::world();
  try {
    if (argc > 1 && std::strcmp(argv[1], "check") == 0) return check_main(argc - 1, argv + 1, comm);
    return mesh_main(argc, argv, comm);
  } catch (const partet::Error& e) {
    // Errors from collective steps are the same on every rank: rank 0 tells.
    if (comm.rank() == 0) std::fprintf(stderr, "partet: error: %s\n", e.what());
    return e.exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "partet: internal error on rank %d: %s\n", comm.rank(), e.what());
    if (comm.size() > 1) comm.abort(partet::kExitInternal);
    return partet::kExitInternal;
  }
}
