// mesh_once: the pipeline of DESIGN.md, one report step per stage: read and
// diagnose the surface, build the octree (sizes, points, triangles, 2:1
// balance), classify leaves, make the interior set manifold (demoting
// leaves to too close), template the interior, on P > 1 ranks gather the
// tree and core on rank 0 (with the removals on the ranks: partition the
// boundary leaves and gather them on every rank), make the initial front.
// Then tree-supported face removals (rank 0's; on the ranks, each rank
// removes the faces of its own leaves and rank 0 finishes:
// tree_removal_step.hpp) and, for the faces they leave, face removals with
// new vertices (rank 0); a front left after those exits 3 (naming where);
// --stop-after templates writes the templated core and exits 0. Then
// quality optimization, on the ranks' parts when P > 1 (optimize_step.hpp),
// its alternatives on small meshes, and restarts on the band around the
// worst tet (restarts_step.hpp).
#include "pipeline/mesh_attempt.hpp"

#include <algorithm>
#include <cstring>
#include <memory>

#include "check/quality.hpp"
#include "core/compact_mesh.hpp"
#include "core/error.hpp"
#include "core/point_text.hpp"
#include "front/delaunay_fill.hpp"
#include "front/face_removal.hpp"
#include "front/front.hpp"
#include "front/gap_vertices.hpp"
#include "front/offset_vertices.hpp"
#include "octree/triangle_bins.hpp"
#include "front/initial_front.hpp"
#include "io/file_bytes.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/distributed_build.hpp"
#include "octree/distributed_classify.hpp"
#include "octree/ghost_layer.hpp"
#include "octree/sizing.hpp"
#include "optimize/optimize.hpp"
#include "parallel/collective_step.hpp"
#include "parallel/vertex_links.hpp"
#include "parallel/write_parts.hpp"
#include "pipeline/cone_alternative.hpp"
#include "pipeline/fill_step.hpp"
#include "pipeline/run_json.hpp"
#include "pipeline/optimize_step.hpp"
#include "pipeline/pass_alternatives.hpp"
#include "pipeline/partition_step.hpp"
#include "pipeline/restarts_step.hpp"
#include "pipeline/tree_removal_step.hpp"
#include "pipeline/treeless_step.hpp"
#include "pipeline/report.hpp"
#include "surface/diagnose.hpp"
#include "templates/gather_core.hpp"
#include "templates/manifold_core.hpp"
#include "templates/template_mesh.hpp"

