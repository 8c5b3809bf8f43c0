#!/usr/bin/env python3
"""Writes the mesh seeds in tests/fuzz/corpus/{obj,off,ply,stl}/: small files, and between them
the variants of each format the readers take (ASCII and binary, colours, normals, texture
coordinates, quads, comments, CRLF). Geometry: a closed cube, and patches cut from two shared
meshes whose terms allow it (spot.obj, public domain; teapot_closed.obj, CC0): their first faces
and the vertices those use, renumbered.

    /usr/bin/python3 tests/fuzz/make_mesh_seeds.py ../shared/data/meshes tests/fuzz/corpus
"""
import os
import struct
import sys

CUBE_V = [(x, y, z) for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)]
CUBE_QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]


def patch(path, faces_wanted):
    """The first faces of an OBJ file and the vertices (and texture coordinates) they use."""
    vs, vts, faces = [], [], []
    with open(path, newline="") as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                vs.append(tuple(float(t) for t in w[1:4]))
            elif w[0] == "vt":
                vts.append(tuple(float(t) for t in w[1:3]))
            elif w[0] == "f" and len(faces) < faces_wanted:
                faces.append([tuple(int(i) - 1 if i else None for i in c.split("/")) for c in w[1:]])
    vmap, tmap = {}, {}
    out_faces = []
    for face in faces:
        out = []
        for corner in face:
            v = vmap.setdefault(corner[0], len(vmap))
            t = tmap.setdefault(corner[1], len(tmap)) if len(corner) > 1 and corner[1] is not None else None
            out.append((v, t))
        out_faces.append(out)
    verts = [None] * len(vmap)
    for old, new in vmap.items():
        verts[new] = vs[old]
    tex = [None] * len(tmap)
    for old, new in tmap.items():
        tex[new] = vts[old]
    return verts, tex, out_faces


def triangles(faces):
    for f in faces:
        for k in range(1, len(f) - 1):
            yield (f[0], f[k], f[k + 1])


