#!/usr/bin/python3
"""Reads a surface mesh (.obj .off .stl .ply) back with meshio for the
surface exporter tests.

usage: surface_readback.py FILE

Prints one fact per line:
  NODES n | CELLS type n | P x y z (each point) | F i j k [l] (each face, as
  point indices) | VOLUME v (the volume the faces enclose, by the divergence
  theorem: positive when they face outward, meaningful for a closed surface)
Exit status 3 when meshio is missing (the test skips), 1 on an error.
"""
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # pragma: no cover
    print("MISSING", e)
    sys.exit(3)


def read_off(path):
    words = open(path).read().split()
    assert words[0] == "OFF", words[0]
    n_points, n_faces = int(words[1]), int(words[2])
    at = 4
    pts = np.array(words[at:at + 3 * n_points], float).reshape(-1, 3)
    at += 3 * n_points
    cells = {}
    for _ in range(n_faces):
        k = int(words[at])
        cells.setdefault({3: "triangle", 4: "quad"}[k], []).append(
            [int(w) for w in words[at + 1:at + 1 + k]])
        at += 1 + k
    return pts, [(t, np.array(c)) for t, c in cells.items()]


def main():
    path = sys.argv[1]
    try:
        m = meshio.read(path)
        pts, blocks = np.asarray(m.points, float), [(b.type, b.data) for b in m.cells]
        print("READER meshio")
    except (Exception, SystemExit):  # noqa: BLE001 (meshio exits on a file it cannot read)
        if not path.endswith(".off"):
            raise
        pts, blocks = read_off(path)
        print("READER off-parser")
    print("NODES", len(pts))
    volume = 0.0
    for kind, data in blocks:
        print("CELLS", kind, len(data))
        for face in data:
            print("F", *face)
            p = pts[face]
            for k in range(1, len(face) - 1):  # fan of triangles about corner 0
                volume += np.dot(p[0], np.cross(p[k], p[k + 1])) / 6.0
    for p in pts:
        print("P", *("%.9g" % c for c in p))
    print("VOLUME", "%.9g" % volume)


if __name__ == "__main__":
    main()
