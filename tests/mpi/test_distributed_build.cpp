// The distributed octree and the per-rank templates against the serial
// pipeline, on 1, 2, 3, 4 and 8 ranks: the leaves gathered in rank order are
// the serial tree after building, after triangle refinement and after
// balance (2:1 balance checked on the gathered tree, by pairs on a small
// one); classes after classification and the manifold pass are the serial
// ones; no rank holds much more than its share; the ranks' core parts put
// together are the serial core (same tets in the same order, same global ids
// and coordinates), and every piece is a valid mesh; the triangles binned
// into the ranks' leaves, put together, are the gathered tree's bins.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "check/validate.hpp"
#include "io/mesh_file.hpp"
#include "octree/balance.hpp"
#include "octree/build.hpp"
#include "octree/classify.hpp"
#include "octree/distributed_build.hpp"
#include "octree/distributed_classify.hpp"
#include "octree/ghost_layer.hpp"
#include "octree/neighbours.hpp"
#include "octree/sizing.hpp"
#include "octree/triangle_bins.hpp"
#include "parallel/comm.hpp"
#include "parallel/vertex_links.hpp"
#include "surface/diagnose.hpp"
#include "templates/gather_core.hpp"
#include "templates/manifold_core.hpp"
#include "templates/template_mesh.hpp"
#include "test_support.hpp"

namespace partet {
namespace {

struct Input {
  std::string label;
  SurfaceMesh surface;
  RootCube root;
  VertexSizing sizing;
};

Input prepare(const std::string& label, SurfaceMesh surface, double factor) {
  Input in;
  in.label = label + " x" + std::to_string(factor);
  const SurfaceSummary summary = diagnose_surface(surface, label);
  in.surface = std::move(surface);
  in.root = make_root_cube(summary.bbox);
  SizingOptions options;
  options.size_factor = factor;
  in.sizing = size_vertices(in.surface, in.root, options);
  return in;
}

// This rank's slice of the (grid point, level) pairs: an even share, or all
// of them on the last rank.
void slice(const Comm& comm, const Input& in, bool all_on_last, std::vector<uint32_t>& grid,
           std::vector<uint8_t>& level) {
  const size_t n = in.sizing.level.size(), p = static_cast<size_t>(comm.size()), r = static_cast<size_t>(comm.rank());
  size_t begin = n * r / p, end = n * (r + 1) / p;
  if (all_on_last) {
    begin = 0;
    end = r + 1 == p ? n : 0;
  }
  grid.assign(in.sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * begin),
              in.sizing.grid.begin() + static_cast<std::ptrdiff_t>(3 * end));
  level.assign(in.sizing.level.begin() + static_cast<std::ptrdiff_t>(begin),
               in.sizing.level.begin() + static_cast<std::ptrdiff_t>(end));
}

// Every rank's leaves of `t` (owner == rank), concatenated in rank order, on
// every rank.
LinearOctree all_leaves(const Comm& comm, const LinearOctree& t) {
  std::string mine;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t.owner[i] != comm.rank()) continue;
    char record[10];
    std::memcpy(record, &t.key[i], 8);
    record[8] = static_cast<char>(t.level[i]);
    record[9] = static_cast<char>(t.cls[i]);
    mine.append(record, 10);
  }
  std::vector<std::string> parts = comm.gather(mine, 0);
  std::string all;
  for (const std::string& p : parts) all += p;
  comm.broadcast(all, 0);
  LinearOctree out;
  for (size_t at = 0; at < all.size(); at += 10) {
    uint64_t key;
    std::memcpy(&key, &all[at], 8);
    out.key.push_back(key);
    out.level.push_back(static_cast<uint8_t>(all[at + 8]));
    out.cls.push_back(static_cast<LeafClass>(all[at + 9]));
    out.owner.push_back(0);
  }
  return out;
}

