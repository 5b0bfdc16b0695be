#!/usr/bin/python3
"""CPU time per real-CAD file against Gmsh's tet mesh of it (issue 16: no file
may take longer than 2x Gmsh).

usage: bench/realcad/time_vs_gmsh.py --bin BUILD/bin/cooperage [--div 40]
           [--folder ../shared/real-cad] [FILE ...]

For each file, at size D/DIV (D the bounding-box diagonal, as run_realcad.py):
  * Cooperage: `cooperage mesh F --size S --dim 2` and `--dim 3`, one thread;
    the user + system CPU seconds of the child process (getrusage), so a
    loaded machine changes the numbers less than wall time would. A refusal
    counts too: a user waits for it as for a mesh.
  * Gmsh (Debian's python3-gmsh, in a child /usr/bin/python3): import the
    file with OCC, Mesh.MeshSizeMin = Max = D/DIV with D from Gmsh's own
    bounding box (its import may change the length unit), one thread, generate(3) (tets,
    the fallback a user has); its child CPU seconds, import included as in
    Cooperage's, minus those of a run that only starts Python and Gmsh
    (an interpreter's start-up is not Gmsh's; Cooperage's own start-up is
    not subtracted).
Prints a Markdown table: seconds of each and the ratio to Gmsh's tet time.
"""
import argparse
import glob
import json
import math
import os
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_FOLDER = os.path.join(HERE, "..", "..", "..", "shared", "real-cad")
PYTHON = "/usr/bin/python3"

GMSH_SCRIPT = r"""
import sys, gmsh
path, div, mesh = sys.argv[1], float(sys.argv[2]), sys.argv[3] == "1"
gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setNumber("General.NumThreads", 1)
if mesh:
    gmsh.model.occ.importShapes(path)
    gmsh.model.occ.synchronize()
    # D/div in Gmsh's own length unit (it may scale the file's on import)
    x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(-1, -1)
    size = ((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) ** 0.5 / div
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(3)
    print(len(gmsh.model.mesh.getElementsByType(4)[0]))
gmsh.finalize()
"""


def child_cpu(cmd, timeout):
    """(exit code, CPU seconds of the child, stdout)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        code, out = r.returncode, r.stdout
    except subprocess.TimeoutExpired:
        code, out = "timeout", ""
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return code, cpu, out


def diagonal(binary, path):
    r = subprocess.run([binary, "info", "--json", path], capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        return None
    vs = json.loads(r.stdout)["volumes"]
    if not vs:
        return None
    lo = [min(v["box_min"][i] for v in vs) for i in range(3)]
    hi = [max(v["box_max"][i] for v in vs) for i in range(3)]
    return math.dist(lo, hi)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--div", type=float, default=40)
    ap.add_argument("--folder", default=DEFAULT_FOLDER)
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("files", nargs="*")
    args = ap.parse_args()
    folder = os.path.abspath(args.folder)
    if not os.path.isdir(folder):
        print(f"skipped: {folder} is absent")
        return 77
    names = args.files or sorted(
        os.path.basename(p) for ext in ("step", "stp", "brep") for p in glob.glob(os.path.join(folder, "*." + ext)))
    print(f"| file | size | --dim 2 s | --dim 3 s | Gmsh tets s | tets | dim 2 / Gmsh | dim 3 / Gmsh |")
    print("|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for name in names:
        path = os.path.join(folder, name)
        d = diagonal(args.bin, path)
        if d is None:
            print(f"| {name} | no solid | | | | | | |")
            continue
        size = d / args.div
        row = []
        for dim in (2, 3):
            code, cpu, _ = child_cpu([args.bin, "mesh", path, "--size", repr(size), "--dim", str(dim), "-o",
                                      f"/tmp/time_vs_gmsh_{os.getpid()}.vtu",
                                      "--threads", "1", "-q"], args.timeout)
            row.append((code, cpu))
        _, start_cpu, _ = child_cpu([PYTHON, "-c", GMSH_SCRIPT, path, repr(args.div), "0"], args.timeout)
        gcode, gcpu, gout = child_cpu([PYTHON, "-c", GMSH_SCRIPT, path, repr(args.div), "1"], args.timeout)
        gmsh_s = max(gcpu - start_cpu, 1e-3)
        tets = gout.strip().splitlines()[-1] if gcode == 0 and gout.strip() else f"exit {gcode}"
        ratios = [c / gmsh_s for _, c in row]
        worst = max([worst] + ratios)
        marks = ["" if code == 0 else f" (exit {code})" for code, _ in row]
        print(f"| {name} | {size:.4g} | {row[0][1]:.2f}{marks[0]} | {row[1][1]:.2f}{marks[1]} | {gmsh_s:.2f} | {tets} "
              f"| {ratios[0]:.2f} | {ratios[1]:.2f} |", flush=True)
    try:
        os.remove(f"/tmp/time_vs_gmsh_{os.getpid()}.vtu")
    except OSError:
        pass
    print(f"\nlargest ratio to Gmsh's tet time: {worst:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
