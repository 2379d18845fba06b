#!/usr/bin/env python3
"""Converts some of CGAL's sample meshes (cgal/data/meshes) into the other formats and
into the shapes real files come in: STL triangle soups (ascii, binary, binary with a
'solid' header), binary PLY little/big endian, PLY with colours, OBJ with quads,
vt/vn, groups and negative indices, OBJ/OFF/PLY soups with unshared vertices.
Writes converted/ next to this script.  Deterministic."""
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_mesh import read_mesh, colour_of  # noqa: E402

SRC = os.path.join(HERE, "cgal", "data", "meshes")
OUT = os.path.join(HERE, "converted")


def load(name):
    pts, faces, cols = read_mesh(os.path.join(SRC, name))
    return pts, faces, cols


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    L = sum(x * x for x in n) ** 0.5 or 1.0
    return [x / L for x in n]


def triangles(faces):
    for f in faces:
        for j in range(1, len(f) - 1):
            yield [f[0], f[j], f[j + 1]]


def write_stl_ascii(path, pts, faces, name="Part1", fmt="%e"):
    with open(path, "w") as fh:
        fh.write("solid %s\n" % name)
        for t in triangles(faces):
            n = normal(*(pts[i] for i in t))
            fh.write("  facet normal %s\n    outer loop\n" % " ".join(fmt % x for x in n))
            for i in t:
                fh.write("      vertex %s\n" % " ".join(fmt % x for x in pts[i]))
            fh.write("    endloop\n  endfacet\n")
        fh.write("endsolid %s\n" % name)


def write_stl_binary(path, pts, faces, header=b"binary STL written by make_converted.py", attr=0):
    tris = list(triangles(faces))
    with open(path, "wb") as fh:
        fh.write(header.ljust(80, b" ")[:80])
        fh.write(struct.pack("<I", len(tris)))
        for t in tris:
            n = normal(*(pts[i] for i in t))
            fh.write(struct.pack("<12fH", *n, *pts[t[0]], *pts[t[1]], *pts[t[2]], attr))


def write_ply(path, pts, faces, fmt="ascii", cols=None, color_type="uchar", alpha=False,
              index_type="int", coord_type="float"):
    endian = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    code = {"float": "f", "double": "d"}[coord_type]
    icode = {"int": "i", "uint": "I"}[index_type]
    head = ["ply", "format %s 1.0" % fmt, "comment written by make_converted.py",
            "element vertex %d" % len(pts)]
    head += ["property %s %s" % (coord_type, c) for c in "xyz"]
    if cols is not None:
        chans = ["red", "green", "blue"] + (["alpha"] if alpha else [])
        head += ["property %s %s" % (color_type, c) for c in chans]
    head += ["element face %d" % len(faces), "property list uchar %s vertex_indices" % index_type, "end_header"]
    with open(path, "wb") as fh:
        fh.write(("\n".join(head) + "\n").encode())
        for i, p in enumerate(pts):
            c = None
            if cols is not None:
                c = list(cols[i]) + ([1.0] if alpha else [])
            if endian is None:
                line = " ".join(repr(float(x)) for x in p)
                if c is not None:
                    if color_type == "uchar":
                        line += " " + " ".join(str(int(round(255 * v))) for v in c)
                    else:
                        line += " " + " ".join("%.6f" % v for v in c)
                fh.write((line + "\n").encode())
            else:
                fh.write(struct.pack(endian + "3" + code, *p))
                if c is not None:
                    if color_type == "uchar":
                        fh.write(struct.pack(endian + "%dB" % len(c), *[int(round(255 * v)) for v in c]))
                    else:
                        fh.write(struct.pack(endian + "%df" % len(c), *c))
        for f in faces:
            if endian is None:
                fh.write(("%d %s\n" % (len(f), " ".join(str(i) for i in f))).encode())
            else:
                fh.write(struct.pack(endian + "B%d%s" % (len(f), icode), len(f), *f))


def write_off(path, pts, faces, cols=None):
    with open(path, "w") as fh:
        fh.write("COFF\n" if cols else "OFF\n")
        fh.write("%d %d 0\n" % (len(pts), len(faces)))
        for i, p in enumerate(pts):
            line = " ".join(repr(float(x)) for x in p)
            if cols:
                line += " " + " ".join(str(int(round(255 * v))) for v in cols[i]) + " 255"
            fh.write(line + "\n")
        for f in faces:
            fh.write("%d %s\n" % (len(f), " ".join(str(i) for i in f)))