void expect_same_leaves(const LinearOctree& a, const LinearOctree& b, const std::string& what, bool classes) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_TRUE(a.key == b.key) << what;
  EXPECT_TRUE(a.level == b.level) << what;
  if (classes) {
    EXPECT_TRUE(a.cls == b.cls) << what;
  }
}

// True when two leaves sharing a face or a positive length of an edge differ
// by more than one level (closed boxes compared pairwise).
bool unbalanced_pair(const LinearOctree& t) {
  for (size_t i = 0; i < t.size(); ++i)
    for (size_t j = i + 1; j < t.size(); ++j) {
      if (std::abs(t.level[i] - t.level[j]) <= 1) continue;
      uint32_t a[3], b[3];
      t.anchor(i, a[0], a[1], a[2]);
      t.anchor(j, b[0], b[1], b[2]);
      const uint32_t ea = octant_edge(t.level[i]), eb = octant_edge(t.level[j]);
      int overlapping = 0, touching = 0;  // axes with a positive overlap, axes where they only touch
      for (int k = 0; k < 3; ++k) {
        const uint32_t lo = std::max(a[k], b[k]), hi = std::min(a[k] + ea, b[k] + eb);
        overlapping += lo < hi;
        touching += lo == hi;
      }
      if (overlapping + touching == 3 && overlapping >= 1) return true;
    }
  return false;
}

std::string bytes_of(const void* data, size_t n) { return std::string(static_cast<const char*>(data), n); }

