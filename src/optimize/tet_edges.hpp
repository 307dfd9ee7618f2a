// The six edges of a tet by local vertex pairs, and for each edge the two
// other corners: the faces at the edge are the faces opposite them. One
// table for the optimizer's edge walks, quality measure and cone bounds.
#pragma once

namespace partet {

inline constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
inline constexpr int kTetEdgeFaces[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};

}  // namespace partet
