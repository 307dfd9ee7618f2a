// Face removal validity checks (see removal_checks.hpp): bounding boxes
// (exact comparisons) reject far entities cheaply, then front faces
// separated from the tet by one of its face planes (exact orientations
// shared by the faces of a vertex), and exact predicates decide the rest.
#include "front/removal_checks.hpp"

#include <algorithm>

#include "core/intersections.hpp"
#include "core/predicates.hpp"

namespace partet {

namespace {

struct Box {
  double lo[3], hi[3];
};

bool boxes_meet(const Box& x, const Box& y) {
  for (int k = 0; k < 3; ++k)
    if (x.hi[k] < y.lo[k] || y.hi[k] < x.lo[k]) return false;
  return true;
}

Box box_of(const double* const* p, int n) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = b.hi[k] = p[0][k];
    for (int i = 1; i < n; ++i) {
      b.lo[k] = std::min(b.lo[k], p[i][k]);
      b.hi[k] = std::max(b.hi[k], p[i][k]);
    }
  }
  return b;
}

// Box x meets the float box fb (lo[3], hi[3]; see Front::face_box).
bool meets_float_box(const Box& x, const float* fb) {
  for (int k = 0; k < 3; ++k)
    if (x.hi[k] < fb[k] || fb[3 + k] < x.lo[k]) return false;
  return true;
}

bool point_in_box(const double* p, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.lo[k] || b.hi[k] < p[k]) return false;
  return true;
}

// Segment (ids u, v) against triangle (ids t[0..2]) with the shared-vertex
// rules: true when they meet other than at shared vertices or along a
// shared edge.
bool segment_conflicts(const Front& front, uint32_t u, uint32_t v, const uint32_t* t) {
  int shared_u = -1, shared_v = -1;
  for (int k = 0; k < 3; ++k) {
    if (t[k] == u) shared_u = k;
    if (t[k] == v) shared_v = k;
  }
  if (shared_u >= 0 && shared_v >= 0) return false;
  if (shared_u < 0 && shared_v < 0)
    return segment_triangle_intersect(front.point(u), front.point(v), front.point(t[0]), front.point(t[1]),
                                      front.point(t[2]));
  const int k = shared_u >= 0 ? shared_u : shared_v;
  const uint32_t s = t[k], o = shared_u >= 0 ? v : u;
  return meets_beyond_shared_vertex(front.point(s), front.point(o), front.point(t[(k + 1) % 3]),
                                    front.point(t[(k + 2) % 3]));
}

// Moves `stamp` on for a new round of per-slot marks; when it wraps to 0,
// every mark is cleared first, so that no old mark equals the new stamp.
void next_stamp(std::vector<uint32_t>& marks, uint32_t& stamp) {
  if (++stamp != 0) return;
  std::fill(marks.begin(), marks.end(), 0);
  stamp = 1;
}

}  // namespace

bool meets_beyond_shared_vertex(const double* s, const double* o, const double* t1, const double* t2) {
  if (orient3d(s, t1, t2, o) != 0) return false;  // the segment meets the plane at s only
  // Coplanar: project along an axis where the triangle stays a triangle
  // (the projection is then one-to-one on the plane); the segment leaves s
  // into the triangle exactly when o lies in the closed angle t1-s-t2.
  for (int drop = 0; drop < 3; ++drop) {
    const int turn = orient2d_projected(s, t1, t2, drop);
    if (turn == 0) continue;
    return orient2d_projected(s, t1, o, drop) * turn >= 0 && orient2d_projected(s, o, t2, drop) * turn >= 0;
  }
  return true;  // degenerate triangle: outside the contract, refuse
}

void gather_near_front(const Front& front, const std::vector<size_t>& leaves, NearFront& near) {
  near.faces.clear();
  near.vertices.clear();
  // A face is listed in every leaf its box overlaps: take it once (marks,
  // not sorting: this runs for every face removal attempt).
  if (near.face_mark.size() < front.num_face_slots()) near.face_mark.resize(front.num_face_slots(), 0);
  next_stamp(near.face_mark, near.gather);
  for (size_t leaf : leaves) {
    for (uint32_t e = front.first_face_entry(leaf); e != kNoIndex; e = front.next_entry(e)) {
      const uint32_t f = front.entry_face(e);
      if (near.face_mark[f] == near.gather) continue;
      near.face_mark[f] = near.gather;
      near.faces.push_back(f);
    }
    for (uint32_t v = front.first_vertex(leaf); v != kNoIndex; v = front.next_vertex(v)) near.vertices.push_back(v);
  }
}

const char* verdict_name(RemovalVerdict v) {
  switch (v) {
    case RemovalVerdict::kValid: return "valid";
    case RemovalVerdict::kNotPositive: return "not positive";
    case RemovalVerdict::kDuplicateFace: return "duplicate face";
    case RemovalVerdict::kVertexInside: return "vertex inside";
    case RemovalVerdict::kEdgeCrossesFace: return "new edge crosses a front face";
    case RemovalVerdict::kFaceCrossesEdge: return "new face crosses a front edge";
  }
  return "?";
}