namespace partet {

namespace {

// Everything one rank holds between steps.
struct MeshState {
  SurfaceMesh surface;
  SurfaceSummary summary;
  RootCube root;
  VertexSizing sizing;
  LinearOctree tree;
  TemplateCore core;
  // On P > 1 ranks the tree is built, classified and templated distributed:
  // this rank's leaves, its local view (own leaves and ghost layers) and its
  // part of the core; `tree` and `core` are then gathered on rank 0, or on
  // every rank for the face removals, when later steps need them (`whole`:
  // this rank holds them).
  DistributedOctree own;
  LinearOctree view;
  TemplateCore part;
  VertexLinks links;  // copies of this rank's template vertices on other ranks
  BoundaryPartition boundary;  // this rank's boundary leaves and front after step 3
  bool whole = false;
  bool thin_core_refined = false;  // refine_thin_core changed the sizes
  // The triangles binned into the tree's leaves by the last
  // classification, for the offset gap vertices (the leaves do not change
  // after it): on one rank the whole tree's; on P ranks each rank's own
  // leaves', then the whole tree's where it is gathered; freed with the
  // initial front.
  LeafTriangles bins;
  InitialFront initial_front;
  TetMesh mesh;  // core, then the tets of face removals (front vertex numbering)
};

// The surface triangles in the numbering of the front (and so of the mesh):
// surface vertex v is front vertex core_vertices + v.
std::vector<uint32_t> boundary_triangles(const MeshState& s) {
  std::vector<uint32_t> tris(s.surface.tris);
  for (uint32_t& v : tris) v += static_cast<uint32_t>(s.initial_front.core_vertices);
  return tris;
}

// Frees everything but the mesh and the surface summary.
void release_build_state(MeshState& s) {
  s.surface = SurfaceMesh{};
  s.sizing = VertexSizing{};
  s.tree = LinearOctree{};
  s.core = TemplateCore{};
  s.own = DistributedOctree{};
  s.view = LinearOctree{};
  s.part = TemplateCore{};
  s.links = VertexLinks{};
  s.boundary = BoundaryPartition{};
  s.initial_front = InitialFront{};
}

// The alive faces of `front` as a surface (vertices compacted).
SurfaceMesh front_left(const Front& front) {
  SurfaceMesh left;
  std::vector<uint32_t> index(front.num_vertices(), UINT32_MAX);
  for (uint32_t f = 0; f < front.num_face_slots(); ++f) {
    if (!front.alive(f)) continue;
    for (int k = 0; k < 3; ++k) {
      uint32_t v = front.face(f)[k];
      if (index[v] == UINT32_MAX) {
        index[v] = static_cast<uint32_t>(left.num_vertices());
        left.xyz.insert(left.xyz.end(), front.point(v), front.point(v) + 3);
      }
      left.tris.push_back(index[v]);
    }
  }
  return left;
}

// "12 front faces remain, near (x, y, z), (x, y, z), ..."
std::string where_left(const SurfaceMesh& left) {
  std::string text = std::to_string(left.num_triangles()) + " front faces remain, near";
  for (size_t t = 0; t < left.num_triangles() && t < 5; ++t) {
    double c[3];
    for (int i = 0; i < 3; ++i)
      c[i] = (left.xyz[3 * left.tris[3 * t] + i] + left.xyz[3 * left.tris[3 * t + 1] + i] +
              left.xyz[3 * left.tris[3 * t + 2] + i]) / 3.0;
    text += (t == 0 ? " " : ", ") + point_text(c);
  }
  if (left.num_triangles() > 5) text += ", ...";
  return text;
}

// OUTPUT's stem + ".front.off": where --keep-partial puts the front left.
std::string partial_front_path(const std::string& output) {
  size_t dot = output.find_last_of('.');
  size_t slash = output.find_last_of('/');
  std::string stem = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? output
                                                                                            : output.substr(0, dot);
  return stem + ".front.off";
}

void check_options(const MeshOptions& o) {
  require_extension(o.input, surface_extensions(), "input surface");
  require_extension(o.output, volume_extensions(), "output");
  if (!o.front_out.empty()) require_extension(o.front_out, surface_extensions(), "front output");
  if (!(o.max_size > 0)) throw InputError("--max-size must be positive (got " + std::to_string(o.max_size) + ")");
  if (!(o.size_factor > 0))
    throw InputError("--size-factor must be positive (got " + std::to_string(o.size_factor) + ")");
  if (o.max_level < 1 || o.max_level > kMaxLevel)
    throw InputError("--max-level must be between 1 and " + std::to_string(kMaxLevel) + " (got " +
                     std::to_string(o.max_level) + ")");
  if (!(o.too_close >= 0)) throw InputError("--too-close must be zero or positive");
  if (o.grading < 1 || o.grading > kMaxGrading)
    throw InputError("--grading must be between 1 and " + std::to_string(kMaxGrading) + " (got " +
                     std::to_string(o.grading) + ")");
  if (!(o.min_core >= 0 && o.min_core <= 1)) throw InputError("--min-core must be between 0 and 1");
}

// The root cube and the level of every surface vertex (same on every rank).
void size_surface(MeshState& s, const MeshOptions& o) {
  s.root = make_root_cube(s.summary.bbox);
  SizingOptions sizing;
  sizing.max_size = o.max_size;
  sizing.size_factor = o.size_factor;
  sizing.max_level = o.max_level;
  s.sizing = size_vertices(s.surface, s.root, sizing);
}

ojson build_tree(MeshState& s, const MeshOptions& o) {
  size_surface(s, o);
  s.tree = build_octree(s.sizing.grid, s.sizing.level);
  refine_for_triangles(s.tree, s.surface, s.root, s.sizing.level);
  balance_octree(s.tree, o.grading);
  int deepest = 0;
  for (uint8_t l : s.tree.level) deepest = std::max<int>(deepest, l);
  ojson c;
  c["leaves"] = s.tree.size();
  c["deepest level"] = deepest;
  c["root edge"] = s.root.edge();
  return c;
}

// No dihedral angle measured (above any angle).
constexpr double kNoAngle = 1e300;

// Rank 0's diagnosed surface and its bounding box, on every rank.
void share_surface(const Comm& comm, MeshState& s) {
  std::string bytes;
  if (comm.rank() == 0) {
    const uint64_t sizes[2] = {s.surface.xyz.size(), s.surface.tris.size()};
    bytes.append(reinterpret_cast<const char*>(sizes), sizeof sizes);
    bytes.append(reinterpret_cast<const char*>(s.summary.bbox), sizeof s.summary.bbox);
    bytes.append(reinterpret_cast<const char*>(s.surface.xyz.data()), sizes[0] * sizeof(double));
    bytes.append(reinterpret_cast<const char*>(s.surface.tris.data()), sizes[1] * sizeof(uint32_t));
  }
  comm.broadcast(bytes, 0);
  if (comm.rank() == 0) return;
  uint64_t sizes[2];
  PARTET_ASSERT(bytes.size() >= sizeof sizes + sizeof s.summary.bbox, "truncated surface broadcast");
  std::memcpy(sizes, bytes.data(), sizeof sizes);
  PARTET_ASSERT(bytes.size() == sizeof sizes + sizeof s.summary.bbox + sizes[0] * sizeof(double) +
                                    sizes[1] * sizeof(uint32_t),
                "truncated surface broadcast");
  const char* at = bytes.data() + sizeof sizes;
  std::memcpy(s.summary.bbox, at, sizeof s.summary.bbox);
  at += sizeof s.summary.bbox;
  s.surface.xyz.resize(sizes[0]);
  s.surface.tris.resize(sizes[1]);
  std::memcpy(s.surface.xyz.data(), at, sizes[0] * sizeof(double));
  std::memcpy(s.surface.tris.data(), at + sizes[0] * sizeof(double), sizes[1] * sizeof(uint32_t));
}

// build_tree on P > 1 ranks: every rank sizes the whole surface and passes
// its slice of the vertices to the distributed build.
ojson build_tree_distributed(MeshState& s, const MeshOptions& o, const Comm& comm) {
  share_surface(comm, s);
  size_surface(s, o);
  const size_t n = s.sizing.level.size(), p = static_cast<size_t>(comm.size());
  const size_t r = static_cast<size_t>(comm.rank()), begin = n * r / p, end = n * (r + 1) / p;
  const std::vector<uint32_t> grid(s.sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * begin),
                                   s.sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * end));
  const std::vector<uint8_t> level(s.sizing.level.begin() + static_cast<std::ptrdiff_t>(begin),
                                   s.sizing.level.begin() + static_cast<std::ptrdiff_t>(end));
  TreeBuildCounts n_build;
  s.own = build_distributed_octree(comm, grid, level, &n_build);
  refine_distributed_for_triangles(s.own, comm.rank(), s.surface, s.root, s.sizing.level);
  balance_distributed_octree(comm, s.own, o.grading);
  int64_t deepest = 0;
  for (uint8_t l : s.own.leaves.level) deepest = std::max<int64_t>(deepest, l);
  const int64_t leaves = static_cast<int64_t>(s.own.leaves.size());
  ojson c;
  c["leaves"] = comm.sum(leaves);
  c["leaves per rank"] = comm.all_gather(leaves);
  c["deepest level"] = comm.max(deepest);
  c["root edge"] = s.root.edge();
  c["rank-set halvings"] = n_build.depths;
  c["coarse passes"] = n_build.coarse_passes;
  return c;
}

