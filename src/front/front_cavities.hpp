// The front's cavities: its alive faces grouped across their edges. Where
// more than two front faces share an edge (two cavities pinched along it,
// as a thin plate's slab leaves between its top and bottom surface
// vertices), the cavities are the wedges of unmeshed space around the
// edge: each face bounds the wedge on its unmeshed side (where
// orient3d(face, p) > 0), which ends at the next face around the edge in
// that direction, so the faces there are paired across those wedges. The
// tree-less removals split their components that way instead of taking
// every face on the edge as one cavity: stress-check seed 673's 260 faces
// left were a chain of such cavities, pinched along 95 edges, that no
// star point could fill together.
//
// Exact: the faces are sorted around the edge by orient3d signs alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "front/front.hpp"

namespace partet {

// The n >= 3 faces on edge (x, y) of `front`, partner[i] set to the face
// across the wedge on faces[i]'s unmeshed side. False (partner unchanged)
// when that is not well defined: n odd, a third vertex coplanar with
// another face on the edge, or two faces in a row around the edge whose
// unmeshed sides do not face each other.
bool pair_faces_around_edge(const Front& front, uint32_t x, uint32_t y, const std::vector<uint32_t>& faces,
                            std::vector<uint32_t>& partner);

// The faces a walk from alive face f crosses its edge (x, y) to, in
// `on_edge` (cleared first): f's partner where pair_faces_around_edge pairs
// the edge's faces, else every other face on the edge (on an edge of two
// faces, the other one, from the front's edge table).
void faces_across_edge(const Front& front, uint32_t f, uint32_t x, uint32_t y, std::vector<uint32_t>& on_edge);

// The alive faces grouped into cavities (connected across edges as
// faces_across_edge crosses them): `faces` holds them cavity by cavity,
// in face index order within each, the cavities in order of their lowest
// face; `first` the start of each cavity in `faces`, plus one past the end.
void front_cavities(const Front& front, std::vector<uint32_t>& faces, std::vector<size_t>& first);

}  // namespace partet
