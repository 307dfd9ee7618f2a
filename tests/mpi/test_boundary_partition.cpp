// The boundary partition (pipeline step 3) on 1, 2, 3, 4 and 8 ranks, from
// the distributed octree and templates: the front built on the ranks and
// then migrated is exactly the serial initial front (same global-id
// triples, each face once); every face sits on the rank holding its leaf,
// that leaf is a boundary or too-close leaf meeting the face, and the
// leaves are the serial ones, each on one rank; every vertex a face uses is
// on its rank with the serial global id and coordinates; every separator
// has the centres of the low ranks' leaves on its low side and the high
// ones on its high side; and MROB balances the front faces within 5 % on
// the data/ surfaces at 2 and 4 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "front/initial_front.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/distributed_build.hpp"
#include "octree/distributed_classify.hpp"
#include "octree/ghost_layer.hpp"
#include "octree/sizing.hpp"
#include "parallel/comm.hpp"
#include "partition/boundary_front.hpp"
#include "partition/boundary_partition.hpp"
#include "partition/front_part.hpp"
#include "surface/diagnose.hpp"
#include "templates/manifold_core.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

using Triple = std::array<uint64_t, 3>;

// The surface sized and the distributed pipeline run up to the templates,
// next to the serial pipeline's tree and initial front.
struct Prepared {
  std::string label;
  SurfaceMesh surface;
  RootCube root;
  LinearOctree view;      // this rank's local view
  TemplateCore part;      // this rank's core part
  LinearOctree tree;      // the serial tree (after the manifold pass)
  InitialFront initial;   // the serial initial front
};

Prepared prepare(const Comm& comm, const std::string& label, SurfaceMesh surface, double factor) {
  Prepared p;
  p.label = label + " x" + std::to_string(factor);
  const SurfaceSummary summary = diagnose_surface(surface, label);
  p.surface = std::move(surface);
  p.root = make_root_cube(summary.bbox);
  SizingOptions options;
  options.size_factor = factor;
  const VertexSizing sizing = size_vertices(p.surface, p.root, options);

  p.tree = build_octree(sizing.grid, sizing.level);
  refine_for_triangles(p.tree, p.surface, p.root, sizing.level);
  balance_octree(p.tree);
  classify_leaves(p.tree, p.surface, p.root, sizing.size);
  make_core_manifold(p.tree);
  p.initial = make_initial_front(p.tree, p.root, template_interior(p.tree, p.root), p.surface);

  const size_t n = sizing.level.size(), np = static_cast<size_t>(comm.size()), r = static_cast<size_t>(comm.rank());
  const size_t begin = n * r / np, end = n * (r + 1) / np;
  const std::vector<uint32_t> grid(sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * begin),
                                   sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * end));
  const std::vector<uint8_t> level(sizing.level.begin() + static_cast<std::ptrdiff_t>(begin),
                                   sizing.level.begin() + static_cast<std::ptrdiff_t>(end));
  DistributedOctree own = build_distributed_octree(comm, grid, level);
  refine_distributed_for_triangles(own, comm.rank(), p.surface, p.root, sizing.level);
  balance_distributed_octree(comm, own);
  classify_distributed(comm, own, p.surface, p.root, sizing.size);
  p.view = ghost_view(comm, own);
  make_core_manifold(comm, p.view);
  p.part = template_interior(p.view, p.root, comm.rank());
  return p;
}

// Every rank's bytes, concatenated in rank order, on every rank.
std::string all_bytes(const Comm& comm, const std::string& mine) {
  std::string all;
  for (const std::string& s : comm.gather(mine, 0)) all += s;
  comm.broadcast(all, 0);
  return all;
}

template <class T>
std::vector<T> all_values(const Comm& comm, const std::vector<T>& mine) {
  std::string bytes(mine.size() * sizeof(T), '\0');
  if (!mine.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
  const std::string all = all_bytes(comm, bytes);
  std::vector<T> out(all.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), all.data(), all.size());
  return out;
}

