#!/usr/bin/env python3
"""Generates the hostile inputs of the range_space_remesh corpus into hostile/, and
hostile/EXPECT.tsv: one line per file,

    name <TAB> expect <TAB> flags <TAB> note

expect:  accept  - a usable mesh: should exit 0 with a valid output
         refuse  - unusable: should exit 2 with one line on stderr and no output
         any     - either, but cleanly (no crash, hang, balloon, wrong file)
flags:   comma-separated: closed (output must be closed), colorfn (output colours
         must follow check_mesh.colour_of), same_as=NAME (output must equal the
         output of NAME: same counts and area), '-' for none.
Deterministic (fixed seeds)."""
import math
import os
import random
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_mesh import read_mesh, colour_of  # noqa: E402

OUT = os.path.join(HERE, "hostile")
CGAL = os.path.join(HERE, "cgal", "data", "meshes")
EXPECT = []


def put(name, data, expect, note, flags="-"):
    path = os.path.join(OUT, name)
    with open(path, "wb") as fh:
        fh.write(data if isinstance(data, bytes) else data.encode("latin-1"))
    EXPECT.append((name, expect, flags, note))


# ----------------------------------------------------------------------------- shapes

OCTA_P = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCTA_F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
TETRA_P = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
TETRA_F = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
CUBE_P = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
CUBE_Q = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]


def cube_tris():
    t = []
    for a, b, c, d in CUBE_Q:
        t += [(a, b, c), (a, c, d)]
    return t


def sphere(n_lat=16, n_lon=24):
    pts = [(0, 0, 1)]
    for i in range(1, n_lat):
        th = math.pi * i / n_lat
        for j in range(n_lon):
            ph = 2 * math.pi * j / n_lon
            pts.append((math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)))
    pts.append((0, 0, -1))
    faces = []
    ring = lambda i, j: 1 + (i - 1) * n_lon + (j % n_lon)
    for j in range(n_lon):
        faces.append((0, ring(1, j), ring(1, j + 1)))
    for i in range(1, n_lat - 1):
        for j in range(n_lon):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            faces += [(a, b, c), (a, c, d)]
    s = len(pts) - 1
    for j in range(n_lon):
        faces.append((s, ring(n_lat - 1, j + 1), ring(n_lat - 1, j)))
    return pts, faces


def off_text(pts, faces, head="OFF", fmt="%r"):
    s = "%s\n%d %d 0\n" % (head, len(pts), len(faces))
    s += "".join(" ".join(fmt % float(c) for c in p) + "\n" for p in pts)
    s += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
    return s


def obj_text(pts, faces):
    s = "".join("v %r %r %r\n" % tuple(float(c) for c in p) for p in pts)
    s += "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in faces)
    return s


def ply_ascii(pts, faces, extra_vertex_props=(), vertex_extra=None, list_types="uchar int"):
    h = "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(pts)
    h += "".join("property %s\n" % p for p in extra_vertex_props)
    h += "element face %d\nproperty list %s vertex_indices\nend_header\n" % (len(faces), list_types)
    b = ""
    for i, p in enumerate(pts):
        b += " ".join(repr(float(c)) for c in p)
        if vertex_extra:
            b += " " + vertex_extra(i, p)
        b += "\n"
    b += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
    return h + b


def ply_binary(pts, faces, endian="<", declared=None, index="i", count="B"):
    fmt = declared or ("binary_little_endian" if endian == "<" else "binary_big_endian")
    tname = {"i": "int", "B": "uchar", "I": "uint"}[index]
    cname = {"B": "uchar", "i": "int", "I": "uint"}[count]
    h = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
         "element face %d\nproperty list %s %s vertex_indices\nend_header\n" % (fmt, len(pts), len(faces), cname, tname))
    b = b"".join(struct.pack(endian + "3f", *p) for p in pts)
    b += b"".join(struct.pack(endian + count + "%d%s" % (len(f), index), len(f), *f) for f in faces)
    return h.encode() + b


