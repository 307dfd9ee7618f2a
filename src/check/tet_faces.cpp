// Face matching of a tet mesh (see tet_faces.hpp).
// Two tets sharing a face must lie on opposite sides of it. The side of a
// tet's fourth vertex d relative to the face's sorted triple (a, b, c) is the
// sign of orient3d(a, b, c, d), which is the tet's exact orientation sign
// times the parity of the permutation taking the tet's vertices to
// (a, b, c, d): exact geometry without a second predicate call per face.
#include "check/tet_faces.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"

namespace partet {
namespace {

struct Entry {
  uint64_t key;   // the face's middle and largest vertex
  uint32_t code;  // 4 * tet + local face
  bool operator<(const Entry& o) const { return key != o.key ? key < o.key : code < o.code; }
};

void sort3(uint32_t v[3]) {
  if (v[0] > v[1]) std::swap(v[0], v[1]);
  if (v[1] > v[2]) std::swap(v[1], v[2]);
  if (v[0] > v[1]) std::swap(v[0], v[1]);
}

// Sign of orient3d(a, b, c, d) for the face's sorted triple (a, b, c) and
// the tet's fourth vertex d; 0 when the tet has no known orientation.
int side_of_sorted_face(const TetMesh& mesh, const std::vector<TetState>& state, uint32_t code) {
  TetState s = state[code / 4];
  int sign = s == TetState::kPositive ? 1 : s == TetState::kNegative ? -1 : 0;
  uint32_t o[3];
  outward_face(mesh, code, o);
  int inversions = (o[0] > o[1]) + (o[0] > o[2]) + (o[1] > o[2]);
  int even = inversions % 2 == 0 ? 1 : -1;
  // For a positive tet the outward face sees d on its negative side.
  return -sign * even;
}

uint32_t opposite_vertex(const TetMesh& mesh, uint32_t code) { return mesh.tets[code]; }

// A duplicate pair shows in all four face groups; it is counted at the face
// opposite the tet's largest vertex (the first one, if repeated).
bool is_counting_face(const TetMesh& mesh, uint32_t code) {
  const uint32_t* v = &mesh.tets[4 * (code / 4)];
  return static_cast<uint32_t>(std::max_element(v, v + 4) - v) == code % 4;
}

class GroupChecker {
 public:
  GroupChecker(const TetMesh& mesh, const std::vector<TetState>& state, FaceProblems& problems,
               FaceMatch& match)
      : mesh_(mesh), state_(state), problems_(problems), match_(match) {}

  void check(const Entry* group, size_t n) {
    if (n == 1) {
      match_.boundary.push_back(group[0].code);
      return;
    }
    bool duplicate = false;
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q) {
        uint32_t cp = group[p].code, cq = group[q].code;
        if (cp / 4 == cq / 4 || opposite_vertex(mesh_, cp) != opposite_vertex(mesh_, cq)) continue;
        duplicate = true;
        if (is_counting_face(mesh_, cp) && problems_.duplicate.note())
          problems_.duplicate.describe(tet_text(mesh_, cp / 4) + " and " + tet_text(mesh_, cq / 4));
      }
    if (n == 2) {
      ++match_.interior;
      int s0 = side_of_sorted_face(mesh_, state_, group[0].code);
      int s1 = side_of_sorted_face(mesh_, state_, group[1].code);
      if (!duplicate && s0 != 0 && s0 == s1 && problems_.same_side.note())
        problems_.same_side.describe(tet_text(mesh_, group[0].code / 4) + " and " +
                                     tet_text(mesh_, group[1].code / 4));
      return;
    }
    if (problems_.crowded.note()) {
      uint32_t face[3];
      outward_face(mesh_, group[0].code, face);
      sort3(face);
      std::string text = "face " + triangle_text(mesh_, face) + " in tets";
      for (size_t i = 0; i < n; ++i) text += " " + std::to_string(group[i].code / 4);
      problems_.crowded.describe(std::move(text));
    }
  }

 private:
  const TetMesh& mesh_;
  const std::vector<TetState>& state_;
  FaceProblems& problems_;
  FaceMatch& match_;
};

}  // namespace

FaceMatch match_tet_faces(const TetMesh& mesh, const std::vector<TetState>& state,
                          FaceProblems& problems) {
  const size_t num_vertices = mesh.num_vertices();
  const size_t num_tets = mesh.num_tets();
  if (num_tets >= (size_t{1} << 30))
    throw InputError("cannot validate " + std::to_string(num_tets) +
                     " tets in one part: at most 2^30 - 1 are supported");

  auto smallest = [&](uint32_t code) {
    uint32_t v[3];
    outward_face(mesh, code, v);
    return std::min({v[0], v[1], v[2]});
  };
  // Counting sort of the face codes by smallest vertex: face_start[v] is
  // where vertex v's faces begin in `codes`.
  std::vector<uint32_t> face_start(num_vertices + 1, 0);
  for (uint32_t t = 0; t < num_tets; ++t)
    if (state[t] != TetState::kOutOfRange)
      for (uint32_t f = 0; f < 4; ++f) ++face_start[smallest(4 * t + f) + 1];
  std::partial_sum(face_start.begin(), face_start.end(), face_start.begin());
  std::vector<uint32_t> codes(face_start[num_vertices]);
  for (uint32_t t = 0; t < num_tets; ++t)
    if (state[t] != TetState::kOutOfRange)
      for (uint32_t f = 0; f < 4; ++f) codes[face_start[smallest(4 * t + f)]++] = 4 * t + f;
  // Filling advanced each start to the next vertex's start: shift back.
  for (size_t v = num_vertices; v > 0; --v) face_start[v] = face_start[v - 1];
  face_start[0] = 0;

  FaceMatch match;
  GroupChecker checker(mesh, state, problems, match);
  std::vector<Entry> bucket;
  for (size_t a = 0; a < num_vertices; ++a) {
    bucket.clear();
    for (uint32_t i = face_start[a]; i < face_start[a + 1]; ++i) {
      uint32_t v[3];
      outward_face(mesh, codes[i], v);
      sort3(v);
      bucket.push_back({(uint64_t{v[1]} << 32) | v[2], codes[i]});
    }
    std::sort(bucket.begin(), bucket.end());
    for (size_t i = 0, j = 0; i < bucket.size(); i = j) {
      while (j < bucket.size() && bucket[j].key == bucket[i].key) ++j;
      checker.check(&bucket[i], j - i);
    }
  }
  return match;
}

}  // namespace partet