ojson classify(MeshState& s, const MeshOptions& o, const Comm& comm) {
  ClassifyOptions options;
  options.too_close = o.too_close;
  if (comm.size() == 1) s.bins = bin_triangles(s.tree, s.surface, s.root);
  ClassCounts n = comm.size() > 1
                      ? classify_distributed(comm, s.own, s.surface, s.root, s.sizing.size, options, &s.bins)
                      : classify_leaves(s.tree, s.surface, s.root, s.sizing.size, s.bins, options);
  ojson c;
  c["boundary"] = n.boundary;
  c["too close"] = n.too_close;
  c["interior"] = n.interior;
  c["outside"] = n.outside;
  return c;
}

// The share of the volume inside the surface that the interior leaves
// fill (before the manifold repair demotes a few), over all ranks.
double core_fraction(const MeshState& s, const Comm& comm) {
  const LinearOctree& tree = comm.size() > 1 ? s.own.leaves : s.tree;
  double inside = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    if (tree.cls[i] != LeafClass::kInterior) continue;
    const double h = octant_edge(tree.level[i]) * s.root.unit;
    inside += h * h * h;
  }
  inside = comm.sum(inside);
  const double volume = comm.max(comm.rank() == 0 ? s.summary.volume : 0.0);
  return volume > 0 ? inside / volume : 1;
}

