#!/usr/bin/env python3
"""Independent reader and checker for OFF / OBJ / PLY (ascii, binary LE/BE) / STL
(ascii, binary) meshes.  Written for the range_space_remesh hostile corpus; shares no
code with the program under test.

  check_mesh.py FILE [--expect-closed] [--color-fn] [--json]

Prints one JSON object: counts, whether every edge has 1 or 2 faces with consistent
orientation (2-manifold edges), non-manifold vertices, whether closed (no border
edges), total area, components, colours, and 'valid' (parsed, >= 1 face, indices in
range, finite coordinates, 2-manifold edges consistently oriented, no non-manifold
vertex, no degenerate index repetition).  STL is merged on exact float coordinates
before the topology check (an STL file has no connectivity).

--expect-closed: 'valid' also needs no border edge.
--color-fn: the file's vertex colours must follow the corpus colour function of the
            position (see colour_of), within 0.06 per channel, at every vertex.

Exit status 0 if valid, 1 if not, 3 if the file cannot be parsed.
"""
import json
import math
import struct
import sys
from collections import defaultdict


class ParseError(Exception):
    pass


# ----------------------------------------------------------------------------- readers

def _floats(tokens):
    return [float(t) for t in tokens]


def read_off(data):
    text = data.decode("latin-1")
    lines = []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if line:
            lines.append(line)
    if not lines:
        raise ParseError("empty OFF")
    head = lines[0].split()
    kw = head[0]
    if "OFF" not in kw:
        raise ParseError("no OFF keyword")
    rest_tokens = head[1:]
    li = 1
    has_c = "C" in kw.replace("OFF", "")
    has_n = kw.startswith("N") or "NOFF" in kw or kw.startswith("CNOFF") or kw.startswith("NCOFF")
    has_st = "ST" in kw
    four = "4" in kw
    ndim = 3
    if kw.startswith("n") or "nOFF" in kw:
        if not rest_tokens:
            rest_tokens = lines[li].split(); li += 1
        ndim = int(rest_tokens[0]); rest_tokens = rest_tokens[1:]
    if four:
        ndim += 1
    tokens = list(rest_tokens)
    while len(tokens) < 3:
        if li >= len(lines):
            raise ParseError("truncated OFF header")
        tokens += lines[li].split(); li += 1
    nv, nf = int(float(tokens[0])), int(float(tokens[1]))
    if nv < 0 or nf < 0:
        raise ParseError("negative OFF counts")
    if nv > len(lines) or nf > len(lines):
        raise ParseError("OFF counts larger than the file")
    pts, cols = [], []
    for i in range(nv):
        if li >= len(lines):
            raise ParseError("truncated OFF vertices")
        t = lines[li].split(); li += 1
        if len(t) < ndim:
            raise ParseError("short OFF vertex line")
        xyz = _floats(t[:3])
        if four:
            w = float(t[3])
            xyz = [c / w for c in xyz] if w != 0 else [float("nan")] * 3
        pts.append(xyz)
        extra = t[ndim:]
        if has_n:
            extra = extra[3:]
        if has_c and len(extra) >= 3:
            c = _floats(extra[:3])
            if any(v > 1.0 for v in c):
                c = [v / 255.0 for v in c]
            cols.append(c)
    faces = []
    for i in range(nf):
        if li >= len(lines):
            raise ParseError("truncated OFF faces")
        t = lines[li].split(); li += 1
        k = int(t[0])
        if k < 0 or len(t) < k + 1:
            raise ParseError("bad OFF face line")
        faces.append([int(x) for x in t[1:k + 1]])
    return pts, faces, (cols if has_c and len(cols) == nv else None)


def read_obj(data):
    text = data.decode("latin-1")
    pts, faces = [], []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        t = line.split()
        if t[0] == "v":
            pts.append(_floats(t[1:4]))
        elif t[0] == "f":
            f = []
            for w in t[1:]:
                i = int(w.split("/")[0])
                if i < 0:
                    i = len(pts) + i
                else:
                    i = i - 1
                f.append(i)
            faces.append(f)
    return pts, faces, None


PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply(data):
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ParseError("not a PLY / no end_header")
    nl = data.find(b"\n", end)
    if nl < 0:
        raise ParseError("no newline after end_header")
    header = data[:end].decode("latin-1").splitlines()
    body = data[nl + 1:]
    fmt = None
    elements = []
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            n = int(t[2])
            if n < 0:
                raise ParseError("negative element count")
            elements.append([t[1], n, []])
        elif t[0] == "property":
            if not elements:
                raise ParseError("property before element")
            if t[1] == "list":
                elements[-1][2].append((t[4], "list", PLY_TYPES[t[2]], PLY_TYPES[t[3]]))
            else:
                elements[-1][2].append((t[2], "scalar", PLY_TYPES[t[1]], None))
    for name, n, props in elements:
        if n > len(body) + 1:
            raise ParseError("element count larger than the file")
    pts, faces, cols = [], [], []
    color_scale = None
    if fmt == "ascii":
        tokens = body.decode("latin-1").split()
        pos = 0

        def nxt():
            nonlocal pos
            if pos >= len(tokens):
                raise ParseError("truncated ascii PLY")
            pos += 1
            return tokens[pos - 1]

        def val(code):
            s = nxt()
            return float(s) if code in "fd" else int(s)
        reader = val
    elif fmt in ("binary_little_endian", "binary_big_endian"):
        endian = "<" if fmt == "binary_little_endian" else ">"
        off = 0

        def reader(code):
            nonlocal off
            size = struct.calcsize(code)
            if off + size > len(body):
                raise ParseError("truncated binary PLY")
            v = struct.unpack_from(endian + code, body, off)[0]
            off += size
            return v
    else:
        raise ParseError("unknown PLY format")
    for name, n, props in elements:
        for _ in range(n):
            rec = {}
            for pname, kind, c1, c2 in props:
                if kind == "list":
                    k = reader(c1)
                    if k < 0 or k > 1_000_000:
                        raise ParseError("absurd list length")
                    rec[pname] = [reader(c2) for _ in range(k)]
                else:
                    rec[pname] = reader(c1)
                    if name == "vertex" and pname in ("red", "green", "blue"):
                        color_scale = 255.0 if c1 in "BbHhIi" else 1.0
            if name == "vertex":
                pts.append([float(rec.get("x", float("nan"))), float(rec.get("y", float("nan"))),
                            float(rec.get("z", float("nan")))])
                if "red" in rec:
                    cols.append([rec["red"] / color_scale, rec["green"] / color_scale, rec["blue"] / color_scale])
            elif name == "face":
                lst = rec.get("vertex_indices", rec.get("vertex_index"))
                if lst is None:
                    raise ParseError("face without vertex_indices")
                faces.append([int(i) for i in lst])
    return pts, faces, (cols if cols and len(cols) == len(pts) else None)


def read_stl(data):
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            pts, faces = [], []
            for i in range(n):
                vals = struct.unpack_from("<12f", data, 84 + 50 * i)
                for k in range(3):
                    pts.append(list(vals[3 + 3 * k:6 + 3 * k]))
                faces.append([3 * i, 3 * i + 1, 3 * i + 2])
            return pts, faces, None
    text = data.decode("latin-1")
    if not text.lstrip().startswith("solid"):
        raise ParseError("neither binary STL (size mismatch) nor ascii STL")
    pts, faces, cur = [], [], []
    for line in text.splitlines():
        t = line.split()
        if t and t[0] == "vertex":
            pts.append(_floats(t[1:4]))
            cur.append(len(pts) - 1)
        elif t and t[0] == "endloop":
            if len(cur) != 3:
                raise ParseError("facet without 3 vertices")
            faces.append(cur)
            cur = []
    return pts, faces, None


def merge_points(pts, faces):
    index, newpts, remap = {}, [], []
    for p in pts:
        key = tuple(p)
        if key not in index:
            index[key] = len(newpts)
            newpts.append(p)
        remap.append(index[key])
    return newpts, [[remap[i] for i in f] for f in faces]