template <class T>
std::vector<T> values_of(const std::string& bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// The links of every rank's template vertices are exactly the other ranks'
// copies of the same global id (checked on rank 0 from all ranks' ids).
void expect_linked(const Comm& comm, const std::vector<uint64_t>& ids, const std::string& label) {
  const VertexLinks links = link_shared_vertices(comm, ids);
  ASSERT_EQ(links.num_vertices(), ids.size()) << label;
  std::vector<uint64_t> flat;  // per vertex: count, then (rank, index) pairs
  for (size_t v = 0; v < ids.size(); ++v) {
    flat.push_back(links.first[v + 1] - links.first[v]);
    for (uint32_t e = links.first[v]; e < links.first[v + 1]; ++e) {
      flat.push_back(static_cast<uint64_t>(links.rank[e]));
      flat.push_back(links.index[e]);
    }
  }
  const auto all_ids = comm.gather(bytes_of(ids.data(), ids.size() * sizeof(uint64_t)), 0);
  const auto all_links = comm.gather(bytes_of(flat.data(), flat.size() * sizeof(uint64_t)), 0);
  if (comm.rank() != 0) return;
  std::map<uint64_t, std::vector<std::pair<uint64_t, uint64_t>>> where;  // id -> (rank, index)
  for (size_t r = 0; r < all_ids.size(); ++r) {
    const std::vector<uint64_t> rank_ids = values_of<uint64_t>(all_ids[r]);
    for (size_t v = 0; v < rank_ids.size(); ++v) where[rank_ids[v]].emplace_back(r, v);
  }
  for (size_t r = 0; r < all_ids.size(); ++r) {
    const std::vector<uint64_t> rank_ids = values_of<uint64_t>(all_ids[r]);
    std::vector<uint64_t> expected;
    for (size_t v = 0; v < rank_ids.size(); ++v) {
      const auto& copies = where[rank_ids[v]];
      expected.push_back(copies.size() - 1);
      for (const auto& [rank, index] : copies)
        if (rank != r) expected.insert(expected.end(), {rank, index});
    }
    EXPECT_TRUE(values_of<uint64_t>(all_links[r]) == expected) << label << ": links of rank " << r;
  }
}

struct Serial {
  LinearOctree built, refined, balanced, classified, manifold;
  size_t demoted = 0;
  TemplateCore core;
};

Serial serial_pipeline(const Input& in) {
  Serial s;
  s.built = build_octree(in.sizing.grid, in.sizing.level);
  s.refined = s.built;
  refine_for_triangles(s.refined, in.surface, in.root, in.sizing.level);
  s.balanced = s.refined;
  balance_octree(s.balanced);
  s.classified = s.balanced;
  classify_leaves(s.classified, in.surface, in.root, in.sizing.size);
  s.manifold = s.classified;
  s.demoted = make_core_manifold(s.manifold).demoted;
  s.core = template_interior(s.manifold, in.root);
  return s;
}

// The distributed pipeline step by step, each stage compared with the
// serial one; returns the largest number of leaves on one rank.
size_t check_distributed(const Comm& comm, const Input& in, bool all_on_last) {
  const Serial s = serial_pipeline(in);
  const std::string& label = in.label;
  std::vector<uint32_t> grid;
  std::vector<uint8_t> level;
  slice(comm, in, all_on_last, grid, level);
  DistributedOctree tree = build_distributed_octree(comm, grid, level);
  EXPECT_TRUE(std::is_sorted(tree.leaves.key.begin(), tree.leaves.key.end())) << label;
  expect_same_leaves(all_leaves(comm, tree.leaves), s.built, label + ": built", false);
  refine_distributed_for_triangles(tree, comm.rank(), in.surface, in.root, in.sizing.level);
  expect_same_leaves(all_leaves(comm, tree.leaves), s.refined, label + ": refined", false);
  balance_distributed_octree(comm, tree);
  const LinearOctree balanced = all_leaves(comm, tree.leaves);
  expect_same_leaves(balanced, s.balanced, label + ": balanced", false);
  EXPECT_TRUE(is_balanced(balanced)) << label;
  if (balanced.size() < 1500) {
    EXPECT_FALSE(unbalanced_pair(balanced)) << label;
  }
  for (size_t i = 0; i < tree.leaves.size(); ++i) {
    const uint64_t key = tree.leaves.key[i];
    EXPECT_EQ(tree.ranges.owner(key), comm.rank()) << label;
  }

  LeafTriangles rows;
  classify_distributed(comm, tree, in.surface, in.root, in.sizing.size, {}, &rows);
  expect_same_leaves(all_leaves(comm, tree.leaves), s.classified, label + ": classified", true);
  EXPECT_EQ(rows.first.size(), tree.leaves.size() + 1) << label;

  LinearOctree view = ghost_view(comm, tree);
  const ManifoldCoreCounts repairs = make_core_manifold(comm, view);
  EXPECT_EQ(repairs.demoted, s.demoted) << label;
  expect_same_leaves(all_leaves(comm, view), s.manifold, label + ": manifold core", true);

  const TemplateCore part = template_interior(view, in.root, comm.rank());
  expect_linked(comm, part.mesh.global_ids, label);
  if (part.mesh.num_tets() > 0) {
    const ValidationResult v = validate_mesh(part.mesh, nullptr);
    EXPECT_TRUE(v.valid) << label << ": the piece of rank " << comm.rank() << " is not valid";
  }
  LinearOctree gathered;
  TemplateCore core;
  gather_tree_and_core(comm, view, part, gathered, core, false, &rows);
  if (comm.rank() == 0) {
    // The triangle rows put together are those of the gathered tree.
    const LeafTriangles whole = bin_triangles(gathered, in.surface, in.root);
    EXPECT_TRUE(rows.first == whole.first) << label;
    EXPECT_TRUE(rows.tris == whole.tris) << label;
  } else {
    EXPECT_TRUE(rows.first.empty()) << label;
  }
  if (comm.rank() == 0) {
    expect_same_leaves(gathered, s.manifold, label + ": gathered", true);
    EXPECT_TRUE(core.mesh.xyz == s.core.mesh.xyz) << label;
    EXPECT_TRUE(core.mesh.tets == s.core.mesh.tets) << label;
    EXPECT_TRUE(core.mesh.global_ids == s.core.mesh.global_ids) << label;
    EXPECT_TRUE(core.leaf_first_vertex == s.core.leaf_first_vertex) << label;
    EXPECT_TRUE(core.leaf_first_tet == s.core.leaf_first_tet) << label;
    EXPECT_TRUE(core.face_case == s.core.face_case) << label;
    EXPECT_EQ(core.leaves_templated, s.core.leaves_templated) << label;
  }
  return static_cast<size_t>(comm.max(static_cast<int64_t>(tree.leaves.size())));
}

TEST(DistributedBuild, GoodSurfacesMatchSerial) {
  const Comm comm = Comm::world();
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(test::data_path("good")))
    if (e.path().extension() == ".off") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  for (const std::string& f : files) {
    const std::string name = std::filesystem::path(f).filename().string();
    for (double factor : {1.0, 0.5}) check_distributed(comm, prepare(name, read_surface_file(f), factor), false);
  }
  for (const char* name : {"sphere966.off", "eight.off", "spool.off", "dragknob.off"})
    check_distributed(comm, prepare(name, read_surface_file(test::data_path(std::string("good/") + name)), 0.25),
                      false);
}