// The same oriented triangle whichever vertex comes first: smallest id first.
Triple rotated(Triple t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// Checks one part against the serial run: its leaves, the faces of each
// leaf and their vertices; the union of the parts' faces and leaves.
void check_part(const Comm& comm, const Prepared& p, const FrontPart& part, const std::string& what) {
  const std::string label = p.label + ": " + what;
  std::map<uint64_t, const double*> serial_xyz;
  for (size_t v = 0; v < p.initial.global_ids.size(); ++v) serial_xyz[p.initial.global_ids[v]] = &p.initial.xyz[3 * v];

  ASSERT_EQ(part.leaf_first_face.size(), part.leaves.size() + 1) << label;
  ASSERT_EQ(part.leaf_first_face.back(), part.num_faces()) << label;
  std::vector<Triple> faces;
  size_t wrong_vertices = 0, far_faces = 0, wrong_leaves = 0;
  for (size_t i = 0; i < part.leaves.size(); ++i) {
    EXPECT_EQ(part.leaves.owner[i], comm.rank()) << label;
    const size_t serial = static_cast<size_t>(
        std::lower_bound(p.tree.key.begin(), p.tree.key.end(), part.leaves.key[i]) - p.tree.key.begin());
    if (serial == p.tree.size() || p.tree.key[serial] != part.leaves.key[i] ||
        p.tree.level[serial] != part.leaves.level[i] || p.tree.cls[serial] != part.leaves.cls[i] ||
        !front_leaf_class(part.leaves.cls[i]))
      ++wrong_leaves;
    double lo[3], hi[3];
    uint32_t a[3];
    part.leaves.anchor(i, a[0], a[1], a[2]);
    octant_box(p.root, a[0], a[1], a[2], part.leaves.level[i], lo, hi);
    const double slack = 1e-9 * p.root.edge();
    for (uint32_t f = part.leaf_first_face[i]; f < part.leaf_first_face[i + 1]; ++f) {
      Triple ids;
      double centroid[3] = {0, 0, 0};
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t v = part.faces[3 * f + k];
        ASSERT_LT(v, part.num_vertices()) << label;
        ids[k] = part.global_ids[v];
        auto at = serial_xyz.find(ids[k]);
        if (at == serial_xyz.end() || !std::equal(at->second, at->second + 3, &part.xyz[3 * v])) ++wrong_vertices;
        for (int d = 0; d < 3; ++d) centroid[d] += part.xyz[3 * v + d] / 3;
      }
      // The face's leaf meets it: its centroid is in the closed leaf box.
      for (int d = 0; d < 3; ++d) far_faces += centroid[d] < lo[d] - slack || centroid[d] > hi[d] + slack;
      faces.push_back(rotated(ids));
    }
  }
  EXPECT_EQ(wrong_leaves, 0u) << label;
  EXPECT_EQ(wrong_vertices, 0u) << label;
  EXPECT_EQ(far_faces, 0u) << label;
  // The vertices are those the faces use, ascending.
  EXPECT_TRUE(std::is_sorted(part.global_ids.begin(), part.global_ids.end())) << label;
  std::vector<char> used(part.num_vertices(), 0);
  for (uint32_t v : part.faces) used[v] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << label;

  std::vector<Triple> all = all_values(comm, faces);
  std::sort(all.begin(), all.end());
  std::vector<Triple> serial;
  for (size_t f = 0; f < p.initial.num_faces(); ++f) {
    const uint32_t* v = &p.initial.faces[3 * f];
    serial.push_back(rotated({p.initial.global_ids[v[0]], p.initial.global_ids[v[1]], p.initial.global_ids[v[2]]}));
  }
  std::sort(serial.begin(), serial.end());
  EXPECT_EQ(all.size(), serial.size()) << label;
  EXPECT_TRUE(all == serial) << label << ": the ranks' faces are not the serial initial front";

  // The leaves: every serial boundary and too-close leaf on exactly one rank.
  std::vector<uint64_t> keys = all_values(comm, part.leaves.key);
  std::sort(keys.begin(), keys.end());
  std::vector<uint64_t> serial_keys;
  for (size_t i = 0; i < p.tree.size(); ++i)
    if (front_leaf_class(p.tree.cls[i])) serial_keys.push_back(p.tree.key[i]);
  EXPECT_TRUE(keys == serial_keys) << label << ": the ranks' leaves are not the serial boundary leaves";
}

// The centres of the leaves of every rank are on its side of every
// separator that split a rank set holding it.
void check_separators(const Comm& comm, const Prepared& p, const FrontPart& part,
                      const std::vector<Separator>& separators) {
  const int rank = comm.rank();
  EXPECT_EQ(separators.size(), static_cast<size_t>(comm.size() - 1)) << p.label;
  size_t wrong = 0;
  for (const Separator& s : separators) {
    if (rank < s.first_rank || rank >= s.last_rank) continue;
    for (size_t i = 0; i < part.leaves.size(); ++i) {
      double c[3];
      octant_centre(p.root, part.leaves.key[i], part.leaves.level[i], c);
      const double side = project(s.normal, c);
      wrong += rank < s.mid_rank ? !(side <= s.offset) : !(side >= s.offset);
    }
  }
  EXPECT_EQ(wrong, 0u) << p.label;
}

