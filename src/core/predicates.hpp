// Exact geometric predicates on double coordinates: a floating-point filter
// with an exact expansion-arithmetic fallback, so the sign is always right.
// Points are `const double*` to 3 coordinates (x, y, z), or 2 for orient2d.
#pragma once

namespace partet {

// Sign (-1, 0, +1) of det[b-a; c-a] for 2-D points: +1 when a, b, c turn
// counterclockwise.
int orient2d(const double* a, const double* b, const double* c);

// orient2d of 3-D points projected onto the coordinate plane that drops
// axis `drop` (0, 1 or 2): the remaining axes in cyclic order (drop x: (y, z),
// drop y: (z, x), drop z: (x, y)), so that the sign agrees with the dropped
// component of the normal (b-a)x(c-a).
int orient2d_projected(const double* a, const double* b, const double* c, int drop);

// Sign of det[b-a; c-a; d-a]: +1 when d lies on the side of the plane abc
// that the normal (b-a)x(c-a) points to. A tet (a, b, c, d) is positively
// oriented when orient3d(a, b, c, d) > 0.
int orient3d(const double* a, const double* b, const double* c, const double* d);

}  // namespace partet
