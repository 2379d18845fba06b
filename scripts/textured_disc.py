# Writes the textured-model figure's input: MESH.obj, a bumpy disc (radius 1, a few
# Gaussian bumps and dents) triangulated in RINGS concentric rings (ring k has 6k
# vertices), one texture coordinate per vertex, u = (x + 1) / 2, v = (y + 1) / 2, so
# without seams; and PNG, a SQUARES x SQUARES checkerboard of 512 x 512 pixels
# (plain Python: zlib and struct, no imaging library).
# Usage: python3 scripts/textured_disc.py MESH.obj PNG [RINGS [SQUARES]]
import math
import struct
import sys
import zlib

mesh_path, png_path = sys.argv[1], sys.argv[2]
rings = int(sys.argv[3]) if len(sys.argv) > 3 else 60
squares = int(sys.argv[4]) if len(sys.argv) > 4 else 8

bumps = [(0.35, 0.2, 0.28, 0.25), (-0.4, 0.3, 0.22, -0.18), (0.05, -0.45, 0.3, 0.2), (-0.3, -0.25, 0.15, 0.12)]
def height(x, y):
    return sum(a * math.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s)) for cx, cy, s, a in bumps)

# the rings: ring k at radius k / rings, its 6k vertices at angles 2 pi j / 6k
# (shifted by half a step on odd rings so that the triangles are less regular)
ring_start, angles, points = [], [], []
for k in range(rings + 1):
    n = max(1, 6 * k)
    ring_start.append(len(points))
    shift = 0.5 if k % 2 else 0.0
    ring_angles = [2 * math.pi * (j + shift) / n for j in range(n)]
    angles.append(ring_angles)
    r = k / rings
    points += [(r * math.cos(a), r * math.sin(a)) for a in ring_angles]
# triangles between ring k - 1 and ring k: walk both rings by angle
faces = []
for k in range(1, rings + 1):
    inner, outer = angles[k - 1], angles[k]
    ni, no = len(inner), len(outer)
    base_i, base_o = ring_start[k - 1], ring_start[k]
    if ni == 1:
        faces += [(base_i, base_o + j, base_o + (j + 1) % no) for j in range(no)]
        continue
    i = j = 0
    while i < ni or j < no:
        # the next angle on each ring, unwrapped past 2 pi
        next_i = inner[(i + 1) % ni] + (2 * math.pi if i + 1 >= ni else 0)
        next_o = outer[(j + 1) % no] + (2 * math.pi if j + 1 >= no else 0)
        if j < no and (i >= ni or next_o <= next_i):
            faces.append((base_i + i % ni, base_o + j % no, base_o + (j + 1) % no))
            j += 1
        else:
            faces.append((base_i + i % ni, base_o + j % no, base_i + (i + 1) % ni))
            i += 1

with open(mesh_path, "w") as out:
    out.write("# bumpy disc, %d rings: %d vertices, %d triangles, uv = ((x + 1) / 2, (y + 1) / 2)\n"
              % (rings, len(points), len(faces)))
    for x, y in points:
        out.write("v %.6f %.6f %.6f\n" % (x, y, height(x, y)))
    for x, y in points:
        out.write("vt %.6f %.6f\n" % ((x + 1) / 2, (y + 1) / 2))
    for f in faces:
        out.write("f %s\n" % " ".join("%d/%d" % (v + 1, v + 1) for v in f))

# the checkerboard: RGB, 8 bits, no interlace, one filter byte (none) per row
size = 512
dark, light = bytes((40, 70, 160)), bytes((245, 225, 120))
rows = b"".join(b"\0" + b"".join(dark if (x * squares // size + y * squares // size) % 2 else light
                                 for x in range(size)) for y in range(size))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
with open(png_path, "wb") as out:
    out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
              + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
print("%s: %d vertices, %d triangles" % (mesh_path, len(points), len(faces)), file=sys.stderr)
