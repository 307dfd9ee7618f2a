#!/usr/bin/env python3
"""Seed corpora and dictionaries for the fuzz targets, made from data/.

usage: seeds.py DATA_DIR OUT_DIR MAX_LEN

Writes OUT_DIR/<target>/ (small valid files of every variant the parser
reads, none longer than MAX_LEN bytes) and OUT_DIR/<target>.dict (the
format's keywords, in libFuzzer's dictionary syntax) for the targets stl,
off, obj, ply, medit, gmsh and vtu. The surfaces are the small OFF files of
data/ and a few triangles cut from its STL files; the volume formats get the
unit cube split into 6 tets.
"""
import base64
import os
import struct
import sys


def read_off(path):
    """Vertices and triangles of an OFF file (comments skipped)."""
    words = []
    with open(path) as f:
        for line in f:
            words.extend(line.split("#")[0].split())
    if words[0].endswith("OFF"):
        words = words[1:]
    nv, nf = int(words[0]), int(words[1])
    at = 3
    xyz = []
    for _ in range(nv):
        xyz.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append(tuple(int(w) for w in words[at + 1:at + 1 + n]))
        at += 1 + n
    return xyz, faces


def cube_tets():
    xyz = [(float(i & 1), float(i >> 1 & 1), float(i >> 2 & 1)) for i in range(8)]
    tets = [(0, 1, 3, 7), (0, 3, 2, 7), (0, 2, 6, 7), (0, 6, 4, 7), (0, 4, 5, 7), (0, 5, 1, 7)]
    tris = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
            (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    return xyz, tris, tets


def stl_ascii(xyz, tris, upper=False):
    s = "solid seed\n"
    for t in tris:
        s += " facet normal 0 0 1\n  outer loop\n"
        for v in t:
            s += "   vertex %r %r %r\n" % xyz[v]
        s += "  endloop\n endfacet\n"
    s += "endsolid seed\n"
    return (s.upper() if upper else s).encode()


def stl_binary(xyz, tris, header=b"solid binary seed"):
    out = header.ljust(80, b"\0") + struct.pack("<I", len(tris))
    for t in tris:
        out += struct.pack("<3f", 0, 0, 1)
        for v in t:
            out += struct.pack("<3f", *xyz[v])
        out += b"\0\0"
    return out


def off_text(xyz, faces, keyword="OFF", colours=False):
    s = "# seed\n%s\n%d %d 0\n" % (keyword, len(xyz), len(faces))
    for p in xyz:
        s += "%r %r %r%s\n" % (p + (" 1 0 0 1" if colours else "",))
    for f in faces:
        s += "%d %s%s\n" % (len(f), " ".join(map(str, f)), " 255 0 0" if colours else "")
    return s.encode()


def obj_text(xyz, faces):
    s = "# seed\nmtllib a.mtl\no seed\n"
    for p in xyz:
        s += "v %r %r %r\n" % p
    s += "vt 0 0\nvn 0 0 1\nusemtl m\ns 1\n"
    forms = ["%d", "%d/1", "%d//1", "%d/1/1"]
    for i, f in enumerate(faces):
        idx = [v + 1 if (i + k) % 2 else v - len(xyz) for k, v in enumerate(f)]
        corners = [forms[(i + k) % 4] % x for k, x in enumerate(idx)]
        s += "f " + " ".join(corners[:2]) + (" \\\n " if i == 0 else " ") + " ".join(corners[2:]) + "\n"
    return s.encode()


def ply(xyz, faces, fmt):
    head = ("ply\nformat %s 1.0\ncomment seed\nelement vertex %d\nproperty float x\n"
            "property double y\nproperty short z\nproperty uchar red\nelement face %d\n"
            "property list uchar int vertex_indices\nproperty int flags\n"
            "element edge 1\nproperty list ushort uint vertex_index\nend_header\n"
            % (fmt, len(xyz), len(faces)))
    if fmt == "ascii":
        body = "".join("%r %r %d 7\n" % (p[0], p[1], int(p[2])) for p in xyz)
        body += "".join("%d %s 1\n" % (len(f), " ".join(map(str, f))) for f in faces)
        body += "2 0 1\n"
        return (head + body).encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "fdhB", p[0], p[1], int(p[2]), 7) for p in xyz)
    body += b"".join(struct.pack(e + "B%dii" % len(f), len(f), *f, 1) for f in faces)
    body += struct.pack(e + "HII", 2, 0, 1)
    return head.encode() + body


