// Exact validity of a face removal: may the tet (a, b, c, p) be built on
// the alive front face (a, b, c) without overlapping what is meshed or
// crossing the front? Every decision is an exact predicate.
//
// The tet's new faces, oriented away from it (into the unmeshed region),
// are (b, c, p), (a, p, c), (a, b, p); a new face whose reverse is alive
// closes that face and is not new; its new edges are p-a, p-b, p-c unless
// already front edges. The removal is valid when:
//  - p is not a, b or c and orient3d(a, b, c, p) > 0;
//  - no new face duplicates an alive face with the same orientation (the
//    tet would lie on that face's meshed side);
//  (i)   no front vertex other than a, b, c, p lies in the closed tet;
//  (ii)  no new edge meets a front face other than at a shared vertex: a
//        face sharing one endpoint s may touch the edge at s only (the edge
//        is coplanar with the face and leaves s into the face's closed
//        angle at s otherwise); a face containing both endpoints would make
//        the edge a front edge;
//  (iii) no new face meets a front edge other than at shared vertices or
//        along the edge itself when it is one of the face's edges (same
//        shared-vertex rule as (ii)).
// With a valid (non self-intersecting) front these exclude every overlap:
// a front face meeting a new face only through their interiors from a
// shared vertex must leave one of them through an edge, which (ii), (iii)
// or the front's own validity rules out.
//
// The front entities checked are those of a NearFront, which must contain
// every alive face (and its edges) and every front vertex that can meet the
// tet's bounding box: gather them from the leaves over any box containing
// the tet (Front's leaf index guarantees the rest).
#pragma once

#include <cstdint>
#include <vector>

#include "front/front.hpp"

namespace partet {

struct NearFront {
  std::vector<uint32_t> faces;       // alive faces, each once, in leaf order
  std::vector<uint32_t> vertices;    // front vertices, in leaf order
  std::vector<uint32_t> face_mark;   // per face slot: the gather that last took it
  uint32_t gather = 0;
  // check_removal's scratch, per front vertex: the check that last
  // classified it against the tet's four face planes, and the planes it is
  // clear of (see check_removal).
  mutable std::vector<uint32_t> vertex_check;
  mutable std::vector<uint8_t> vertex_clear;
  mutable uint32_t check = 0;
};

// Replaces `near` with the faces listed in `leaves` (Front's leaf index)
// and the front vertices of those leaves. The front edges that meet the
// leaves are edges of those faces: both faces along an edge are listed
// wherever the edge is, and check_removal takes each edge from the face
// running along it from its lower to its higher vertex index.
void gather_near_front(const Front& front, const std::vector<size_t>& leaves, NearFront& near);

enum class RemovalVerdict : uint8_t {
  kValid = 0,
  kNotPositive,      // p is a vertex of the face, or on its back side or plane
  kDuplicateFace,    // a new face is an alive face with the same orientation
  kVertexInside,     // (i)
  kEdgeCrossesFace,  // (ii)
  kFaceCrossesEdge,  // (iii)
};

const char* verdict_name(RemovalVerdict v);

// Why a removal failed: the verdict and the front entity that caused it
// (the duplicated face, the vertex inside, the face the new edge p-(a, b,
// c)[index] crosses, or the face along whose edge new side `index` crosses;
// the sides are (b, c, p), (a, p, c), (a, b, p)).
struct RemovalBlocker {
  RemovalVerdict verdict = RemovalVerdict::kValid;
  uint8_t index = 0;
  uint32_t entity = 0;
};

// The blocking entity of `why` is a face slot (a duplicated or crossing
// face), else a vertex or none.
inline bool blocked_by_face(const RemovalBlocker& why) {
  return why.verdict == RemovalVerdict::kDuplicateFace || why.verdict == RemovalVerdict::kEdgeCrossesFace ||
         why.verdict == RemovalVerdict::kFaceCrossesEdge;
}

// Front entities to test before the near front, e.g. what blocked the
// other targets of the same face: the far targets of a long face are
// mostly blocked by the same few faces, which a scan of its whole
// neighbourhood finds only after hundreds of others. Those no longer on
// the front are passed over, so a list may outlive changes to the front;
// the verdict is the one the near front alone gives (each suspect tested
// is a front entity the check may test), only the blocker reported may
// differ.
struct Suspects {
  std::vector<uint32_t> faces;
  std::vector<uint32_t> vertices;
  bool empty() const { return faces.empty() && vertices.empty(); }
  void clear() {
    faces.clear();
    vertices.clear();
  }
  // Adds the entity of `why` when it is a vertex inside or a crossing face
  // and not there yet.
  void add(const RemovalBlocker& why);
};

// Validity of the tet on alive face f with apex p, against `near`; with
// `why`, the reason when it is not valid. With `suspects`, those are
// tested first.
RemovalVerdict check_removal(const Front& front, uint32_t f, uint32_t p, const NearFront& near,
                             RemovalBlocker* why = nullptr, const Suspects* suspects = nullptr);

// True when a removal (f, p) that failed for `why` must still fail on the
// front as it is now: the blocking entity is still on the front and the
// new edge or side it blocked is still new. Any changes may have been made
// since by apply_tet, remove_tet and add_vertex: face slots are never
// reused, and a vertex that was ever on the front keeps its index and
// point (remove_last_vertex only takes back one no face used), so a
// blocker still on the front, against an edge or side still new, blocks
// as it did. Exact: it re-evaluates no geometry.
bool still_blocked(const Front& front, uint32_t f, uint32_t p, const RemovalBlocker& why);

// Closed segment s-o against closed triangle (s, t1, t2) sharing vertex s:
// true when they meet anywhere other than at s.
bool meets_beyond_shared_vertex(const double* s, const double* o, const double* t1, const double* t2);

}  // namespace partet