// Each attempt of refine_thin_core scales the sizes by this factor.
constexpr double kThinCoreScale = 0.7;
constexpr int kThinCoreAttempts = 2;

// When the core fills less than o.min_core of the volume, the front fills
// the rest from the surface vertices alone: on a thin or coarsely
// triangulated body (no leaf far enough from the surface) it makes long
// tets across the body that the optimizer cannot mend. The tree is then
// built and classified again with every target size scaled by
// kThinCoreScale, up to kThinCoreAttempts times, stopping at the first
// attempt whose core reaches o.min_core; the attempt with the largest core
// is kept (the coarsest among equals), so a body whose core stays empty
// (CAD parts whose sizes come from slivers) keeps its first tree.
ojson refine_thin_core(MeshState& s, const MeshOptions& o, const Comm& comm) {
  const bool distributed = comm.size() > 1;
  double best = core_fraction(s, comm), factor = o.size_factor, best_factor = factor;
  ojson c;
  c["core fraction before"] = best;
  struct Tree {
    VertexSizing sizing;
    LinearOctree tree;
    DistributedOctree own;
    LeafTriangles bins;  // the classification's, of this tree
  } kept;
  bool current_is_best = true;
  for (int attempt = 0; attempt < kThinCoreAttempts && best < o.min_core; ++attempt) {
    if (current_is_best) kept = {std::move(s.sizing), std::move(s.tree), std::move(s.own), std::move(s.bins)};
    MeshOptions finer = o;
    factor *= kThinCoreScale;
    finer.size_factor = factor;
    if (distributed) {
      build_tree_distributed(s, finer, comm);
    } else {
      build_tree(s, finer);
    }
    classify(s, finer, comm);
    const double fraction = core_fraction(s, comm);
    current_is_best = fraction > best;
    if (current_is_best) {
      best = fraction;
      best_factor = factor;
    }
  }
  if (!current_is_best) {
    s.sizing = std::move(kept.sizing);
    s.tree = std::move(kept.tree);
    s.own = std::move(kept.own);
    s.bins = std::move(kept.bins);
  }
  s.thin_core_refined = best_factor != o.size_factor;
  c["core fraction"] = best;
  c["size factor"] = best_factor;
  return c;
}

// The optimizer's options from the command line's.
OptimizeOptions optimize_options(const MeshOptions& o) {
  OptimizeOptions out;
  out.passes = o.optimize_passes;
  out.quality_target_deg = o.quality_target;
  return out;
}

}  // namespace