def medit(xyz, tris, tets):
    s = "MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n" % len(xyz)
    s += "".join("%r %r %r 0\n" % p for p in xyz)
    s += "Triangles\n%d\n" % len(tris) + "".join("%d %d %d 1\n" % tuple(v + 1 for v in t) for t in tris)
    s += "Tetrahedra\n%d\n" % len(tets) + "".join("%d %d %d %d 1\n" % tuple(v + 1 for v in t) for t in tets)
    return (s + "End\n").encode()


def gmsh(xyz, tris, tets):
    n = len(xyz)
    s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    s += "$Nodes\n1 %d 1 %d\n3 1 0 %d\n" % (n, n, n)
    s += "".join("%d\n" % (i + 1) for i in range(n))
    s += "".join("%r %r %r\n" % p for p in xyz) + "$EndNodes\n"
    s += "$Elements\n2 %d 1 %d\n" % (len(tris) + len(tets), len(tris) + len(tets))
    s += "2 1 2 %d\n" % len(tris)
    s += "".join("%d %d %d %d\n" % ((i + 1,) + tuple(v + 1 for v in t)) for i, t in enumerate(tris))
    s += "3 1 4 %d\n" % len(tets)
    s += "".join("%d %d %d %d %d\n" % ((len(tris) + i + 1,) + tuple(v + 1 for v in t))
                 for i, t in enumerate(tets))
    return (s + "$EndElements\n").encode()


def vtu(xyz, tets, binary):
    def array(name, vtype, comps, values, fmt):
        if binary:
            raw = struct.pack("<%d%s" % (len(values), fmt), *values)
            data = base64.b64encode(struct.pack("<Q", len(raw)) + raw).decode()
            return ('<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="binary">%s'
                    "</DataArray>\n" % (vtype, name, comps, data))
        return ('<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="ascii">%s'
                "</DataArray>\n" % (vtype, name, comps, " ".join(repr(v) for v in values)))
    header = ' header_type="UInt64"' if binary else ""
    s = '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian"%s>\n' % header
    s += '<UnstructuredGrid>\n<Piece NumberOfPoints="%d" NumberOfCells="%d">\n' % (len(xyz), len(tets))
    s += "<Points>\n" + array("Points", "Float64", 3, [c for p in xyz for c in p], "d") + "</Points>\n"
    s += "<Cells>\n" + array("connectivity", "Int64", 1, [v for t in tets for v in t], "q")
    s += array("offsets", "Int64", 1, [4 * (i + 1) for i in range(len(tets))], "q")
    s += array("types", "UInt8", 1, [10] * len(tets), "B") + "</Cells>\n"
    return (s + "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n").encode()


DICTS = {
    "stl": ["solid", "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet",
            "endsolid", "SOLID", "nan", "inf", "1e308", "-0"],
    "off": ["OFF", "COFF", "NOFF", "CNOFF", "STOFF", "4OFF", "nOFF", "BINARY", "#", "nan", "3 ", "4 "],
    "obj": ["v ", "vt ", "vn ", "f ", "g ", "o ", "s ", "usemtl ", "mtllib ", "l ", "p ", "/", "//",
            "-1", "\\\n", "#"],
    "ply": ["ply\n", "format ", "ascii", "binary_little_endian", "binary_big_endian", "1.0", "comment",
            "obj_info", "element ", "property ", "list ", "vertex", "face", "vertex_indices",
            "vertex_index", "end_header\n", "char", "uchar", "short", "ushort", "int", "uint", "float",
            "double", "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64",
            " x", " y", " z"],
    "medit": ["MeshVersionFormatted", "MeshVersionFormatted 2", "Dimension", "Vertices", "Triangles",
              "Tetrahedra", "Edges", "Quadrilaterals", "Hexahedra", "Corners", "Ridges", "End", "#"],
    "gmsh": ["$MeshFormat", "$EndMeshFormat", "4.1 0 8", "4.1 1 8", "$Nodes", "$EndNodes",
             "$Elements", "$EndElements", "$Entities", "$EndEntities", "$PhysicalNames",
             "$EndPhysicalNames", "$Comments"],
    "vtu": ["<VTKFile", "UnstructuredGrid", "<Piece", "NumberOfPoints", "NumberOfCells", "<Points>",
            "<Cells>", "<DataArray", "</DataArray>", "format=\"ascii\"", "format=\"binary\"",
            "format=\"appended\"", "<AppendedData encoding=\"raw\">", "header_type=\"UInt32\"",
            "header_type=\"UInt64\"", "connectivity", "offsets", "types", "Float32", "Float64",
            "Int32", "Int64", "UInt8", "GlobalNodeId", "<PUnstructuredGrid", "<Piece Source=\"",
            "byte_order=\"LittleEndian\"", "byte_order=\"BigEndian\"", "NumberOfComponents=\"3\""],
}