def stl_ascii(pts, faces, name="hostile"):
    s = "solid %s\n" % name
    for f in faces:
        s += "facet normal 0 0 0\n outer loop\n"
        for i in f:
            s += "  vertex %s\n" % " ".join(repr(float(c)) for c in pts[i])
        s += " endloop\nendfacet\n"
    return s + "endsolid %s\n" % name


def stl_binary(pts, faces, header=b"hostile", count=None, attr=0):
    b = header.ljust(80, b"\0")[:80] + struct.pack("<I", len(faces) if count is None else count)
    for f in faces:
        b += struct.pack("<12fH", 0, 0, 0, *pts[f[0]], *pts[f[1]], *pts[f[2]], attr)
    return b


# ----------------------------------------------------------------------------- cases

def main():
    os.makedirs(OUT, exist_ok=True)
    rnd = random.Random(20260517)
    sp, sf = sphere()

    # --- PLY -----------------------------------------------------------------------
    h = ("ply\nformat ascii 1.0\nelement face %d\nproperty list uchar int vertex_indices\n"
         "element vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n" % (len(OCTA_F), len(OCTA_P)))
    body = "".join("3 %d %d %d\n" % f for f in OCTA_F) + "".join("%r %r %r\n" % tuple(map(float, p)) for p in OCTA_P)
    put("ply_face_element_before_vertex.ply", h + body, "any", "face element declared and stored before the vertex element (legal PLY)")

    col = lambda i, p: " ".join("%.6f" % c for c in colour_of(p)) + " 1.0"
    put("ply_float_colors_rgba.ply", ply_ascii(sp, sf, ("float red", "float green", "float blue", "float alpha"), col),
        "accept", "vertex colours as float red green blue alpha in [0,1]", "closed,colorfn")
    colu = lambda i, p: " ".join(str(int(round(255 * c))) for c in colour_of(p))
    put("ply_uchar_colors.ply", ply_ascii(sp, sf, ("uchar red", "uchar green", "uchar blue"), colu),
        "accept", "vertex colours as uchar", "closed,colorfn")
    # unreferenced vertices interleaved in a coloured PLY: colours must stay on their vertices
    pts2, faces2, cols2 = [], [], []
    remap = {}
    for i, p in enumerate(sp):
        if i % 5 == 2:  # an unreferenced vertex, far away, with a wrong colour
            pts2.append((0.9, -0.9, 0.9))
        remap[i] = len(pts2)
        pts2.append(p)
    faces2 = [tuple(remap[i] for i in f) for f in sf]
    used = set(i for f in faces2 for i in f)
    colx = lambda i, p: (" ".join(str(int(round(255 * c))) for c in colour_of(p)) if i in used else "255 0 255")
    put("ply_unreferenced_vertices_colors.ply", ply_ascii(pts2, faces2, ("uchar red", "uchar green", "uchar blue"), colx),
        "accept", "every 5th vertex unreferenced (magenta, off the surface): colours must stay on the right vertices",
        "closed,colorfn")

    put("ply_list_int_int_1e9_ascii.ply",
        ply_ascii(OCTA_P, OCTA_F, list_types="int int").replace("3 0 2 4\n", "1000000000 1 2 3\n", 1),
        "refuse", "property list int int; a face line '1000000000 1 2 3' (must not allocate 10^9 indices)")
    b = ply_binary(OCTA_P, OCTA_F, count="i")
    hdr_end = b.index(b"end_header\n") + len(b"end_header\n")
    face0 = hdr_end + 12 * len(OCTA_P)
    b = b[:face0] + struct.pack("<i", 1000000000) + b[face0 + 4:]
    put("ply_list_int_int_1e9_binary.ply", b, "refuse", "binary LE, list count int = 10^9 on the first face")
    b2 = b[:face0] + struct.pack("<i", -7) + b[face0 + 4:]
    put("ply_list_count_negative_binary.ply", b2, "refuse", "binary LE, list count int = -7")

    txt = ply_ascii(OCTA_P, OCTA_F)
    put("ply_vertex_count_far_larger.ply", txt.replace("element vertex 6", "element vertex 300"), "refuse",
        "element vertex 300 but 6 vertex lines (count below the file size)")
    put("ply_face_count_1e12.ply", txt.replace("element face 8", "element face 1000000000000"), "refuse",
        "element face 10^12")
    put("ply_vertex_count_negative.ply", txt.replace("element vertex 6", "element vertex -12"), "refuse", "element vertex -12")
    put("ply_vertex_count_2pow32.ply", txt.replace("element vertex 6", "element vertex 4294967302"), "refuse",
        "element vertex 2^32+6 (wraps to 6 in 32 bits)")
    put("ply_property_before_element.ply", txt.replace("element vertex 6\n", "property float w\nelement vertex 6\n"),
        "refuse", "a property line before any element")
    put("ply_no_end_header.ply", txt.replace("end_header\n", ""), "refuse", "no end_header")
    put("ply_unknown_type.ply", txt.replace("property float z", "property float128 z"), "refuse", "unknown scalar type")
    put("ply_crlf.ply", txt.replace("\n", "\r\n"), "accept", "ascii PLY with CRLF line ends", "closed")
    put("ply_index_out_of_range.ply", txt.replace("3 0 2 4\n", "3 0 2 40\n", 1), "refuse", "face index 40 of 6 vertices")

    bun = read_mesh(os.path.join(CGAL, "bunny00.off"))
    ble = ply_binary(bun[0], bun[1], "<")
    put("ply_binary_le_declared_be.ply", ply_binary(bun[0], bun[1], "<", declared="binary_big_endian"), "refuse",
        "little-endian data under a binary_big_endian header (indices become huge)")
    put("ply_binary_be_declared_le.ply", ply_binary(bun[0], bun[1], ">", declared="binary_little_endian"), "refuse",
        "big-endian data under a binary_little_endian header")
    # byte-sized indices are endian-free: a valid connectivity with garbage coordinates
    sp_small, sf_small = sphere(8, 12)
    put("ply_wrong_endian_uchar_indices.ply",
        ply_binary(sp_small, sf_small, "<", declared="binary_big_endian", index="B"), "any",
        "LE floats read as BE (coordinates from 1e-40 to 1e+38, some NaN), uchar indices valid")
    for k, frac in enumerate((0.0005, 0.01, 0.2, 0.5, 0.77, 0.9, 0.999)):
        cut = int(len(ble) * frac)
        put("ply_binary_truncated_%02d.ply" % k, ble[:cut], "refuse", "bunny00 binary LE PLY cut at %.1f%% (%d bytes)" % (100 * frac, cut))
    asc = ply_ascii(bun[0], bun[1]).encode()
    for k, frac in enumerate((0.3, 0.6, 0.95, 0.99999)):
        cut = int(len(asc) * frac)
        put("ply_ascii_truncated_%02d.ply" % k, asc[:cut], "refuse", "bunny00 ascii PLY cut at %.3f%%" % (100 * frac))

    # --- OFF -----------------------------------------------------------------------
    oc = off_text(OCTA_P, OCTA_F)
    put("off_huge_degree.off", oc.replace("3 0 2 4\n", "1000000000 0 2 4\n", 1), "refuse", "face degree 10^9")
    put("off_degree_999999_many.off", "OFF\n6 2000 0\n" + "".join("%r %r %r\n" % tuple(map(float, p)) for p in OCTA_P)
        + "999999 0 1 2\n" * 2000, "refuse", "2000 faces of declared degree 999999 (just under the reader's check)")
    put("off_counts_scientific.off", oc.replace("6 8 0", "6e0 8e0 0"), "any", "counts written 6e0 8e0")
    put("off_counts_1e18.off", oc.replace("6 8 0", "1e18 8 0"), "refuse", "vertex count 10^18")
    put("off_count_negative.off", oc.replace("6 8 0", "6 -8 0"), "refuse", "face count -8")
    put("off_comments_everywhere.off",
        "# leading comment\nOFF # keyword comment\n\n# blank lines and comments\n6 8 0 # counts\n"
        + "".join("%r %r %r # vertex %d\n" % (*map(float, p), i) for i, p in enumerate(OCTA_P))
        + "# faces follow\n" + "".join("3 %d %d %d # face\n" % f for f in OCTA_F), "accept",
        "comments before the keyword, after tokens, blank lines", "closed")
    cols_i = lambda p: " ".join(str(int(round(255 * c))) for c in colour_of(p)) + " 255"
    put("coff_int_colors.off", "COFF\n%d %d 0\n" % (len(sp), len(sf))
        + "".join("%r %r %r %s\n" % (*map(float, p), cols_i(p)) for p in sp)
        + "".join("3 %d %d %d\n" % f for f in sf), "accept", "COFF, colours as ints 0-255 with alpha", "closed,colorfn")
    cols_f = lambda p: " ".join("%.6f" % c for c in colour_of(p)) + " 1.0"
    put("coff_float_colors.off", "COFF\n%d %d 0\n" % (len(sp), len(sf))
        + "".join("%r %r %r %s\n" % (*map(float, p), cols_f(p)) for p in sp)
        + "".join("3 %d %d %d\n" % f for f in sf), "accept", "COFF, colours as floats in [0,1] with alpha", "closed,colorfn")
    put("noff_normals.off", "NOFF\n6 8 0\n" + "".join("%r %r %r %r %r %r\n" % (*map(float, p), *map(float, p)) for p in OCTA_P)
        + "".join("3 %d %d %d\n" % f for f in OCTA_F), "accept", "NOFF with per-vertex normals", "closed")
    put("cnoff_normals_colors.off", "CNOFF\n6 8 0\n" + "".join("%r %r %r %r %r %r 0.5 0.5 0.5 1\n" % (*map(float, p), *map(float, p)) for p in OCTA_P)
        + "".join("3 %d %d %d\n" % f for f in OCTA_F), "any", "CNOFF (normals then colours)")
    put("4off_homogeneous.off", "4OFF\n6 8 0\n" + "".join("%r %r %r 2.0\n" % tuple(2.0 * c for c in p) for p in OCTA_P)
        + "".join("3 %d %d %d\n" % f for f in OCTA_F), "any", "4OFF: homogeneous coordinates (2x, w = 2): same as the octahedron",
        "same_as=off_octahedron.off")
    put("noff_dimension3.off", "nOFF\n3\n6 8 0\n" + "".join("%r %r %r\n" % tuple(map(float, p)) for p in OCTA_P)
        + "".join("3 %d %d %d\n" % f for f in OCTA_F), "any", "nOFF with dimension 3")
    put("noff_dimension5.off", "nOFF\n5\n6 8 0\n" + "".join("%r %r %r 7 8\n" % tuple(map(float, p)) for p in OCTA_P)
        + "".join("3 %d %d %d\n" % f for f in OCTA_F), "any", "nOFF with dimension 5")
    put("off_face_colors.off", oc.replace("3 0 2 4\n", "3 0 2 4 255 0 0\n").replace("3 2 1 4\n", "3 2 1 4 0.1 0.9 0.2 1\n"),
        "accept", "per-face colours (int and float) after the indices", "closed")
    put("off_binary_keyword.off", b"OFF BINARY\n" + struct.pack(">3i", 6, 8, 0)
        + b"".join(struct.pack(">3f", *p) for p in OCTA_P)
        + b"".join(struct.pack(">4i", 3, *f) + struct.pack(">i", 0) for f in OCTA_F), "any", "OFF BINARY (big-endian)")
    put("off_binary_huge_count.off", b"OFF BINARY\n" + struct.pack(">3i", 2000000000, 2000000000, 0) + b"\0" * 64,
        "refuse", "OFF BINARY with counts 2*10^9 (the text checks skip binary OFF)")
    put("off_nan.off", oc.replace("1.0 0.0 0.0", "nan 0.0 0.0", 1), "refuse", "a NaN coordinate")
    put("off_inf.off", oc.replace("1.0 0.0 0.0", "inf 0.0 0.0", 1), "refuse", "an infinite coordinate")
    put("off_1e308.off", off_text([tuple(1e308 * c for c in p) for p in OCTA_P], OCTA_F), "any",
        "octahedron of radius 1e308 (the bounding-box diagonal overflows)")
    put("off_1e308_and_tiny.off", off_text([tuple(1e308 * c for c in p) for p in OCTA_P] + [(0.0, 0.0, 1e-300)],
                                           OCTA_F + [(0, 2, 6)]), "any", "huge and tiny coordinates mixed; non-manifold too")
    put("off_1e300_radius.off", off_text([tuple(1e300 * c for c in p) for p in OCTA_P], OCTA_F), "accept",
        "octahedron of radius 1e300 (diagonal finite)", "closed")
    put("off_1e-300_radius.off", off_text([tuple(1e-300 * c for c in p) for p in OCTA_P], OCTA_F), "accept",
        "octahedron of radius 1e-300 (subnormal products)", "closed")
    put("off_offset_1e9.off", off_text([tuple(1e9 + 0.001 * c for c in p) for p in sp], sf), "any",
        "sphere of radius 0.001 centred at (1e9, 1e9, 1e9)")
    ele = read_mesh(os.path.join(CGAL, "elephant.off"))
    put("off_elephant_utm_offset.off", off_text([(p[0] + 500000.0, p[1] + 5000000.0, p[2] + 200.0) for p in ele[0]], ele[1]),
        "accept", "elephant (1.2 units across) at UTM-like coordinates (5e5, 5e6, 200), as scans are stored", "closed")
    put("off_elephant_offset_1e4.off", off_text([(p[0] + 10000.0, p[1], p[2]) for p in ele[0]], ele[1]),
        "accept", "elephant translated by 10^4", "closed")
    put("off_all_points_identical.off", off_text([(0.5, 0.5, 0.5)] * 6, OCTA_F), "refuse", "all points identical")
    put("off_collinear.off", off_text([(float(i), 2.0 * i, 3.0 * i) for i in range(6)], OCTA_F), "refuse",
        "all points on a line (every triangle degenerate)")
    put("off_single_triangle.off", off_text([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]), "any", "a single triangle")
    put("off_bowtie.off", off_text([(0, 0, 0), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)], [(0, 1, 2), (0, 3, 4)]),
        "any", "two triangles sharing only a vertex (non-manifold vertex)")
    put("off_nonmanifold_edge.off", off_text([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1)],
                                              [(0, 1, 2), (1, 0, 3), (0, 1, 4)]), "any", "three faces on one edge (a repair may cut it)")
    # Mobius strip
    n = 24
    mp = []
    for i in range(n):
        t = 2 * math.pi * i / n
        for s in (-0.3, 0.3):
            mp.append(((1 + s * math.cos(t / 2)) * math.cos(t), (1 + s * math.cos(t / 2)) * math.sin(t), s * math.sin(t / 2)))
    mf = []
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        if i < n - 1:
            c, d = 2 * i + 2, 2 * i + 3
        else:
            c, d = 1, 0  # the half twist
        mf += [(a, c, b), (b, c, d)]
    put("off_moebius.off", off_text(mp, mf), "any", "a Moebius strip (not orientable; a repair may cut it)")
    ct = cube_tris()
    flipped = list(ct)
    flipped[3] = flipped[3][::-1]
    put("off_cube_one_face_flipped.off", off_text(CUBE_P, flipped), "accept",
        "closed cube with one triangle's orientation flipped (repairable)", "closed")
    put("off_cube_duplicate_face.off", off_text(CUBE_P, ct + [ct[0]]), "any", "closed cube with one triangle twice")
    put("off_cube_degenerate_face.off", off_text(CUBE_P, ct + [(0, 0, 1)]), "any", "closed cube plus a face (0 0 1)")
    put("off_octahedron.off", off_text(OCTA_P, OCTA_F), "accept", "reference octahedron", "closed")
    put("off_octahedron_far_unreferenced.off", off_text(OCTA_P + [(1000.0, -2000.0, 3000.0)], OCTA_F), "accept",
        "octahedron plus one unreferenced far vertex: same result as the octahedron alone",
        "closed,same_as=off_octahedron.off")
    put("off_unreferenced_first.off", off_text([(50.0, 50.0, 50.0)] + OCTA_P, [tuple(i + 1 for i in f) for f in OCTA_F]),
        "accept", "the unreferenced vertex comes first (indices shift)", "closed,same_as=off_octahedron.off")
    put("off_truncated_header.off", "OFF\n6 8", "refuse", "header cut after two counts")
    put("off_truncated_mid.off", oc[: len(oc) * 2 // 3], "refuse", "cut at two thirds")
    put("off_no_keyword.off", oc[4:], "any", "counts without the OFF keyword")
    put("off_tetra_quads_nonplanar.off", off_text([(0, 0, 0), (1, 0, 0), (1, 1, 0.5), (0, 1, 0), (0.5, 0.5, 1.0)],
                                                  [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]),
        "accept", "pyramid whose base quad is non-planar", "closed")
    # polygons: a big planar polygon face closed by a fan
    k = 2000
    poly = [(math.cos(2 * math.pi * i / k), math.sin(2 * math.pi * i / k), 0.0) for i in range(k)] + [(0.0, 0.0, 1.0)]
    pf = [tuple(range(k - 1, -1, -1))] + [(i, (i + 1) % k, k) for i in range(k)]
    put("off_cone_2000gon_base.off", off_text(poly, pf), "accept", "cone with a 2000-corner base polygon", "closed")

    # --- OBJ -----------------------------------------------------------------------
    oo = obj_text(OCTA_P, OCTA_F)
    rel = "".join("v %r %r %r\n" % tuple(map(float, p)) for p in OCTA_P)
    rel += "".join("f %s\n" % " ".join(str(i - len(OCTA_P)) for i in f) for f in OCTA_F)
    put("obj_negative_indices.obj", rel, "accept", "relative (negative) indices", "closed,same_as=off_octahedron.off")
    mixed = rel.replace("f -6 -4 -2\n", "f 1/1/1 -4//-2 5/3\n")
    put("obj_slash_forms.obj", "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\n" + mixed, "accept",
        "f 1/1/1, -4//-2 and 5/3 forms mixed", "closed")
    put("obj_missing_vertex.obj", oo.replace("f 1 3 5\n", "f 1 3 50\n", 1), "refuse", "face refers to vertex 50 of 6")
    put("obj_index_zero.obj", oo.replace("f 1 3 5\n", "f 0 3 5\n", 1), "refuse", "face index 0")
    put("obj_huge_index.obj", oo.replace("f 1 3 5\n", "f 1 3 99999999999999999999\n", 1), "refuse", "index 10^20")
    put("obj_huge_negative_index.obj", oo.replace("f 1 3 5\n", "f 1 3 -99999999999\n", 1), "refuse", "index -10^11")
    put("obj_index_2pow32.obj", oo.replace("f 1 3 5\n", "f 1 3 4294967301\n", 1), "refuse", "index 2^32+5 (wraps to 5)")
    put("obj_1MB_comment_line.obj", "# " + "x" * (1 << 20) + "\n" + oo, "accept", "a 1 MB comment line", "closed")
    put("obj_1MB_v_line.obj", "v 1 2 3" + " 4" * (1 << 19) + "\n" + oo, "any", "a 1 MB 'v' line with 500k extra numbers")
    put("obj_1MB_garbage_line.obj", oo + "".join(rnd.choice("abcdefghij0123456789 ./-") for _ in range(1 << 20)) + "\n",
        "any", "a 1 MB line of garbage after the faces")
    kk = 100000
    circ = "".join("v %r %r 0\n" % (math.cos(2 * math.pi * i / kk), math.sin(2 * math.pi * i / kk)) for i in range(kk))
    circ += "v 0 0 1\nf %s\n" % " ".join(str(i) for i in range(kk, 0, -1))
    circ += "".join("f %d %d %d\n" % (i + 1, (i + 1) % kk + 1, kk + 1) for i in range(kk))
    put("obj_cone_100000gon_base.obj", circ, "any", "cone whose base is one 100,000-corner face (a 1.2 MB 'f' line)")
    kk = 300000
    circ = "".join("v %r %r 0\n" % (math.cos(2 * math.pi * i / kk), math.sin(2 * math.pi * i / kk)) for i in range(kk))
    circ += "v 0 0 1\nf %s\n" % " ".join(str(i) for i in range(kk, 0, -1))
    circ += "".join("f %d %d %d\n" % (i + 1, (i + 1) % kk + 1, kk + 1) for i in range(kk))
    put("obj_cone_300000gon_base.obj", circ, "any", "cone whose base is one 300,000-corner face (a 2 MB 'f' line, 22 MB file)")
    put("obj_nul_bytes.obj", oo.replace("v 0.0 1.0 0.0\n", "v 0.0 1.0\x00 0.0\n").encode("latin-1"), "any",
        "a NUL byte inside a 'v' line")
    put("obj_nul_prefix.obj", b"\x00" * 16 + oo.encode(), "any", "16 NUL bytes before the first line")
    put("obj_no_faces.obj", "".join("v %r %r %r\n" % tuple(map(float, p)) for p in OCTA_P), "refuse", "vertices only")
    put("obj_two_vertex_face.obj", oo + "f 1 2\n", "any", "a face of two vertices (a repair may drop it)")
    put("obj_nan.obj", oo.replace("v 1.0 0.0 0.0", "v nan 0.0 0.0"), "refuse", "a NaN coordinate")
    put("obj_inf.obj", oo.replace("v 1.0 0.0 0.0", "v -inf 0.0 0.0"), "refuse", "an infinite coordinate")
    put("obj_crlf_tabs.obj", oo.replace(" ", "\t").replace("\n", "\r\n"), "accept", "tabs and CRLF", "closed")
    put("obj_line_continuation.obj", oo.replace("f 1 3 5\n", "f 1 \\\n3 5\n", 1), "any", "a face split by a backslash continuation")
    put("obj_w_coordinate.obj", oo.replace("v 1.0 0.0 0.0", "v 1.0 0.0 0.0 1.0").replace("v -1.0 0.0 0.0", "v -1.0 0.0 0.0 0.5 0.5 0.5"),
        "accept", "v lines with w and with vertex colours", "closed")
    put("obj_two_components_groups.obj",
        "o A\n" + obj_text(OCTA_P, OCTA_F) + "o B\ng b\n"
        + "".join("v %r %r %r\n" % (p[0] + 5, p[1], p[2]) for p in TETRA_P)
        + "".join("f %s\n" % " ".join(str(i + 7) for i in f) for f in TETRA_F), "accept", "two objects", "closed")

    # --- STL -----------------------------------------------------------------------
    sb = stl_binary(sp, sf, header=b"solid sphere exported as binary with a 'solid' header")
    put("stl_binary_with_solid_header.stl", sb, "accept", "binary STL whose 80-byte header starts with 'solid' (SolidWorks does this)", "closed")
    put("stl_binary_count_huge.stl", stl_binary(sp, sf, count=4000000000), "accept",
        "binary STL declaring 4*10^9 triangles: its whole records are read, with a note", "closed")
    put("stl_binary_count_short.stl", stl_binary(sp, sf, count=len(sf) // 2), "any", "binary STL declaring half its triangles")
    put("stl_binary_trailing_bytes.stl", stl_binary(sp, sf) + b"\0" * 37, "any", "binary STL with 37 trailing bytes")
    put("stl_binary_truncated.stl", stl_binary(sp, sf)[:-77], "refuse", "binary STL cut 77 bytes short")
    put("stl_binary_empty_solid.stl", stl_binary([], [], header=b"solid empty"), "refuse", "binary STL of 0 triangles")
    sa = stl_ascii(sp, sf)
    put("stl_ascii_ok_sphere.stl", sa, "accept", "reference ascii STL sphere", "closed")
    put("stl_ascii_no_solid_header.stl", sa.replace("solid hostile\n", "", 1), "any", "ascii facets without the 'solid' line")
    put("stl_ascii_truncated.stl", sa[: len(sa) // 2], "any", "ascii STL cut in the middle of a facet")
    put("stl_ascii_nan.stl", sa.replace("vertex 0.0 0.0 1.0", "vertex nan 0.0 1.0", 1), "refuse", "a NaN vertex")
    put("stl_ascii_inf.stl", sa.replace("vertex 0.0 0.0 1.0", "vertex inf 0.0 1.0", 1), "refuse", "an infinite vertex")
    nanb = stl_binary(sp, sf)
    nanb = nanb[:84 + 12] + struct.pack("<f", float("nan")) + nanb[84 + 16:]
    put("stl_binary_nan.stl", nanb, "refuse", "binary STL with a NaN vertex coordinate")
    put("stl_ascii_four_vertex_facet.stl", sa.replace("  vertex 0.0 0.0 1.0\n", "  vertex 0.0 0.0 1.0\n  vertex 0.5 0.5 0.5\n", 1),
        "any", "a facet with four vertices")
    put("stl_ascii_1e308.stl", stl_ascii([tuple(1e308 * c for c in p) for p in OCTA_P], OCTA_F), "any", "octahedron of radius 1e308")
    put("stl_inconsistent_orientation.stl", stl_ascii(CUBE_P, [f if k % 3 else f[::-1] for k, f in enumerate(cube_tris())]),
        "accept", "cube soup with every third triangle reversed (repairable)", "closed")
    put("stl_two_cubes_sharing_edge.stl", stl_ascii(CUBE_P + [(x + 2, y + 2, z) for x, y, z in CUBE_P],
                                                    cube_tris() + [tuple(i + 8 for i in f) for f in cube_tris()]),
        "any", "two cubes touching along an edge (non-manifold edge)")

    # --- any extension ---------------------------------------------------------------
    for ext in ("off", "obj", "ply", "stl"):
        put("empty.%s" % ext, b"", "refuse", "empty file")
        put("random_bytes.%s" % ext, bytes(rnd.randrange(256) for _ in range(4096)), "refuse", "4 KB of random bytes")
        put("whitespace_only.%s" % ext, b" \n\t\n   \r\n", "refuse", "only whitespace")
    put("uppercase_extension.OFF", off_text(OCTA_P, OCTA_F), "accept", "extension in capitals", "closed")

    with open(os.path.join(OUT, "EXPECT.tsv"), "w") as fh:
        fh.write("# name\texpect\tflags\tnote\n")
        for row in EXPECT:
            fh.write("\t".join(row) + "\n")
    print("%d hostile files in %s" % (len(EXPECT), OUT))


if __name__ == "__main__":
    main()