namespace {

RemovalVerdict blocked(RemovalBlocker* why, RemovalVerdict verdict, uint32_t entity, int index) {
  if (why) *why = {verdict, static_cast<uint8_t>(index), entity};
  return verdict;
}

}  // namespace

void Suspects::add(const RemovalBlocker& why) {
  std::vector<uint32_t>* list = nullptr;
  if (why.verdict == RemovalVerdict::kVertexInside) list = &vertices;
  if (blocked_by_face(why) && why.verdict != RemovalVerdict::kDuplicateFace) list = &faces;
  if (list && std::find(list->begin(), list->end(), why.entity) == list->end()) list->push_back(why.entity);
}

RemovalVerdict check_removal(const Front& front, uint32_t f, uint32_t p, const NearFront& near,
                             RemovalBlocker* why, const Suspects* suspects) {
  const uint32_t* base = front.face(f);
  const uint32_t a = base[0], b = base[1], c = base[2];
  if (p == a || p == b || p == c) return blocked(why, RemovalVerdict::kNotPositive, p, 0);
  const double *pa = front.point(a), *pb = front.point(b), *pc = front.point(c), *pp = front.point(p);
  if (orient3d(pa, pb, pc, pp) <= 0) return blocked(why, RemovalVerdict::kNotPositive, p, 0);

  // New faces (outward from the tet) and whether each is new or closes a twin.
  const uint32_t sides[3][3] = {{b, c, p}, {a, p, c}, {a, b, p}};
  bool new_side[3];
  for (int s = 0; s < 3; ++s) {
    const uint32_t g = front.find_face(sides[s][0], sides[s][1], sides[s][2]);
    new_side[s] = g == kNoIndex;
    if (g == kNoIndex) continue;
    // Same orientation when the alive face is a rotation of the side.
    const uint32_t* t = front.face(g);
    for (int r = 0; r < 3; ++r)
      if (t[r] == sides[s][0] && t[(r + 1) % 3] == sides[s][1])
        return blocked(why, RemovalVerdict::kDuplicateFace, g, s);
  }
  const uint32_t ends[3] = {a, b, c};
  bool new_edge[3];
  for (int k = 0; k < 3; ++k) new_edge[k] = front.edge_uses(p, ends[k]) == 0;

  const double* corners[4] = {pa, pb, pc, pp};
  const Box tet_box = box_of(corners, 4);

  // Bit k of clear_of(x): x lies strictly outside the tet's face plane k
  // (base, then the sides) or is one of that face's corners. A front face
  // whose three corners share a bit meets the closed tet at most in
  // corners or an edge of that face, which no test below reports: it is
  // passed over. Cached per vertex for this check. The low four bits are
  // those the orientation filter makes certain; the high four mark planes
  // it left open (x on or within rounding of the plane), which only
  // clear_of_plane settles exactly, when a verdict depends on them (points on
  // a face plane are common: core faces, flat parts of the surface).
  if (near.vertex_check.size() < front.num_vertices()) {
    near.vertex_check.resize(front.num_vertices(), 0);
    near.vertex_clear.resize(front.num_vertices(), 0);
  }
  next_stamp(near.vertex_check, near.check);
  const uint32_t planes[4][3] = {{a, c, b}, {b, c, p}, {a, p, c}, {a, b, p}};
  const PlaneSide plane_side[4] = {{pa, pc, pb}, {pb, pc, pp}, {pa, pp, pc}, {pa, pb, pp}};
  auto clear_of = [&](uint32_t x) -> uint8_t {
    if (near.vertex_check[x] == near.check) return near.vertex_clear[x];
    uint8_t mask = 0;
    const bool corner = x == a || x == b || x == c || x == p;
    for (int k = 0; k < 4; ++k) {
      const uint32_t* q = planes[k];
      if (x == q[0] || x == q[1] || x == q[2]) {
        mask |= static_cast<uint8_t>(1u << k);
      } else if (!corner) {
        const int side = plane_side[k].filtered(front.point(x));
        if (side != 0) mask |= static_cast<uint8_t>((side > 0 ? 1u : 0u) << k);
        else mask |= static_cast<uint8_t>(0x10u << k);
      }
    }
    near.vertex_check[x] = near.check;
    near.vertex_clear[x] = mask;
    return mask;
  };
  // Bit k of clear_of(x), decided exactly when the filter left it open.
  auto clear_of_plane = [&](uint32_t x, int k) {
    const uint8_t mask = clear_of(x);
    if (((mask >> (4 + k)) & 1u) == 0) return ((mask >> k) & 1u) != 0;
    const bool clear = plane_side[k].exact(front.point(x)) > 0;
    near.vertex_clear[x] = static_cast<uint8_t>((mask & ~(0x10u << k)) | (clear ? 1u << k : 0u));
    return clear;
  };
  // True when the three corners share a bit.
  auto passed_over = [&](uint32_t x, uint32_t y, uint32_t z) {
    const uint8_t mx = clear_of(x), my = clear_of(y), mz = clear_of(z);
    if ((mx & my & mz & 0x0Fu) != 0) return true;
    const unsigned open = (mx | mx >> 4) & (my | my >> 4) & (mz | mz >> 4) & 0x0Fu;
    for (int k = 0; k < 4; ++k)
      if (((open >> k) & 1u) && clear_of_plane(x, k) && clear_of_plane(y, k) && clear_of_plane(z, k)) return true;
    return false;
  };

  // (i) Front vertices in the closed tet: clear of no face plane.
  auto inside = [&](uint32_t v) {
    if (v == a || v == b || v == c || v == p) return false;
    if (!point_in_box(front.point(v), tet_box)) return false;
    const uint8_t mask = clear_of(v);
    if ((mask & 0x0Fu) != 0) return false;
    for (int k = 0; k < 4; ++k)
      if (((mask >> (4 + k)) & 1u) && clear_of_plane(v, k)) return false;
    return true;
  };

  // (ii) New edges against front faces, (iii) new faces against front
  // edges; only faces whose box meets the tet's box matter for either.
  const bool any_new_edge = new_edge[0] || new_edge[1] || new_edge[2];
  const bool any_new_side = new_side[0] || new_side[1] || new_side[2];
  Box edge_box[3], side_box[3];
  for (int k = 0; k < 3; ++k) {
    const double* e[2] = {pp, front.point(ends[k])};
    edge_box[k] = box_of(e, 2);
    const double* sp[3] = {front.point(sides[k][0]), front.point(sides[k][1]), front.point(sides[k][2])};
    side_box[k] = box_of(sp, 3);
  }
  // The verdict face g gives, with the index of the edge or side it blocks.
  auto crossing = [&](uint32_t g, int& index) {
    const float* face_box = front.face_box(g);
    if (!meets_float_box(tet_box, face_box)) return RemovalVerdict::kValid;
    const uint32_t* t = front.face(g);
    if (passed_over(t[0], t[1], t[2])) return RemovalVerdict::kValid;
    for (int k = 0; k < 3; ++k) {
      if (!new_edge[k] || !meets_float_box(edge_box[k], face_box)) continue;
      index = k;
      if (segment_conflicts(front, p, ends[k], t)) return RemovalVerdict::kEdgeCrossesFace;
    }
    if (!any_new_side) return RemovalVerdict::kValid;
    for (int k = 0; k < 3; ++k) {
      const uint32_t u = t[k], w = t[(k + 1) % 3];
      if (u > w) continue;  // the edge is checked from the face running along it upwards
      const double* ends_uw[2] = {front.point(u), front.point(w)};
      const Box uw = box_of(ends_uw, 2);
      if (!boxes_meet(tet_box, uw)) continue;
      for (int s = 0; s < 3; ++s) {
        if (!new_side[s] || !boxes_meet(side_box[s], uw)) continue;
        index = s;
        if (segment_conflicts(front, u, w, sides[s])) return RemovalVerdict::kFaceCrossesEdge;
      }
    }
    return RemovalVerdict::kValid;
  };

  const bool any_new = any_new_edge || any_new_side;
  int index = 0;
  if (suspects) {
    for (uint32_t v : suspects->vertices)
      if (front.vertex_uses(v) > 0 && inside(v)) return blocked(why, RemovalVerdict::kVertexInside, v, 0);
    if (any_new)
      for (uint32_t g : suspects->faces) {
        if (!front.alive(g)) continue;
        const RemovalVerdict verdict = crossing(g, index);
        if (verdict != RemovalVerdict::kValid) return blocked(why, verdict, g, index);
      }
  }
  for (uint32_t v : near.vertices)
    if (inside(v)) return blocked(why, RemovalVerdict::kVertexInside, v, 0);
  if (!any_new) return RemovalVerdict::kValid;
  for (uint32_t g : near.faces) {
    const RemovalVerdict verdict = crossing(g, index);
    if (verdict != RemovalVerdict::kValid) return blocked(why, verdict, g, index);
  }
  return RemovalVerdict::kValid;
}

bool still_blocked(const Front& front, uint32_t f, uint32_t p, const RemovalBlocker& why) {
  const uint32_t* base = front.face(f);
  const uint32_t a = base[0], b = base[1], c = base[2];
  switch (why.verdict) {
    case RemovalVerdict::kValid: return false;
    case RemovalVerdict::kNotPositive: return true;  // geometry and ids only
    case RemovalVerdict::kDuplicateFace: return front.alive(why.entity);
    case RemovalVerdict::kVertexInside: return front.vertex_uses(why.entity) > 0;
    case RemovalVerdict::kEdgeCrossesFace: {
      const uint32_t ends[3] = {a, b, c};
      return front.alive(why.entity) && front.edge_uses(p, ends[why.index]) == 0;
    }
    case RemovalVerdict::kFaceCrossesEdge: {
      const uint32_t sides[3][3] = {{b, c, p}, {a, p, c}, {a, b, p}};
      const uint32_t* side = sides[why.index];
      return front.alive(why.entity) && front.find_face(side[0], side[1], side[2]) == kNoIndex;
    }
  }
  return false;
}

}  // namespace partet
