// Rank 0 (or every rank) puts the ranks' leaves and core parts together
// (see gather_core.hpp).
#include "templates/gather_core.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "parallel/byte_image.hpp"
#include "templates/face_rule.hpp"

namespace partet {
namespace {

// This rank's leaves, their face cases and tet counts, its core part, and
// its leaves' triangle rows when it has them (else two empty arrays).
std::string part_image(const LinearOctree& view, const TemplateCore& part, int rank, const LeafTriangles* rows) {
  std::vector<uint64_t> key;
  std::vector<uint8_t> level, face_case;
  std::vector<LeafClass> cls;
  std::vector<uint32_t> tets_of_leaf;
  for (size_t i = 0; i < view.size(); ++i) {
    if (view.owner[i] != rank) continue;
    key.push_back(view.key[i]);
    level.push_back(view.level[i]);
    cls.push_back(view.cls[i]);
    face_case.insert(face_case.end(), &part.face_case[kLeafFaces * i], &part.face_case[kLeafFaces * (i + 1)]);
    tets_of_leaf.push_back(static_cast<uint32_t>(part.leaf_first_tet[i + 1] - part.leaf_first_tet[i]));
  }
  std::string out;
  put_array(out, key);
  put_array(out, level);
  put_array(out, cls);
  put_array(out, face_case);
  put_array(out, tets_of_leaf);
  put_array(out, part.mesh.xyz);
  put_array(out, part.mesh.tets);
  put_array(out, part.mesh.global_ids);
  const std::vector<uint64_t> templated{part.leaves_templated};
  put_array(out, templated);
  put_array(out, rows ? rows->first : std::vector<uint32_t>{});
  put_array(out, rows ? rows->tris : std::vector<uint32_t>{});
  return out;
}

}  // namespace

void gather_tree_and_core(const Comm& comm, const LinearOctree& view, const TemplateCore& part,
                          LinearOctree& tree, TemplateCore& core, bool everywhere, LeafTriangles* rows) {
  const std::string mine = part_image(view, part, comm.rank(), rows);
  const std::vector<std::string> images = everywhere ? comm.all_gather(mine) : comm.gather(mine, 0);
  tree = LinearOctree();
  core = TemplateCore();
  if (rows) *rows = LeafTriangles{};
  if (images.empty()) return;  // not rank 0, and not everywhere
  struct Part {
    std::vector<double> xyz;
    std::vector<uint32_t> tets;
    std::vector<uint64_t> ids;
    std::vector<uint32_t> index;  // per vertex, its place in the union
    size_t taken = 0;             // vertices placed so far
  };
  std::vector<Part> parts(images.size());
  std::vector<uint32_t> tets_of_leaf;
  for (size_t r = 0; r < images.size(); ++r) {
    size_t pos = 0;
    const std::string& image = images[r];
    append_array(image, pos, tree.key);
    append_array(image, pos, tree.level);
    append_array(image, pos, tree.cls);
    append_array(image, pos, core.face_case);
    const size_t leaves_before = tets_of_leaf.size();
    append_array(image, pos, tets_of_leaf);
    parts[r].xyz = get_array<double>(image, pos);
    parts[r].tets = get_array<uint32_t>(image, pos);
    parts[r].ids = get_array<uint64_t>(image, pos);
    core.leaves_templated += get_array<uint64_t>(image, pos).at(0);
    const std::vector<uint32_t> first = get_array<uint32_t>(image, pos);
    if (!rows) continue;
    PARTET_ASSERT(first.size() == tets_of_leaf.size() - leaves_before + 1,
                  "gathered triangle rows disagree with the leaves");
    if (rows->first.empty()) rows->first.push_back(0);
    const uint32_t base = rows->first.back();
    for (size_t i = 1; i < first.size(); ++i) rows->first.push_back(base + first[i]);
    append_array(image, pos, rows->tris);
  }
  tree.owner.assign(tree.size(), 0);
  PARTET_ASSERT(std::is_sorted(tree.key.begin(), tree.key.end()), "gathered leaves out of order");
  PARTET_ASSERT(core.face_case.size() == kLeafFaces * tree.size() && tets_of_leaf.size() == tree.size(),
                "gathered core parts disagree with the leaves");

  // Vertices: the union of the parts' global ids (each ascending), merged
  // in one pass over the parts' heads (a scan of the P heads per vertex);
  // each part's vertex gets its place in the union as it is taken.
  std::vector<uint64_t>& ids = core.mesh.global_ids;
  size_t total = 0, tet_entries = 0;
  for (Part& p : parts) {
    PARTET_ASSERT(std::is_sorted(p.ids.begin(), p.ids.end()), "a core part's ids out of order");
    p.index.resize(p.ids.size());
    total += p.ids.size();
    tet_entries += p.tets.size();
  }
  ids.reserve(total);
  const auto head = [](const Part& p) { return p.ids[p.taken]; };
  for (;;) {
    Part* low = nullptr;
    for (Part& p : parts)
      if (p.taken < p.ids.size() && (!low || head(p) < head(*low))) low = &p;
    if (!low) break;
    if (ids.empty() || ids.back() != head(*low)) ids.push_back(head(*low));
    low->index[low->taken++] = static_cast<uint32_t>(ids.size() - 1);
  }
  core.mesh.xyz.resize(3 * ids.size());
  core.mesh.tets.reserve(tet_entries);
  for (const Part& p : parts) {
    for (size_t v = 0; v < p.ids.size(); ++v) std::copy_n(&p.xyz[3 * v], 3, &core.mesh.xyz[3 * size_t{p.index[v]}]);
    for (uint32_t v : p.tets) core.mesh.tets.push_back(p.index.at(v));
  }
  core.leaf_first_tet.assign(tree.size() + 1, 0);
  for (size_t i = 0; i < tree.size(); ++i) core.leaf_first_tet[i + 1] = core.leaf_first_tet[i] + tets_of_leaf[i];
  PARTET_ASSERT(4 * core.leaf_first_tet.back() == core.mesh.tets.size(), "gathered tet counts disagree");

  // Home leaves: ids and leaf keys both ascend, so one sweep.
  core.leaf_first_vertex.assign(tree.size() + 1, static_cast<uint32_t>(ids.size()));
  size_t v = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    core.leaf_first_vertex[i] = static_cast<uint32_t>(v);
    const uint64_t end = tree.key[i] + octant_key_span(tree.level[i]);
    while (v < ids.size() && (ids[v] >> 3) < end) ++v;
  }
  PARTET_ASSERT(v == ids.size(), "template vertex outside the tree");
}

}  // namespace partet
