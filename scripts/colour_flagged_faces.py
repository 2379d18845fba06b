# Writes INPUT.off as an ASCII PLY with its faces coloured: red where FLAGGED.off
# (the command-line program's --topology-report) has the same face, grey elsewhere.
import sys
def read_off(path):
    words = open(path).read().split()
    assert words[0].endswith("OFF")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = [tuple(words[at + 3 * i: at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(x) for x in words[at + 1: at + 1 + n]])
        at += 1 + n
    return points, faces
points, faces = read_off(sys.argv[1])
flagged_points, flagged_faces = read_off(sys.argv[2])
key = lambda pts, f: frozenset(tuple(float(c) for c in pts[i]) for i in f)
flagged = {key(flagged_points, f) for f in flagged_faces}
with open(sys.argv[3], "w") as out:
    out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
              "property uchar blue\nend_header\n" % (len(points), len(faces)))
    for p in points:
        out.write(" ".join(p) + "\n")
    for f in faces:
        colour = "220 40 30" if key(points, f) in flagged else "217 217 204"
        out.write("%d %s %s\n" % (len(f), " ".join(map(str, f)), colour))
print(sum(key(points, f) in flagged for f in faces), "of", len(faces), "faces flagged", file=sys.stderr)