def write(path, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(path, mode, newline="" if mode == "w" else None) as f:
        f.write(data)
    print(f"{path}: {os.path.getsize(path)} bytes")


def obj_text(verts, faces, tex=None, eol="\n", header=""):
    lines = [header] if header else []
    lines += ["v %g %g %g" % v for v in verts]
    if tex:
        lines += ["vt %g %g" % t for t in tex]
    for f in faces:
        if tex:
            lines.append("f " + " ".join("%d/%d" % (v + 1, t + 1) for v, t in f))
        else:
            lines.append("f " + " ".join(str(v + 1) for v in f))
    return eol.join(lines) + eol


def off_text(verts, faces, keyword="OFF", colour=False, normals=False):
    out = [keyword, "# seed", "%d %d 0" % (len(verts), len(faces))]
    for i, v in enumerate(verts):
        row = "%g %g %g" % v
        if normals:
            row += " 0 0 1"
        if colour:
            row += " %d %d %d" % (i * 40 % 256, 128, 255)
        out.append(row)
    out += ["%d " % len(f) + " ".join(map(str, f)) for f in faces]
    return "\n".join(out) + "\n"


def off_binary(verts, faces):
    data = b"OFF BINARY\n" + struct.pack("<3I", len(verts), len(faces), 0)
    data += b"".join(struct.pack("<3f", *v) for v in verts)
    for f in faces:
        data += struct.pack("<I", len(f)) + struct.pack("<%dI" % len(f), *f)
    return data


def ply(verts, faces, fmt="ascii", extra=(), colours=False, count_type="uchar", comment=""):
    head = ["ply", "format %s 1.0" % fmt]
    if comment:
        head.append("comment " + comment)
    head += ["element vertex %d" % len(verts), "property float x", "property float y",
             "property float z"]
    head += ["property float %s" % e for e in extra]
    if colours:
        head += ["property uchar red", "property uchar green", "property uchar blue"]
    head += ["element face %d" % len(faces), "property list %s int vertex_indices" % count_type,
             "end_header"]
    header = ("\n".join(head) + "\n").encode()
    if fmt == "ascii":
        rows = []
        for i, v in enumerate(verts):
            row = "%g %g %g " % v + "".join("%g " % (0.5 + 0.1 * k) for k in range(len(extra)))
            if colours:
                row += "%d %d %d " % (i * 40 % 256, 128, 255)
            rows.append(row)
        rows += ["%d " % len(f) + " ".join(map(str, f)) + " " for f in faces]
        return header + ("\n".join(rows) + "\n").encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    count = {"uchar": "B", "uint16": "H", "int": "i"}[count_type]
    body = b""
    for i, v in enumerate(verts):
        body += struct.pack(e + "3f", *v)
        body += b"".join(struct.pack(e + "f", 0.5) for _ in extra)
        if colours:
            body += struct.pack("3B", i * 40 % 256, 128, 255)
    for f in faces:
        body += struct.pack(e + count, len(f)) + struct.pack(e + "%di" % len(f), *f)
    return header + body


def stl_ascii(verts, tris):
    out = ["solid seed"]
    for t in tris:
        out += ["  facet normal 0 0 1", "    outer loop"]
        out += ["      vertex %g %g %g" % verts[i] for i in t]
        out += ["    endloop", "  endfacet"]
    return "\n".join(out + ["endsolid seed"]) + "\n"


def stl_binary(verts, tris, header=b"seed binary stl"):
    data = header.ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        data += struct.pack("<3f", 0, 0, 1)
        data += b"".join(struct.pack("<3f", *verts[i]) for i in t) + b"\0\0"
    return data


def main():
    shared, out = sys.argv[1], sys.argv[2]
    for d in ("obj", "off", "ply", "stl"):
        os.makedirs(os.path.join(out, d), exist_ok=True)
    spot_v, spot_t, spot_f = patch(os.path.join(shared, "spot.obj"), 48)
    spot_idx = [[v for v, _ in f] for f in spot_f]
    pot_v, pot_t, pot_f = patch(os.path.join(shared, "teapot_closed.obj"), 24)
    pot_idx = [[v for v, _ in f] for f in pot_f]
    cube_tris = list(triangles(CUBE_QUADS))

    o = os.path.join(out, "obj")
    write(os.path.join(o, "cube_quads.obj"), obj_text(CUBE_V, CUBE_QUADS, header="# closed cube"))
    write(os.path.join(o, "spot_patch_vt.obj"), obj_text(spot_v, spot_f, tex=spot_t))
    write(os.path.join(o, "teapot_patch_crlf.obj"),
          obj_text(pot_v, pot_f, tex=pot_t, eol="\r\n",
                   header="mtllib default.mtl\r\n#\r\ng Base\r\nusemtl default"))
    write(os.path.join(o, "negative_normals.obj"),
          "o tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\ns 1\nf -3//1 -2//1 -1//1\n")

    f = os.path.join(out, "off")
    write(os.path.join(f, "cube.off"), off_text(CUBE_V, CUBE_QUADS))
    write(os.path.join(f, "spot_patch_colour.off"), off_text(spot_v, spot_idx, "COFF", colour=True))
    write(os.path.join(f, "teapot_patch_normals.off"),
          off_text(pot_v, pot_idx, "NOFF", normals=True))
    write(os.path.join(f, "cube_binary.off"), off_binary(CUBE_V, CUBE_QUADS))
    write(os.path.join(f, "spot_patch_binary.off"), off_binary(spot_v, spot_idx))

    p = os.path.join(out, "ply")
    write(os.path.join(p, "cube_ascii.ply"), ply(CUBE_V, CUBE_QUADS))
    # The layout of Stanford's zipper output (extra vertex properties, trailing spaces).
    write(os.path.join(p, "spot_patch_zipper.ply"),
          ply(spot_v, spot_idx, extra=("confidence", "intensity"), comment="zipper output"))
    write(os.path.join(p, "spot_patch_le_colour.ply"),
          ply(spot_v, spot_idx, "binary_little_endian", colours=True))
    write(os.path.join(p, "teapot_patch_be.ply"),
          ply(pot_v, pot_idx, "binary_big_endian", count_type="int"))
    write(os.path.join(p, "cube_le_uint16.ply"),
          ply(CUBE_V, CUBE_QUADS, "binary_little_endian", count_type="uint16"))

    s = os.path.join(out, "stl")
    write(os.path.join(s, "cube_ascii.stl"), stl_ascii(CUBE_V, cube_tris))
    write(os.path.join(s, "cube_binary.stl"), stl_binary(CUBE_V, cube_tris))
    write(os.path.join(s, "spot_patch_binary_solid.stl"),
          stl_binary(spot_v, list(triangles(spot_idx)), header=b"solid exported as binary"))
    write(os.path.join(s, "teapot_patch_ascii.stl"), stl_ascii(pot_v, list(triangles(pot_idx))))


if __name__ == "__main__":
    main()
