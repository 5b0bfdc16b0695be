#!/usr/bin/python3
"""Which surfaces of a --dim 2 mesh stay below a scaled Jacobian of 0.2, and
whether their sharpest corner explains it (issue 16).

usage: bench/realcad/corner_bounds.py --bin BUILD/bin/cooperage [--div 40] FILE ...

No element at a corner of interior angle a can have a scaled Jacobian above
sin(a) (a quad's corner sine; a triangle's is scaled by 2/sqrt(3)), so a face
with a 3-degree corner cannot reach 0.2 by any mesh. For each file, meshed as
run_realcad.py does (`cooperage mesh F --size D/DIV --dim 2`), this prints every
surface whose worst element is below 0.2 with its sharpest corner
(`cooperage info --json`, "sharpest_corner") and "at bound" when the worst
element is within 10 % of min(0.2, bound), "BELOW" otherwise: the faces where
the mesher, not the geometry, is the limit. Per-surface minima are the run's
own quality table (printed on stdout when it is not a terminal).

A face below its corner's bound is also measured against its boundary as
meshed: at a boundary node where the polygon of curve nodes has interior
angle a (the sum of the angles its elements make there), some element has a
corner of at most a, so no mesh of that boundary does better than sin(a).
The chords of a curved corner can meet far sharper than its tangents. Such
a face is "at its boundary's bound": finer curve nodes near the corner, not
a better interior, would raise it.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_realcad import DEFAULT_FOLDER, diagonal, info  # noqa: E402


def boundary_corners(msh):
    """Per surface (the .msh's geometrical tags), the smallest interior angle
    [degrees] of its meshed boundary: at each node on an edge that only one
    of the surface's elements uses, the sum of the angles its elements make
    there."""
    import meshio
    m = meshio.read(msh)
    pts = m.points
    angle_sum = {}  # (surface, node) -> sum of element angles
    edge_use = {}   # (surface, node, node) -> elements using the edge
    for block, tags in zip(m.cells, m.cell_data["gmsh:geometrical"]):
        if block.type not in ("triangle", "quad"):
            continue
        cells = block.data
        k = cells.shape[1]
        for c in range(k):
            a, b, d = cells[:, c], cells[:, (c + 1) % k], cells[:, (c - 1) % k]
            u, v = pts[b] - pts[a], pts[d] - pts[a]
            cos = np.einsum("ij,ij->i", u, v) / (
                np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1) + 1e-300)
            ang = np.degrees(np.arccos(np.clip(cos, -1, 1)))
            for t, n, g in zip(tags, a, ang):
                angle_sum[(t, n)] = angle_sum.get((t, n), 0.0) + g
            for t, x, y in zip(tags, a, b):
                key = (t, min(x, y), max(x, y))
                edge_use[key] = edge_use.get(key, 0) + 1
    out = {}
    for (t, x, y), n in edge_use.items():
        if n != 1:
            continue
        for node in (x, y):
            out[int(t)] = min(out.get(int(t), 360.0), angle_sum[(t, node)])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--div", type=float, default=40.0)
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.files:
            path = name if os.path.exists(name) else os.path.join(DEFAULT_FOLDER, name)
            model = info(args.bin, path)
            if model is None:  # no solid (a surface model): run_realcad.py reports it
                print("%s: no model (`cooperage info` fails)" % os.path.basename(path))
                continue
            corner = {s["id"]: (s["sharpest_corner"] or {"degrees": 360.0})["degrees"]
                      for s in model["surfaces"]}
            out = os.path.join(tmp, "out.msh")
            r = subprocess.run([args.bin, "mesh", path, "--size", repr(diagonal(model) / args.div),
                                "--dim", "2", "-o", out],
                               capture_output=True, text=True, timeout=600)
            polygon = boundary_corners(out) if r.returncode == 0 else {}
            worst = {}  # surface -> (min SJ, element type)
            for line in r.stdout.splitlines():
                t = line.split()
                if len(t) > 5 and t[0] == "surface":
                    worst[int(t[1])] = min(worst.get(int(t[1]), (2.0, "")), (float(t[5]), t[3]))
            at_bound = at_boundary = below = 0
            for sid, (sj, kind) in sorted(worst.items()):
                if sj >= 0.2:
                    continue
                a = corner.get(sid, 360.0)
                bound = 1.0 if a >= 90 else math.sin(math.radians(a)) * (2 / math.sqrt(3) if kind == "tri" else 1)
                ok = sj >= 0.9 * min(0.2, bound)
                p = polygon.get(sid, 180.0)
                scale = 2 / math.sqrt(3) if kind == "tri" else 1
                pbound = 1.0 if p >= 90 else math.sin(math.radians(p)) * scale
                at_polygon = not ok and sj >= 0.9 * min(0.2, pbound)
                at_bound += ok
                at_boundary += at_polygon
                below += not ok and not at_polygon
                verdict = "at bound" if ok else "at its boundary's bound" if at_polygon else "BELOW"
                print("%s surface %d: %s worst %.3f, sharpest corner %.1f degrees (bound %.3f), "
                      "boundary polygon %.1f degrees (bound %.3f) %s"
                      % (os.path.basename(path), sid, kind, sj, a, bound, p, pbound, verdict))
            print("%s: exit %d; surfaces below 0.2: %d at their corner's bound, %d at their "
                  "boundary's, %d below both"
                  % (os.path.basename(path), r.returncode, at_bound, at_boundary, below))


if __name__ == "__main__":
    main()
