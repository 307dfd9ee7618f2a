# The smallest interior dihedral angle of a closed, outward-oriented OFF
# surface between two triangles sharing an edge. At a convex edge of
# interior angle t every tet holding that edge has a dihedral angle of at
# most t, so no mesher can beat it: bench/run reports it as the bound forced
# by the input. Reflex edges (t > 180) force nothing; refining a surface by
# midpoint splits keeps the bound (new edges are flat).
import math


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#", 1)[0].split()]
    nv, nf = int(tokens[1]), int(tokens[2])
    xyz = [tuple(float(x) for x in tokens[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
    tris, at = [], 4 + 3 * nv
    for _ in range(nf):
        n = int(tokens[at])
        tris.append(tuple(int(v) for v in tokens[at + 1:at + 1 + n]))
        at += n + 1
    return xyz, tris


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit_normal(xyz, tri):
    a, b, c = (xyz[v] for v in tri)
    n = cross(sub(b, a), sub(c, a))
    length = math.sqrt(dot(n, n))
    return tuple(x / length for x in n) if length > 0 else None


def min_interior_dihedral_deg(path):
    """Smallest interior angle (degrees) over the edges with two triangles."""
    xyz, tris = read_off(path)
    first_side = {}  # directed edge (a, b) -> triangle index
    for t, tri in enumerate(tris):
        for k in range(3):
            first_side[(tri[k], tri[(k + 1) % 3])] = t
    best = 180.0
    for (a, b), t in first_side.items():
        u = first_side.get((b, a))
        if u is None or u < t:
            continue
        n1, n2 = unit_normal(xyz, tris[t]), unit_normal(xyz, tris[u])
        if n1 is None or n2 is None:
            continue
        turn = math.degrees(math.acos(max(-1.0, min(1.0, dot(n1, n2)))))
        apex = next(v for v in tris[u] if v != a and v != b)
        convex = dot(n1, sub(xyz[apex], xyz[a])) < 0
        if convex:
            best = min(best, 180.0 - turn)
    return best