int mesh_once(const MeshOptions& options, const Comm& comm, const Log& log, const MeshAttempt& attempt) {
  RunReport report(comm, log);
  report.set("input", options.input);
  report.set("options", options_json(options));
  if (attempt.report_key) report.set(attempt.report_key, true);
  int code = kExitOk;
  std::string message;
  MeshState s;
  // On P > 1 ranks the octree, the templates, the tree-supported face
  // removals and the optimizer are distributed; the tree-less removals run
  // on rank 0 (the others take part in every step for agreement and
  // timings, and write empty pieces).
  const bool root_rank = comm.rank() == 0;
  const bool distributed = comm.size() > 1;
  // Whether rank 0 needs the whole tree and core after templating.
  const bool gather = options.stop_after != StopAfter::kTemplates || !options.front_out.empty();
  try {
    report.run_step("check options", [&] {
      check_options(options);
      return ojson::object();
    });
    report.run_step("read surface", [&] {
      if (!root_rank) return ojson::object();
      s.surface = read_surface_file(options.input);
      ojson c;
      c["triangles"] = s.surface.num_triangles();
      c["vertices"] = s.surface.num_vertices();
      return c;
    });
    report.run_step("diagnose surface", [&] {
      if (!root_rank) return ojson::object();
      s.summary = diagnose_surface(s.surface, options.input, [&](double f) { log.progress("diagnose surface", f); });
      for (const auto& note : s.summary.notes) log.note(file_basename(options.input) + ": " + note);
      ojson c;
      c["shells"] = s.summary.shells;
      c["cavities"] = s.summary.cavities;
      c["reoriented"] = s.summary.reoriented;
      c["volume"] = s.summary.volume;
      return c;
    });
    if (root_rank) report.set("surface", summary_json(s.summary));
    if (options.stop_after == StopAfter::kSurface) {
      report.finish(code, message);
      if (!options.report.empty()) collective_step(comm, [&] { report.write(options.report); });
      return kExitOk;
    }
    report.run_step("build octree", [&] {
      if (distributed) return build_tree_distributed(s, options, comm);
      return root_rank ? build_tree(s, options) : ojson::object();
    });
    report.run_step("classify leaves", [&] {
      return distributed || root_rank ? classify(s, options, comm) : ojson::object();
    });
    if (options.min_core > 0) {
      report.run_step("refine thin core", [&] {
        return distributed || root_rank ? refine_thin_core(s, options, comm) : ojson::object();
      });
    }
    report.run_step("manifold core", [&] {
      if (!distributed && !root_rank) return ojson::object();
      GhostCounts ghosts;
      if (distributed) s.view = ghost_view(comm, s.own, &ghosts);
      ManifoldCoreCounts n = distributed ? make_core_manifold(comm, s.view) : make_core_manifold(s.tree);
      ojson c;
      if (distributed) c["ghost leaves"] = comm.sum(static_cast<int64_t>(ghosts.layer1 + ghosts.layer2));
      c["demoted"] = n.demoted;
      c["repairs"] = n.repaired;
      c["rounds"] = n.rounds;
      c["interior"] = n.interior;
      return c;
    });
    report.run_step("template interior", [&] {
      if (distributed) {
        s.part = template_interior(s.view, s.root, comm.rank());
        const int64_t tets = static_cast<int64_t>(s.part.mesh.num_tets());
        ojson c;
        c["tets"] = comm.sum(tets);
        c["tets per rank"] = comm.all_gather(tets);
        c["leaves"] = comm.sum(static_cast<int64_t>(s.part.leaves_templated));
        s.links = link_shared_vertices(comm, s.part.mesh.global_ids);
        c["shared vertices per rank"] = comm.all_gather(static_cast<int64_t>(s.links.num_shared()));
        return c;
      }
      if (!root_rank) return ojson::object();
      s.core = template_interior(s.tree, s.root);
      s.whole = true;
      ojson c;
      c["tets"] = s.core.mesh.num_tets();
      c["vertices"] = s.core.mesh.num_vertices();
      c["leaves"] = s.core.leaves_templated;
      return c;
    });
    // The boundary partition is for the removals on the ranks; when rank 0
    // makes them, the tree and core are gathered on it alone.
    const bool on_ranks = options.stop_after == StopAfter::kNone && !attempt.removals_on_root;
    if (distributed && on_ranks) {
      report.run_step("partition boundary", [&] {
        return partition_boundary_step(comm, s.view, s.part, s.root, s.surface, options.partitioner, s.boundary);
      });
    }
    if (distributed && gather) {
      // With the removals on the ranks every rank works on a copy of the
      // whole front (the tree-less ones on the ranks take rank 0's state,
      // which needs the tree and the initial front, in every attempt); else
      // (and for the templates' front alone, --front-out) rank 0 needs them.
      const bool everywhere = options.stop_after == StopAfter::kNone && (on_ranks || options.treeless_on_ranks);
      report.run_step(everywhere ? "gather tree and core" : "gather on rank 0", [&] {
        gather_tree_and_core(comm, s.view, s.part, s.tree, s.core, everywhere, &s.bins);
        s.whole = root_rank || everywhere;
        ojson c;
        if (root_rank) c["vertices"] = s.core.mesh.num_vertices();
        return c;
      });
    }
    report.run_step("core quality", [&] {
      // Each rank measures its part (the whole core on one rank).
      const TetMesh& core = distributed ? s.part.mesh : s.core.mesh;
      double extremes[2] = {kNoAngle, kNoAngle};  // smallest dihedral, minus the largest
      if (core.num_tets() > 0) {
        const QualityStats q = measure_quality(core);
        extremes[0] = q.min_dihedral_deg;
        extremes[1] = -q.max_dihedral_deg;
      }
      comm.min(extremes, 2);
      if (extremes[0] == kNoAngle) return ojson::object();
      ojson c;
      c["min dihedral"] = extremes[0];
      c["max dihedral"] = -extremes[1];
      return c;
    });
    report.run_step("initial front", [&] {
      if (!s.whole) return ojson::object();
      s.initial_front = make_initial_front(s.tree, s.root, s.core, s.surface);
      size_t offset = 0;
      if (options.gap_vertices) {
        GapVertices gap = gap_vertices(s.tree, s.root, s.surface, s.sizing.size, options.too_close);
        if (options.offset_vertices)
          offset = add_offset_vertices(s.tree, s.root, s.surface, s.sizing.size, options.too_close, s.initial_front,
                                       gap, s.bins.first.size() == s.tree.size() + 1 ? &s.bins : nullptr);
        add_free_vertices(s.initial_front, s.tree, gap.xyz, gap.global_ids, gap.leaf);
      }
      s.bins = LeafTriangles{};
      const InitialFront& front = s.initial_front;
      if (!root_rank) return ojson::object();
      if (!options.front_out.empty()) write_surface_file(front_surface(front), options.front_out, {options.ascii});
      ojson c;
      c["faces"] = front.num_faces();
      c["surface faces"] = front.surface_faces;
      c["core faces"] = front.num_faces() - front.surface_faces;
      c["gap vertices"] = front.free_vertices;
      c["offset vertices"] = offset;
      return c;
    });
    // The same on every rank: each holds the surface (share_surface).
    const bool filled = attempt.fill && options.delaunay_fill && options.stop_after != StopAfter::kTemplates &&
                        s.surface.num_triangles() > kDelaunayFillTriangles;
    if (filled) {
      report.run_step("delaunay fill", [&] {
        // With the removals on rank 0 the other ranks' fronts go unused.
        const bool used = s.whole && (root_rank || !attempt.removals_on_root);
        return used ? fill_step(s.initial_front, s.tree, s.core.mesh) : ojson::object();
      });
    }
    if (options.stop_after == StopAfter::kTemplates) {
      report.run_step("write core", [&] {
        const TetMesh& core = distributed ? s.part.mesh : s.core.mesh;
        write_distributed_mesh(core, options.output, {options.ascii}, comm);
        ojson c;
        c["tets"] = comm.sum(static_cast<int64_t>(core.num_tets()));
        c["file"] = options.output;
        return c;
      });
    } else {
      SurfaceMesh left;
      std::unique_ptr<Front> front;
      RemovalMemo memo;
      std::string treeless_note;  // how the tree-less removals ended, when they left faces
      report.run_step("face removals (tree)", [&] {
        if (!s.whole) return ojson::object();
        s.mesh = std::move(s.core.mesh);
        const RankLeaves ranks{&s.boundary.front.leaves, &s.boundary.separators};
        return tree_removal_step(comm, s.initial_front, s.tree, s.root, s.mesh, ranks, front, memo,
                                 attempt.shape_order, attempt.removals_on_root);
      });
      if (options.treeless && comm.max(static_cast<int64_t>(front ? front->num_alive_faces() : 0)) > 0) {
        RemovalOptions treeless_options;
        if (attempt.once) {
          treeless_options.starts = 1;
          treeless_options.rerun_best = false;  // a failure here is discarded (FrontLeftOpen)
        }
        treeless_options.short_growth_first = attempt.short_growth;
        treeless_options.shape_order = attempt.shape_order;
        report.run_step("face removals (tree-less)", [&] {
          return treeless_step(comm, s.initial_front, s.tree, s.root, s.mesh, front, memo, treeless_note,
                               options.treeless_on_ranks, treeless_options);
        });
      }
      if (front) left = front_left(*front);
      int64_t faces_left = comm.max(static_cast<int64_t>(left.num_triangles()));
      if (faces_left > 0 && !attempt.last && (options.treeless || s.thin_core_refined))
        throw FrontLeftOpen{s.thin_core_refined, filled};
      if (faces_left > 0) {
        if (options.keep_partial) {
          report.run_step("write partial", [&] {
            s.mesh.global_ids = {};  // whole on rank 0: its own numbering is global
            write_distributed_mesh(s.mesh, options.output, {options.ascii}, comm);
            if (root_rank) write_surface_file(left, partial_front_path(options.output), {});
            ojson c;
            c["tets"] = s.mesh.num_tets();
            c["front"] = partial_front_path(options.output);
            return c;
          });
        }
        throw MeshingError(options.input + ": face removals could not close the front: " + where_left(left) + treeless_note +
                           (options.keep_partial ? "; the tets made and the front left were written"
                                                                    : "; nothing was written (--keep-partial writes "
                                                                      "the tets made and the front left)"));
      }
      if (root_rank) {
        s.mesh.tris = boundary_triangles(s);
        drop_unused_vertices(s.mesh);
      }
      // Only the mesh goes on: what built it is freed before the optimizer
      // and the writer allocate theirs. The mesh is whole on rank 0, so its
      // own numbering is global: the front's global ids go too.
      s.mesh.global_ids = {};
      front.reset();
      memo = RemovalMemo{};
      left = SurfaceMesh{};
      release_build_state(s);
      QualityStats optimized;  // the mesh after the optimizer (rank 0)
      const bool few_tets = options.optimize_passes > 0 &&
                            comm.max(static_cast<int64_t>(root_rank && s.mesh.num_tets() <= kPassAlternativeTets)) > 0;
      TetMesh front_mesh = few_tets && root_rank ? s.mesh : TetMesh{};
      if (options.optimize_passes > 0) {
        report.run_step("optimize", [&] { return optimize_step(comm, s.mesh, optimize_options(options), optimized); });
      }
      if (few_tets) run_pass_alternatives(report, root_rank, s.mesh, front_mesh, optimized, optimize_options(options));
      if (options.optimize_passes > 0 &&
          comm.max(static_cast<int64_t>(root_rank && s.mesh.num_triangles() <= kConeTriangles)) > 0) {
        report.run_step("cone alternative", [&] {
          if (!root_rank) return ojson::object();
          return try_cone_alternative(s.mesh, optimized, optimize_options(options));
        });
      }
      if (options.optimize_passes > 0)
        report.run_step("local restarts", [&] {
          return root_rank ? local_restarts(s.mesh, optimized, optimize_options(options)) : ojson::object();
        });
      report.run_step("write mesh", [&] {
        // On P > 1 ranks a .pvtu is written in balanced pieces, one per
        // rank, by rank 0, which holds the whole mesh.
        const bool pieces = distributed && file_extension(options.output) == "pvtu";
        ojson c;
        c["tets"] = s.mesh.num_tets();
        if (pieces) {
          c["tets per rank"] = write_whole_as_pieces(s.mesh, options.output, {options.ascii}, comm);
        } else {
          write_distributed_mesh(s.mesh, options.output, {options.ascii}, comm);
          c["vertices"] = s.mesh.num_vertices();
        }
        c["file"] = options.output;
        return c;
      });
    }
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