def write_obj(path, pts, faces, uv=False, normals=False, negative=False, groups=False):
    with open(path, "w") as fh:
        fh.write("# Blender-like export written by make_converted.py\nmtllib material.mtl\no Mesh\n")
        for p in pts:
            fh.write("v %.6f %.6f %.6f\n" % tuple(p))
        if uv:
            for p in pts:
                fh.write("vt %.6f %.6f\n" % (p[0] - int(p[0]), p[1] - int(p[1])))
        if normals:
            for p in pts:
                L = sum(x * x for x in p) ** 0.5 or 1.0
                fh.write("vn %.4f %.4f %.4f\n" % tuple(x / L for x in p))
        fh.write("usemtl Material\ns off\n")
        n = len(pts)
        for k, f in enumerate(faces):
            if groups and k % max(1, len(faces) // 3) == 0:
                fh.write("g part%d\nusemtl Material.%03d\n" % (k, k % 7))
            corners = []
            for i in f:
                idx = (i - n) if negative else (i + 1)
                if uv and normals:
                    corners.append("%d/%d/%d" % (idx, idx, idx))
                elif normals:
                    corners.append("%d//%d" % (idx, idx))
                elif uv:
                    corners.append("%d/%d" % (idx, idx))
                else:
                    corners.append("%d" % idx)
            fh.write("f %s\n" % " ".join(corners))


def unshare(pts, faces):
    """Every face gets its own copies of its corners (a soup)."""
    out_pts, out_faces = [], []
    for f in faces:
        out_faces.append(list(range(len(out_pts), len(out_pts) + len(f))))
        out_pts += [list(pts[i]) for i in f]
    return out_pts, out_faces


def normalised(pts):
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    c = [(lo[i] + hi[i]) / 2 for i in range(3)]
    s = max(hi[i] - lo[i] for i in range(3)) / 2
    return [[(p[i] - c[i]) / s for i in range(3)] for p in pts]


def main():
    os.makedirs(OUT, exist_ok=True)
    o = lambda name: os.path.join(OUT, name)

    ele = load("elephant.off")
    write_stl_ascii(o("elephant_soup_solidworks_style.stl"), *ele[:2], name="elephant")
    write_stl_binary(o("elephant_binary.stl"), *ele[:2])
    write_stl_binary(o("elephant_binary_solid_header.stl"), *ele[:2],
                     header=b"solid elephant  exported by SolidWorks-like writer (binary!)", attr=0x7FFF)
    write_obj(o("elephant_negative_indices.obj"), *ele[:2], negative=True)
    write_obj(o("elephant_vt_vn_groups.obj"), *ele[:2], uv=True, normals=True, groups=True)
    sp, sf = unshare(*ele[:2])
    write_obj(o("elephant_soup_unshared.obj"), sp, sf)
    write_off(o("elephant_soup_unshared.off"), sp, sf)
    write_ply(o("elephant_soup_unshared.ply"), sp, sf)

    fan = load("fandisk.off")
    write_stl_binary(o("fandisk_binary.stl"), *fan[:2])
    write_ply(o("fandisk_binary_le.ply"), *fan[:2], fmt="binary_little_endian")
    write_ply(o("fandisk_binary_be.ply"), *fan[:2], fmt="binary_big_endian")
    write_ply(o("fandisk_binary_be_double_uint.ply"), *fan[:2], fmt="binary_big_endian",
              coord_type="double", index_type="uint")

    bunny = load("bunny00.off")
    write_ply(o("bunny00_binary_le.ply"), *bunny[:2], fmt="binary_little_endian")

    holes = load("elephant-with-holes.off")
    write_stl_binary(o("elephant_with_holes_binary.stl"), *holes[:2])
    write_obj(o("elephant_with_holes.obj"), *holes[:2])

    cc3 = load("blobby_3cc.off")
    write_stl_ascii(o("blobby_3cc_soup.stl"), *cc3[:2], fmt="%.6g")

    for name in ("torus_quad.off", "cube_quad.off", "cross_quad.off"):
        m = load(name)
        write_obj(o(name.replace(".off", "_vt_vn.obj")), *m[:2], uv=True, normals=True)

    # colours: a smooth function of the position (check_mesh --color-fn checks it)
    for name in ("elephant.off", "sphere.off"):
        pts, faces, _ = load(name)
        pts = normalised(pts)
        cols = [colour_of(p) for p in pts]
        base = name.replace(".off", "")
        write_ply(o(base + "_colorfn_uchar_rgba_binary_le.ply"), pts, faces, fmt="binary_little_endian",
                  cols=cols, alpha=True)
        write_ply(o(base + "_colorfn_float_rgb.ply"), pts, faces, cols=cols, color_type="float")
        write_off(o(base + "_colorfn.off"), pts, faces, cols=cols)


if __name__ == "__main__":
    main()
