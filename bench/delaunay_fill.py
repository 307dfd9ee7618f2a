#!/usr/bin/env python3
# bench/delaunay_fill.py MESH: how much of a volume a Delaunay fill would
# leave to the face removals (a study for the speed targets; bench/README.md,
# twenty-third session). MESH is a Medit .mesh written by partet, best with
# --no-optimize (`partet IN -o MESH.mesh --no-optimize`): its vertices are
# those the front uses (surface, gap vertices, core). The script builds the
# Delaunay tetrahedralization of those vertices (Qhull through SciPy), finds
# the input triangles that are not Delaunay faces, removes every Delaunay
# tet that meets one of them (separating-axis test in floating point on the
# triangle shrunk by 1e-6 toward its centroid, so tets touching it only at
# its vertices or edges stay), then counts the tets left inside the
# surface: those not reached from the convex hull across a Delaunay input
# triangle or through a removed tet. It prints the share of input triangles
# that are Delaunay, the tets removed, the volume share of the tets left and
# their quality. Floating point throughout: a measurement, not a mesher.
# Needs python3-numpy and python3-scipy (Debian).
import sys
from collections import deque

import numpy as np
from scipy.spatial import Delaunay


def read_medit(path):
    lines = open(path).read().split("\n")
    points = tets = triangles = None
    i = 0
    while i < len(lines):
        key = lines[i].strip()
        if key in ("Vertices", "Tetrahedra", "Triangles"):
            n = int(lines[i + 1])
            rows = np.loadtxt(lines[i + 2:i + 2 + n], ndmin=2) if n else np.zeros((0, 5))
            if key == "Vertices":
                points = rows[:, :3]
            elif key == "Tetrahedra":
                tets = rows[:, :4].astype(int) - 1
            else:
                triangles = rows[:, :3].astype(int) - 1
            i += 2 + n
            continue
        i += 1
    return points, tets, triangles


def separated(triangle, tet):
    """True when an axis separates the triangle from the closed tet."""
    edges_t = [triangle[1] - triangle[0], triangle[2] - triangle[1], triangle[0] - triangle[2]]
    edges_T = [tet[j] - tet[i] for i in range(4) for j in range(i + 1, 4)]
    axes = [np.cross(edges_t[0], edges_t[1])]
    axes += [np.cross(tet[(i + 1) % 4] - tet[i], tet[(i + 2) % 4] - tet[i]) for i in range(4)]
    axes += [np.cross(a, b) for a in edges_t for b in edges_T]
    eps = 1e-12 * (np.abs(tet).max() + np.abs(triangle).max())
    for axis in axes:
        norm = np.linalg.norm(axis)
        if norm < 1e-30:
            continue
        pt, pT = triangle @ (axis / norm), tet @ (axis / norm)
        if pt.max() < pT.min() - eps or pT.max() < pt.min() - eps:
            return True
    return False


def quality(points):
    """Radius ratios (0 for flat tets) and smallest dihedral angles (degrees)."""
    a, b, c, d = points
    ab, ac, ad = b - a, c - a, d - a
    six_v = np.abs(np.einsum("ij,ij->i", ab, np.cross(ac, ad)))
    area = sum(0.5 * np.linalg.norm(np.cross(y - x, z - x), axis=1) for x, y, z in ((a, b, c), (a, b, d), (a, c, d), (b, c, d)))
    centre = ((ab * ab).sum(1)[:, None] * np.cross(ac, ad) + (ac * ac).sum(1)[:, None] * np.cross(ad, ab)
              + (ad * ad).sum(1)[:, None] * np.cross(ab, ac))
    ok = (six_v > 0) & (np.linalg.norm(centre, axis=1) > 0)
    rr = np.zeros(len(a))
    rr[ok] = 3 * (six_v[ok] / (2 * area[ok])) / (np.linalg.norm(centre[ok], axis=1) / (2 * six_v[ok]))
    smallest = np.full(len(a), 180.0)
    p = [a, b, c, d]
    for i in range(4):
        for j in range(i + 1, 4):
            k, l = [x for x in range(4) if x not in (i, j)]
            e = p[j] - p[i]
            n1, n2 = np.cross(e, p[k] - p[i]), np.cross(e, p[l] - p[i])
            cos = (n1 * n2).sum(1) / np.sqrt((n1 * n1).sum(1) * (n2 * n2).sum(1) + 1e-300)
            smallest = np.minimum(smallest, np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return rr, smallest, ok


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: delaunay_fill.py MESH.mesh")
    points, tets, triangles = read_medit(sys.argv[1])
    used = np.unique(tets.ravel())
    index = -np.ones(len(points), int)
    index[used] = np.arange(len(used))
    q, triangles = points[used], index[triangles]
    dt = Delaunay(q, qhull_options="Qbb Qc Qz Q12 Qt")
    simplices, neighbours = dt.simplices, dt.neighbors

    faces = {}  # sorted face -> [(tet, index of the opposite vertex)]
    for opposite, others in enumerate(((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))):
        for t, face in enumerate(map(tuple, np.sort(simplices[:, list(others)], axis=1))):
            faces.setdefault(face, []).append((t, opposite))
    surface = [tuple(f) for f in np.sort(triangles, axis=1)]
    walls = {side for f in surface if f in faces for side in faces[f]}
    missing = [i for i, f in enumerate(surface) if f not in faces]

    lo, hi = q[simplices].min(1), q[simplices].max(1)
    removed = np.zeros(len(simplices), bool)
    for m in missing:
        corners = q[triangles[m]]
        centre = corners.mean(0)
        shrunk = centre + (corners - centre) * (1 - 1e-6)
        near = np.where(np.all(lo <= shrunk.max(0), 1) & np.all(hi >= shrunk.min(0), 1))[0]
        for t in near:
            if not removed[t] and not separated(shrunk, q[simplices[t]]):
                removed[t] = True

    outside = np.zeros(len(simplices), bool)
    queue = deque()
    for t in range(len(simplices)):
        if removed[t]:
            continue
        if any(neighbours[t, k] == -1 and (t, k) not in walls for k in range(4)):
            outside[t] = True
            queue.append(t)
    while queue:
        t = queue.popleft()
        for k in range(4):
            u = neighbours[t, k]
            if u < 0 or outside[u] or removed[u] or (t, k) in walls:
                continue
            outside[u] = True
            queue.append(u)
    kept = np.where(~outside & ~removed)[0]

    def volume(points_of):
        a, b, c, d = points_of
        return np.abs(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))).sum() / 6

    whole = volume([points[tets[:, k]] for k in range(4)])
    kept_points = [q[simplices[kept][:, k]] for k in range(4)]
    rr, smallest, ok = quality(kept_points)
    print("input triangles %d, Delaunay %.1f %%" % (len(surface), 100 * (1 - len(missing) / len(surface))))
    print("Delaunay tets %d, removed across the others %d, left inside %d holding %.1f %% of the volume"
          % (len(simplices), removed.sum(), len(kept), 100 * volume(kept_points) / whole))
    print("tets left: mean radius ratio %.4f, %.2f %% under 10 degrees, %d flat; the mesh read: %d tets"
          % (rr.mean(), 100 * (smallest < 10).mean(), (~ok).sum(), len(tets)))


if __name__ == "__main__":
    main()