def main():
    data, out, max_len = sys.argv[1], sys.argv[2], int(sys.argv[3])
    seeds = {name: {} for name in DICTS}
    for sub in ("good", "fixable", "bad"):
        folder = os.path.join(data, sub)
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if name.endswith(".off") and os.path.getsize(path) <= max_len:
                with open(path, "rb") as f:
                    seeds["off"][name] = f.read()
                xyz, faces = read_off(path)
                stem = name[:-4]
                seeds["obj"][stem + ".obj"] = obj_text(xyz, faces)
                for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
                    seeds["ply"]["%s-%s.ply" % (stem, fmt)] = ply(xyz, faces, fmt)
                if all(len(f) == 3 for f in faces):
                    seeds["stl"][stem + "-ascii.stl"] = stl_ascii(xyz, faces)
                    seeds["stl"][stem + "-binary.stl"] = stl_binary(xyz, faces)
                    seeds["off"][stem + "-coff.off"] = off_text(xyz, faces, "COFF", True)
            if name.endswith(".stl"):
                with open(path, "rb") as f:
                    raw = f.read()
                if raw[:5] == b"solid" and b"\0" not in raw[:300]:
                    cut = raw[:raw.index(b"endfacet", 2000) + 9] + b"endsolid\n"
                else:
                    cut = raw[:80] + struct.pack("<I", 8) + raw[84:84 + 8 * 50]
                seeds["stl"][name] = cut
    xyz, faces = read_off(os.path.join(data, "good", "cube.off"))
    seeds["stl"]["cube-upper.stl"] = stl_ascii(xyz, faces, upper=True)
    seeds["stl"]["cube-plain-header.stl"] = stl_binary(xyz, faces, b"made by a seed script")
    cxyz, ctris, ctets = cube_tets()
    seeds["medit"]["cube.mesh"] = medit(cxyz, ctris, ctets)
    seeds["gmsh"]["cube.msh"] = gmsh(cxyz, ctris, ctets)
    seeds["vtu"]["cube-ascii.vtu"] = vtu(cxyz, ctets, False)
    seeds["vtu"]["cube-binary.vtu"] = vtu(cxyz, ctets, True)
    seeds["vtu"]["cube.pvtu"] = (b'<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid" version="1.0">\n'
                                 b'<PUnstructuredGrid><PPoints><PDataArray type="Float64" '
                                 b'NumberOfComponents="3"/></PPoints>\n<Piece Source="cube_0.vtu"/>\n'
                                 b'<Piece Source="cube_1.vtu"/>\n</PUnstructuredGrid>\n</VTKFile>\n')
    for target, files in seeds.items():
        folder = os.path.join(out, target)
        os.makedirs(folder, exist_ok=True)
        for name, content in files.items():
            if len(content) <= max_len:
                with open(os.path.join(folder, name), "wb") as f:
                    f.write(content)
        with open(os.path.join(out, target + ".dict"), "w") as f:
            for i, word in enumerate(DICTS[target]):
                escaped = "".join(c if " " <= c <= "~" and c not in '\\"' else "\\x%02X" % ord(c)
                                  for c in word)
                f.write('kw%d="%s"\n' % (i, escaped))


if __name__ == "__main__":
    main()