def read_mesh(path):
    with open(path, "rb") as fh:
        data = fh.read()
    ext = path.rsplit(".", 1)[-1].lower()
    if ext == "off":
        return read_off(data)
    if ext == "obj":
        return read_obj(data)
    if ext == "ply":
        return read_ply(data)
    if ext == "stl":
        return read_stl(data)
    raise ParseError("unknown extension")


# ----------------------------------------------------------------------------- analysis

def colour_of(p):
    """The corpus colour function: smooth in the position (bounding box [-1, 1]^3)."""
    x, y, z = p
    clamp = lambda v: min(1.0, max(0.0, v))
    return [clamp(0.5 + 0.5 * x), clamp(0.5 + 0.5 * y), clamp(0.5 + 0.5 * z)]


def tri_area(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return 0.5 * math.sqrt(w[0] ** 2 + w[1] ** 2 + w[2] ** 2)


def analyse(pts, faces, cols=None, merged=False):
    r = {"vertices": len(pts), "faces": len(faces), "merged_on_coordinates": merged}
    deg = defaultdict(int)
    for f in faces:
        deg[len(f)] += 1
    r["face_degrees"] = {str(k): v for k, v in sorted(deg.items())}
    r["finite"] = all(math.isfinite(c) for p in pts for c in p)
    bad_index = any(i < 0 or i >= len(pts) for f in faces for i in f)
    r["indices_in_range"] = not bad_index
    r["short_faces"] = sum(1 for f in faces if len(f) < 3)
    r["repeated_index_faces"] = sum(1 for f in faces if len(set(f)) != len(f))
    if bad_index:
        r["valid"] = False
        r["why"] = "index out of range"
        return r
    used = set(i for f in faces for i in f)
    r["unreferenced_vertices"] = len(pts) - len(used)
    # directed edges
    directed = defaultdict(int)
    undirected = defaultdict(list)
    for fi, f in enumerate(faces):
        k = len(f)
        for j in range(k):
            a, b = f[j], f[(j + 1) % k]
            directed[(a, b)] += 1
            undirected[(min(a, b), max(a, b))].append(fi)
    border = nonman = misoriented = 0
    for (a, b), fl in undirected.items():
        n = len(fl)
        if n == 1:
            border += 1
        elif n == 2:
            if directed.get((a, b), 0) != 1 or directed.get((b, a), 0) != 1:
                misoriented += 1
        else:
            nonman += 1
    r["edges"] = len(undirected)
    r["border_edges"] = border
    r["non_manifold_edges"] = nonman
    r["misoriented_edges"] = misoriented
    r["duplicate_faces"] = len(faces) - len(set(tuple(sorted(f)) for f in faces))
    # non-manifold vertices: the faces around a vertex must form one fan (connected
    # through edges incident to the vertex)
    around = defaultdict(list)
    for fi, f in enumerate(faces):
        for v in set(f):
            around[v].append(fi)
    nm_vertices = 0
    for v, fl in around.items():
        if len(fl) <= 1:
            continue
        parent = {fi: fi for fi in fl}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        by_edge = defaultdict(list)
        for fi in fl:
            f = faces[fi]
            k = len(f)
            for j in range(k):
                if f[j] == v:
                    for w in (f[(j + 1) % k], f[(j - 1) % k]):
                        by_edge[w].append(fi)
        for w, group in by_edge.items():
            for g in group[1:]:
                parent[find(g)] = find(group[0])
        if len(set(find(fi) for fi in fl)) > 1:
            nm_vertices += 1
    r["non_manifold_vertices"] = nm_vertices
    # components (faces through shared vertices)
    parent = list(range(len(pts)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for f in faces:
        for i in f[1:]:
            a, b = find(f[0]), find(i)
            if a != b:
                parent[a] = b
    r["components"] = len(set(find(i) for i in used))
    # area (polygons fanned), degenerate triangles
    area = 0.0
    zero = 0
    for f in faces:
        a = 0.0
        for j in range(1, len(f) - 1):
            a += tri_area(pts[f[0]], pts[f[j]], pts[f[j + 1]])
        if a == 0.0:
            zero += 1
        area += a
    r["area"] = area
    r["zero_area_faces"] = zero
    if pts:
        lo = [min(p[i] for p in pts) for i in range(3)]
        hi = [max(p[i] for p in pts) for i in range(3)]
        r["bbox"] = [lo, hi]
    r["euler"] = len(used) - len(undirected) + len(faces)
    r["closed"] = border == 0 and len(faces) > 0
    r["two_manifold_edges"] = nonman == 0 and misoriented == 0
    r["has_colors"] = cols is not None
    # orientable after re-orienting faces (per component, ignoring non-manifold edges)?
    r["orientable"] = orientable(faces, undirected) if nonman == 0 else False
    why = []
    if not faces:
        why.append("no face")
    if not r["finite"]:
        why.append("non-finite coordinate")
    if r["short_faces"]:
        why.append("face with < 3 corners")
    if r["repeated_index_faces"]:
        why.append("face repeating a vertex")
    if nonman:
        why.append("%d non-manifold edges" % nonman)
    if misoriented:
        why.append("%d misoriented edges" % misoriented)
    if nm_vertices:
        why.append("%d non-manifold vertices" % nm_vertices)
    r["valid"] = not why
    r["why"] = "; ".join(why)
    return r


def orientable(faces, undirected):
    """Whether flipping some faces makes every 2-face edge consistently oriented."""
    sign = [0] * len(faces)
    adj = defaultdict(list)
    for (a, b), fl in undirected.items():
        if len(fl) == 2:
            f, g = fl
            # same direction of (a, b) in both faces -> they must have opposite signs
            def dirn(fi):
                ff = faces[fi]
                k = len(ff)
                for j in range(k):
                    if ff[j] == a and ff[(j + 1) % k] == b:
                        return 1
                    if ff[j] == b and ff[(j + 1) % k] == a:
                        return -1
                return 0
            same = dirn(f) == dirn(g)
            adj[f].append((g, -1 if same else 1))
            adj[g].append((f, -1 if same else 1))
    for s in range(len(faces)):
        if sign[s]:
            continue
        sign[s] = 1
        stack = [s]
        while stack:
            f = stack.pop()
            for g, rel in adj[f]:
                want = sign[f] * rel
                if sign[g] == 0:
                    sign[g] = want
                    stack.append(g)
                elif sign[g] != want:
                    return False
    return True


def check(path, expect_closed=False, color_fn=False):
    try:
        pts, faces, cols = read_mesh(path)
    except (ParseError, ValueError, IndexError, KeyError, struct.error, OverflowError) as e:
        return {"file": path, "parsed": False, "valid": False, "why": "parse error: %s" % e}
    merged = path.lower().endswith(".stl")
    if merged:
        pts, faces = merge_points(pts, faces)
    r = analyse(pts, faces, cols, merged)
    r["file"] = path
    r["parsed"] = True
    if expect_closed and r.get("valid") and not r["closed"]:
        r["valid"] = False
        r["why"] = "%d border edges although the input was closed" % r["border_edges"]
    if color_fn:
        if cols is None:
            r["valid"] = False
            r["why"] = (r["why"] + "; " if r["why"] else "") + "no vertex colours"
        else:
            worst = 0.0
            for p, c in zip(pts, cols):
                want = colour_of(p)
                worst = max(worst, max(abs(want[i] - c[i]) for i in range(3)))
            r["color_max_error"] = worst
            if worst > 0.06:
                r["valid"] = False
                r["why"] = (r["why"] + "; " if r["why"] else "") + "vertex colours off by %.3f" % worst
    return r


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        print(__doc__)
        return 2
    r = check(args[0], "--expect-closed" in argv, "--color-fn" in argv)
    print(json.dumps(r))
    if not r.get("parsed"):
        return 3
    return 0 if r["valid"] else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
