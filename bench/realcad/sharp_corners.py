#!/usr/bin/env python3
"""Is a surface mesh's worst element limited by the geometry? (issue 16)

For every quad or triangle of a surface mesh (.vtu written by
`cooperage mesh F --dim 2`) whose scaled Jacobian is below FLOOR (0.2),
take its worst corner and the angle the face itself has at that node: the
sum of the corner angles of all elements of the same surface (block_id)
around it. Where that angle is below asin(FLOOR) (11.5 degrees for 0.2), no
element there can reach FLOOR -- one element spanning the corner has
scaled Jacobian sin(angle) at best -- so the element is limited by the
geometry; otherwise the mesher could have done better. Computed from the
mesh alone, independent of the program's own report. Elements that touch
such a corner node are counted "at" it; those within two rings of
elements of it, "near" it (a wedge of a few degrees squeezes the first
rings too); the rest "elsewhere" are the mesher's to improve.

  /usr/bin/python3 bench/realcad/sharp_corners.py OUT.vtu [--floor 0.2]
"""
import argparse
import math
from collections import defaultdict

import meshio
import numpy as np


def corner_angles(p, ring):
    """Angle (radians) and sine-based scaled Jacobian at each corner."""
    n = len(ring)
    out = []
    for i in range(n):
        a, b, c = p[ring[i]], p[ring[(i + 1) % n]], p[ring[(i - 1) % n]]
        u, v = b - a, c - a
        lu, lv = np.linalg.norm(u), np.linalg.norm(v)
        if lu == 0 or lv == 0:
            out.append((0.0, 0.0))
            continue
        cosang = float(np.clip(np.dot(u, v) / (lu * lv), -1, 1))
        out.append((math.acos(cosang), math.sqrt(max(0.0, 1 - cosang * cosang))))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("--floor", type=float, default=0.2)
    args = ap.parse_args()
    m = meshio.read(args.mesh)
    p = m.points
    elems = []  # (surface, ring, scaled jacobian)
    for bi, block in enumerate(m.cells):
        if block.type not in ("quad", "triangle"):
            continue
        sid = m.cell_data["block_id"][bi]
        sj = m.cell_data["scaled_jacobian"][bi]
        for k, ring in enumerate(block.data):
            elems.append((int(sid[k]), [int(x) for x in ring], float(sj[k]), block.type))
    # The face's angle at a node: the sum of its elements' corner angles.
    total = defaultdict(float)
    for sid, ring, _, _ in elems:
        for i, (ang, _) in enumerate(corner_angles(p, ring)):
            total[(sid, ring[i])] += ang
    limit = math.radians(math.degrees(math.asin(min(1.0, args.floor))))
    # Node neighbours within each surface, for the rings around a corner.
    nbrs = defaultdict(set)
    for sid, ring, _, _ in elems:
        for a in ring:
            nbrs[(sid, a)].update(ring)
    sharp = {key: ang for key, ang in total.items() if ang < limit}

    def rings_from_sharp(sid, ring):
        """0 when the element has a sharp corner node, 1 or 2 for the rings
        around one, None farther."""
        frontier = {(sid, a) for a in ring}
        seen = set(frontier)
        for dist in range(3):
            if any(k in sharp for k in frontier):
                return dist
            nxt = set()
            for k in frontier:
                nxt.update((sid, b) for b in nbrs[k])
            frontier = nxt - seen
            seen |= frontier
        return None

    rows = []
    for sid, ring, sj, kind in elems:
        if sj < args.floor:
            rows.append((sid, sj, rings_from_sharp(sid, ring)))
    at = sum(1 for r in rows if r[2] == 0)
    near = sum(1 for r in rows if r[2] in (1, 2))
    print("%s: %d elements below %.2f: %d at a corner the face itself makes sharper than "
          "%.1f degrees (limited by geometry), %d within two rings of one, %d elsewhere"
          % (args.mesh, len(rows), args.floor, at, math.degrees(limit), near,
             len(rows) - at - near))
    by_surface = defaultdict(list)
    for r in rows:
        by_surface[r[0]].append(r)
    for sid in sorted(by_surface):
        rs = by_surface[sid]
        corners = sorted({round(math.degrees(a), 1) for (s2, _), a in sharp.items() if s2 == sid})
        print("  surface %d: %d below (min %.3f): %d at, %d near its sharp corners (%s deg), "
              "%d elsewhere" % (sid, len(rs), min(r[1] for r in rs),
                                sum(1 for r in rs if r[2] == 0),
                                sum(1 for r in rs if r[2] in (1, 2)),
                                ", ".join("%.1f" % a for a in corners) or "none",
                                sum(1 for r in rs if r[2] is None)))


if __name__ == "__main__":
    main()