// Builds, partitions and migrates; checks everything; returns the work
// imbalance after migration.
double run_partition(const Comm& comm, const Prepared& p, BisectionMethod method) {
  MigrationBytes exchanged;
  const FrontPart before = make_boundary_front(comm, p.view, p.part, p.root, p.surface, &exchanged);
  check_part(comm, p, before, "before partition");
  // The leaves before the partition are this rank's own.
  size_t not_own = 0;
  for (uint64_t key : before.leaves.key) {
    auto at = std::lower_bound(p.view.key.begin(), p.view.key.end(), key);
    not_own += at == p.view.key.end() || *at != key || p.view.owner[static_cast<size_t>(at - p.view.key.begin())] != comm.rank();
  }
  EXPECT_EQ(not_own, 0u) << p.label;

  PartitionResult cut = partition_front_leaves(comm, before, p.root, method);
  MigrationBytes migrated;
  const FrontPart after = migrate_front_part(comm, before, cut.destination, &migrated);
  check_part(comm, p, after, "after migration");
  check_separators(comm, p, after, cut.separators);
  // Every leaf went where the partition sent it; bytes add up over ranks.
  std::vector<uint64_t> sent_keys;
  for (size_t i = 0; i < before.leaves.size(); ++i)
    if (cut.destination[i] == comm.rank()) sent_keys.push_back(before.leaves.key[i]);
  for (uint64_t key : sent_keys)
    EXPECT_TRUE(std::binary_search(after.leaves.key.begin(), after.leaves.key.end(), key)) << p.label;
  EXPECT_EQ(comm.sum(migrated.sent), comm.sum(migrated.received)) << p.label;
  if (comm.size() == 1) {
    EXPECT_EQ(migrated.sent, 0) << p.label;
  }
  return work_imbalance(comm, after);
}

std::vector<std::string> data_surfaces() {
  std::vector<std::string> files;
  for (const char* dir : {"good", "fixable"})
    for (const auto& e : std::filesystem::directory_iterator(test::data_path(dir))) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(PartitionBoundary, FrontIsTheSerialInitialFrontOnEveryRankCount) {
  const Comm comm = Comm::world();
  for (const char* name : {"good/sphere966.off", "good/cube.off", "good/eight.off", "fixable/tet-shuffled.off"}) {
    const Prepared p = prepare(comm, name, read_surface_file(test::data_path(name)), 0.5);
    for (BisectionMethod m : {BisectionMethod::kRob, BisectionMethod::kRib, BisectionMethod::kMrob})
      run_partition(comm, p, m);
  }
  SurfaceMesh cavity = test::shifted_box(0, 4);
  test::append(cavity, test::shifted_box(1, 2));
  run_partition(comm, prepare(comm, "box with cavity", cavity, 0.25), BisectionMethod::kMrob);
  SurfaceMesh two = test::shifted_box(0, 1);
  test::append(two, test::shifted_box(3, 1));
  run_partition(comm, prepare(comm, "two boxes", two, 0.25), BisectionMethod::kRib);
}

// The weighted cut cannot split a leaf, so the imbalance is bounded by the
// heaviest leaves against a rank's share: with a few faces per leaf it
// needs some dozens of faces per rank. So each data surface is sized at
// 1, 1/2, 1/4 and 1/8 of its edge lengths (more core faces, smaller leaves;
// stopping once the front passes 10000 faces), and the 5 % bound is
// asserted wherever the front has at least 64 faces per rank: every surface
// but tet-shuffled (4 faces, no core at any size), hedra (at most 120) and,
// on 4 ranks, icosahedron (at most 164).
TEST(PartitionBoundary, MrobBalancesTheFrontOnTheDataSurfaces) {
  const Comm comm = Comm::world();
  if (comm.size() != 2 && comm.size() != 4) GTEST_SKIP() << "asserted on 2 and 4 ranks";
  size_t asserted = 0;
  for (const std::string& file : data_surfaces()) {
    const std::string name = std::filesystem::path(file).filename().string();
    for (double factor : {1.0, 0.5, 0.25, 0.125}) {
      const Prepared p = prepare(comm, name, read_surface_file(file), factor);
      const double imbalance = run_partition(comm, p, BisectionMethod::kMrob);
      const size_t faces = p.initial.num_faces();
      if (comm.rank() == 0)
        std::printf("%-28s %d ranks: %6zu faces, imbalance %.4f\n", p.label.c_str(), comm.size(), faces, imbalance);
      if (faces >= 64 * static_cast<size_t>(comm.size())) {
        EXPECT_LE(imbalance, 1.05) << p.label;
        ++asserted;
      }
      if (faces > 10000) break;
    }
  }
  EXPECT_GE(asserted, 40u);
}

}  // namespace
}  // namespace partet
