#!/usr/bin/python3
"""Real CAD made by other people (../shared/real-cad, issue 16): mesh every file
as a new user would and check each mesh independently.

usage: bench/realcad/run_realcad.py --bin BUILD/bin/cooperage [--dim 3|2]
           [--div 40] [--timeout 120] [--must-mesh] [FILE ...]

For each file F (default: every .step/.stp/.brep of the folder):
  cooperage mesh F --size D/DIV --dim DIM -o OUT.vtu --threads 1
with D the diagonal of the bounding box of all volumes (of all surfaces in
a surface model; `cooperage info --json`). A run counts as meshed when it exits 0 AND the .vtu passes this
script's own checks, read with meshio (not Cooperage's readers):
  3D: only hexes (or wedges), every corner Jacobian positive, no element face
      in more than two elements, a closed boundary, the meshed volume within
      1 % of the CAD's (sum over volumes from `info --json`);
  2D: only quads and triangles, every element of positive area, the meshed
      area within 2 % of the CAD's surface area (faceting of curved faces at
      D/40 stays well below that).
Prints one Markdown table row per file (file, result or first error line,
elements, the minimum scaled Jacobian computed here, seconds) and the count. Exit status: 77 when the folder is absent
(CTest's skip code), 1 with --must-mesh when a file does not mesh, else 0.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "fuzz"))
from campaign import HEX_CORNERS, WEDGE_CORNERS, check_mesh, read_mesh  # noqa: E402  (the campaign's independent checks)

DEFAULT_FOLDER = os.path.join(ROOT, "..", "shared", "real-cad")


def info(binary, path):
    r = subprocess.run([binary, "info", "--json", path], capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        return None
    return json.loads(r.stdout)


def diagonal(model):
    vs = model["volumes"] or model["surfaces"]  # a surface model has no volume
    lo = [min(v["box_min"][i] for v in vs) for i in range(3)]
    hi = [max(v["box_max"][i] for v in vs) for i in range(3)]
    return math.dist(lo, hi)


def hex_volume(pts, blocks):
    from campaign import HEX_TETS, WEDGE_TETS, tet_volume
    total = 0.0
    for kind, cells in blocks:
        if kind in ("hex", "wedge"):
            total += tet_volume(pts, cells, HEX_TETS if kind == "hex" else WEDGE_TETS).sum()
    return total


def unit(v):
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-300)


def min_scaled_jacobian(pts, blocks):
    """The smallest scaled Jacobian over the elements, computed here: hexes
    and wedges at their corners (det of the three unit edges; Verdict's hex
    value also looks at the centre), quads at their corners against the
    quad's mean normal, triangles 2/sqrt(3) |e1 x e2| / (|e1| |e2|) at the
    worst corner. None when there is no element."""
    worst = []
    for kind, c in blocks:
        q = pts[c]
        if kind in ("hex", "wedge"):
            for a0, a, b, d in (HEX_CORNERS if kind == "hex" else WEDGE_CORNERS):
                e1, e2, e3 = (unit(q[:, x] - q[:, a0]) for x in (a, b, d))
                worst.append(np.einsum("ij,ij->i", e1, np.cross(e2, e3)).min())
        elif kind == "quad":
            crosses = [np.cross(q[:, (k + 1) % 4] - q[:, k], q[:, (k + 3) % 4] - q[:, k]) for k in range(4)]
            n = unit(sum(crosses))
            for k in range(4):
                e1 = q[:, (k + 1) % 4] - q[:, k]
                e2 = q[:, (k + 3) % 4] - q[:, k]
                den = np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1)
                worst.append((np.einsum("ij,ij->i", crosses[k], n) / np.maximum(den, 1e-300)).min())
        elif kind == "tri":
            for k in range(3):
                e1 = q[:, (k + 1) % 3] - q[:, k]
                e2 = q[:, (k + 2) % 3] - q[:, k]
                den = np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1)
                sj = 2 / math.sqrt(3) * np.linalg.norm(np.cross(e1, e2), axis=1) / np.maximum(den, 1e-300)
                worst.append(np.minimum(sj, 1.0).min())
    return min(worst) if worst else None


def check_3d(path, cad_volume):
    problem = check_mesh(path, None)  # positivity, conformity, closed boundary
    if problem:
        return problem, 0
    pts, blocks = read_mesh(path)
    cells = sum(len(c) for k, c in blocks if k in ("hex", "wedge"))
    if cells == 0:
        return "no hexes", 0
    volume = hex_volume(pts, blocks)
    if abs(volume - cad_volume) > 0.01 * cad_volume:
        return "meshed volume %.6g against the CAD's %.6g" % (volume, cad_volume), cells
    return "", cells


def check_2d(path, cad_area):
    pts, blocks = read_mesh(path)
    area, cells = 0.0, 0
    for kind, c in blocks:
        if kind not in ("quad", "tri"):
            return "a %s in a surface mesh" % kind, 0
        q = pts[c]
        tris = [(0, 1, 2)] if kind == "tri" else [(0, 1, 2), (0, 2, 3)]
        for a, b, d in tris:
            cross = np.cross(q[:, b] - q[:, a], q[:, d] - q[:, a])
            a2 = np.linalg.norm(cross, axis=1)
            if (a2 <= 0).any():
                return "a degenerate %s" % kind, 0
            area += 0.5 * a2.sum()
        cells += len(c)
    if cells == 0:
        return "no elements", 0
    if abs(area - cad_area) > 0.02 * cad_area:
        return "meshed area %.6g against the CAD's %.6g" % (area, cad_area), cells
    return "", cells


def run_one(binary, path, dim, div, timeout, tmp):
    model = info(binary, path)
    if not model or not (model["volumes"] or model["surfaces"]):
        return "no model (`cooperage info` fails)", 0, 0.0, None
    size = diagonal(model) / div
    out = os.path.join(tmp, os.path.basename(path) + ".vtu")
    t0 = time.monotonic()
    try:
        r = subprocess.run([binary, "mesh", path, "--size", repr(size), "--dim", str(dim), "-o", out,
                            "--threads", "1", "--quiet"], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout (> %g s)" % timeout, 0, time.monotonic() - t0, None
    seconds = time.monotonic() - t0
    if r.returncode != 0:
        first = (r.stderr.strip().splitlines() or ["exit %d" % r.returncode])[0]
        return first.replace("cooperage: error: ", "")[:110], 0, seconds, None
    if dim == 3:
        problem, cells = check_3d(out, sum(v["volume"] for v in model["volumes"]))
    else:
        problem, cells = check_2d(out, sum(s["area"] for s in model["surfaces"]))
    pts, blocks = read_mesh(out)
    sj = min_scaled_jacobian(pts, [(k, c) for k, c in blocks if (k in ("hex", "wedge")) == (dim == 3)])
    os.remove(out)
    return ("OK" if not problem else "exit 0 but " + problem), cells, seconds, sj


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--dim", type=int, default=3, choices=(2, 3))
    ap.add_argument("--div", type=float, default=40.0)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--folder", default=os.environ.get("COOPERAGE_REAL_CAD", DEFAULT_FOLDER))
    ap.add_argument("--must-mesh", action="store_true", help="exit 1 unless every file meshes")
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    if not os.path.isdir(a.folder):
        print("skipped: %s is absent (the real-CAD parts are not part of the project)" % a.folder)
        return 77
    files = a.files or sorted(f for f in os.listdir(a.folder)
                              if f.lower().endswith((".step", ".stp", ".brep")))
    binary = os.path.abspath(a.bin)
    ok, low, failed_must = 0, 0, []
    print("| file | --dim %d at D/%g | elements | min SJ | seconds |" % (a.dim, a.div))
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for f in files:
            result, cells, seconds, sj = run_one(binary, os.path.join(a.folder, f), a.dim, a.div,
                                                 a.timeout, tmp)
            print("| %s | %s | %s | %s | %.1f |" % (f, result, "{:,}".format(cells) if cells else "",
                                                    "%.2f" % sj if sj is not None else "", seconds),
                  flush=True)
            if result == "OK" and sj is not None:
                low += sj < 0.2
            ok += result == "OK"
            if a.must_mesh and result != "OK":
                failed_must.append(f)
    print("\n%d of %d meshed (--dim %d, D/%g); %d of them with a minimum scaled Jacobian below 0.2"
          % (ok, len(files), a.dim, a.div, low))
    if failed_must:
        print("must mesh but did not: " + ", ".join(failed_must))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