TEST(DistributedBuild, GeneratedBoxesMatchSerial) {
  const Comm comm = Comm::world();
  check_distributed(comm, prepare("box", test::box_surface(1, 2, 3), 1.0), false);
  SurfaceMesh two = test::shifted_box(0, 1);
  test::append(two, test::shifted_box(3, 1));
  check_distributed(comm, prepare("two boxes", two, 0.25), false);
  SurfaceMesh cavity = test::shifted_box(0, 4);
  test::append(cavity, test::shifted_box(1, 2));
  check_distributed(comm, prepare("box with cavity", cavity, 0.25), false);
}

TEST(DistributedBuild, SameTreeWhereverThePointsStart) {
  const Comm comm = Comm::world();
  check_distributed(comm, prepare("sphere966.off", read_surface_file(test::data_path("good/sphere966.off")), 1.0),
                    true);
}

TEST(DistributedBuild, RanksShareTheLeaves) {
  const Comm comm = Comm::world();
  const Input in = prepare("sphere966.off", read_surface_file(test::data_path("good/sphere966.off")), 0.5);
  const size_t most = check_distributed(comm, in, false);
  const size_t total = serial_pipeline(in).balanced.size();
  // The build balances the sum of point levels, not the leaves: allow twice
  // the even share.
  if (comm.rank() == 0) std::printf("%s: %zu leaves, at most %zu on one of %d ranks\n", in.label.c_str(), total, most, comm.size());
  if (comm.size() > 1) {
    EXPECT_LT(most, 2 * total / static_cast<size_t>(comm.size()) + 64) << most << " of " << total;
  }
}

TEST(DistributedBuild, GradedTreesMatchSerial) {
  // The wider blocks of grading radius 2 and 3 reach further across the
  // ranks' key ranges than the plain balance: the same tree either way.
  const Comm comm = Comm::world();
  for (const char* name : {"sphere966.off", "spool.off"}) {
    const Input in = prepare(name, read_surface_file(test::data_path(std::string("good/") + name)), 1.0);
    std::vector<uint32_t> grid;
    std::vector<uint8_t> level;
    slice(comm, in, false, grid, level);
    for (int grading = 2; grading <= 3; ++grading) {
      DistributedOctree tree = build_distributed_octree(comm, grid, level);
      refine_distributed_for_triangles(tree, comm.rank(), in.surface, in.root, in.sizing.level);
      balance_distributed_octree(comm, tree, grading);
      LinearOctree serial = build_octree(in.sizing.grid, in.sizing.level);
      refine_for_triangles(serial, in.surface, in.root, in.sizing.level);
      balance_octree(serial, grading);
      const LinearOctree graded = all_leaves(comm, tree.leaves);
      expect_same_leaves(graded, serial, in.label + ": graded " + std::to_string(grading), false);
      EXPECT_TRUE(is_graded(graded, grading)) << in.label;
    }
  }
}

}  // namespace
}  // namespace partet
