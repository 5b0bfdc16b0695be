#!/usr/bin/python3
"""Issue 17's parts meshed by `cooperage` with the automatic decomposition,
against Gmsh's all-hex route for an arbitrary solid (tetrahedra split into
four hexahedra each, Mesh.SubdivisionAlgorithm = 2), at the same size.

    /usr/bin/python3 bench/decompose/run_decompose.py [--bin build/bin/cooperage]

Per part: the cuts and pieces (`cooperage plan --json`), the time of the
search (the run's "decompose" stage) against the whole run, hexes and min /
mean scaled Jacobian (`cooperage quality` reads both tools' meshes, so both
are measured by the same code). One thread, one run each (~1-2 minutes in
all); real CAD parts are skipped when ../shared/real-cad is absent.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import gmsh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# ../shared/real-cad next to the checkout (a git worktree: one folder up more)
REAL = next((p for p in (os.path.normpath(os.path.join(ROOT, *up, "shared", "real-cad"))
                         for up in (("..",), ("..", ".."))) if os.path.isdir(p)),
            os.path.normpath(os.path.join(ROOT, "..", "shared", "real-cad")))

# (name, file, Gmsh builder or None for a STEP file Gmsh imports itself)
JOURNALS = ["fig3a_auto.xml", "bracket_holes.xml", "tee_bosses.xml"]
REAL_PARTS = ["occt_xr1-tc-lbr.stp", "gmsh_Angled.step",
              "pyocc_face_recognition_sample_part.stp", "occt_bm2_ec_lever-A.stp"]


def gmsh_journal_part(name):
    """The journal's solid in Gmsh's OCC kernel (same primitives)."""
    occ = gmsh.model.occ
    if name == "fig3a_auto.xml":
        a = occ.addBox(0, 0, 0, 4, 4, 2)
        b = occ.addBox(1, 0.5, 2, 1, 1, 1)
        c = occ.addBox(4, 2.5, 0.5, 1, 1, 1)
        occ.fuse([(3, a)], [(3, b), (3, c)])
    elif name == "bracket_holes.xml":
        a = occ.addBox(0, 0, 0, 6, 4, 1)
        b = occ.addBox(0, 0, 1, 1, 4, 4)
        f, _ = occ.fuse([(3, a)], [(3, b)])
        h1 = occ.addCylinder(3.5, 2, -1, 0, 0, 3, 0.6)
        h2 = occ.addCylinder(-1, 2, 3, 3, 0, 0, 0.6)
        occ.cut(f, [(3, h1), (3, h2)])
    elif name == "tee_bosses.xml":
        a = occ.addBox(0, 3, 0, 9, 2, 1.5)
        b = occ.addBox(3.5, 0, 0, 2, 3, 1.5)
        w = occ.addCylinder(0, 4, 0.75, -1, 0, 0, 0.5)
        e = occ.addCylinder(9, 4, 0.75, 1, 0, 0, 0.5)
        so = occ.addCylinder(4.5, 0, 0.75, 0, -1, 0, 0.5)
        occ.fuse([(3, a)], [(3, b), (3, w), (3, e), (3, so)])
    occ.synchronize()


def gmsh_mesh(part, size, out):
    """Gmsh's all-hex route for an arbitrary solid; returns seconds."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    t0 = time.perf_counter()
    if part.endswith(".xml"):
        gmsh_journal_part(os.path.basename(part))
    else:
        gmsh.model.occ.importShapes(part)
        gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 2)  # all hexahedra
    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.SaveAll", 0)
    for dim, tag in gmsh.model.getEntities(3):
        gmsh.model.addPhysicalGroup(3, [tag])
    gmsh.write(out)
    seconds = time.perf_counter() - t0
    gmsh.finalize()
    return seconds


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def quality(binary, mesh):
    """(hexes, min SJ, mean SJ) of the hex blocks of a mesh file."""
    r = run([binary, "quality", mesh, "--json"])
    if r.returncode != 0:
        return None
    data = json.loads(r.stdout)
    hexes, lo, total = 0, 1.0, 0.0
    for b in data.get("blocks", []):
        if b.get("type") != "hex":
            continue
        m = b["metrics"]["scaled_jacobian"] if "metrics" in b else b["scaled_jacobian"]
        hexes += b["count"]
        lo = min(lo, m["min"])
        total += m["mean"] * b["count"]
    return hexes, lo, (total / hexes if hexes else 0.0)


def diagonal(binary, path):
    data = json.loads(run([binary, "info", path, "--json"]).stdout)
    vols = data["volumes"]
    lo = [min(v["box_min"][k] for v in vols) for k in range(3)]
    hi = [max(v["box_max"][k] for v in vols) for k in range(3)]
    return sum((h - l) ** 2 for l, h in zip(lo, hi)) ** 0.5


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "cooperage"))
    args = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="cooperage-decompose-bench-")
    rows = []
    parts = [(j, os.path.join(ROOT, "examples", j)) for j in JOURNALS[:2]]
    parts += [(JOURNALS[2], os.path.join(ROOT, "tests", "data", "decompose", JOURNALS[2]))]
    parts += [(p, os.path.join(REAL, p)) for p in REAL_PARTS]
    for name, path in parts:
        if not os.path.exists(path):
            print(f"{name}: absent, skipped", file=sys.stderr)
            continue
        out = os.path.join(tmp, re.sub(r"\W", "_", name) + ".vtu")
        if path.endswith(".xml"):
            size = float(re.search(r'<mesh size="([0-9.]+)"', open(path).read()).group(1))
        else:
            size = diagonal(args.bin, path) / 40.0
        plan = run([args.bin, "plan", path, "--size", repr(size), "--json"])
        cuts, pieces = [], []
        if plan.returncode == 0:
            p = json.loads(plan.stdout)
            for v in p["decomposition"]["volumes"]:
                cuts += [c["description"] + " (" + c["through"] + ")" for c in v["cuts"]]
            pieces = [v["scheme"] for v in p["volumes"]]
        t0 = time.perf_counter()
        if path.endswith(".xml"):
            job = os.path.join(tmp, name)
            text = open(path).read()
            text = re.sub(r'<export file="[^"]*"/>', f'<export file="{out}"/>', text)
            open(job, "w").write(text)
            r = run([args.bin, "run", job, "--threads", "1", "-q"])
        else:
            r = run([args.bin, "mesh", path, "--size", repr(size), "-o", out, "--threads", "1", "-q"])
        wall = time.perf_counter() - t0
        stages = {}
        m = re.search(r"^time \[s\]:(.*)$", r.stdout, re.M)
        if m:
            for item in m.group(1).split(","):
                item = item.strip().rsplit(" ", 1)
                if len(item) == 2:
                    stages[item[0]] = float(item[1])
        ours = quality(args.bin, out) if r.returncode == 0 else None
        gout = os.path.join(tmp, re.sub(r"\W", "_", name) + "_gmsh.msh")
        try:
            gsec = gmsh_mesh(path, size, gout)
            theirs = quality(args.bin, gout)
        except Exception as e:  # noqa: BLE001 - report, go on
            gsec, theirs = None, None
            print(f"{name}: gmsh failed: {e}", file=sys.stderr)
        rows.append(dict(part=name, size=size, exit=r.returncode, cuts=cuts, pieces=pieces,
                         decompose=stages.get("decompose", 0.0), total=stages.get("total", wall),
                         wall=wall, ours=ours, gmsh_seconds=gsec, gmsh=theirs,
                         error=(r.stderr.strip().splitlines() or [""])[-1] if r.returncode else ""))
        print(json.dumps(rows[-1]), flush=True)
    shutil.rmtree(tmp, ignore_errors=True)
    print("\n| part | size | cuts | pieces (schemes) | search [s] | run [s] | hexes | min SJ | mean SJ |"
          " Gmsh hexes | Gmsh min SJ | Gmsh mean SJ | Gmsh [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for w in rows:
        o, g = w["ours"], w["gmsh"]
        ours = f"{o[0]} | {o[1]:.3f} | {o[2]:.3f}" if o else f"exit {w['exit']} | - | -"
        gm = f"{g[0]} | {g[1]:.3f} | {g[2]:.3f}" if g else "- | - | -"
        gs = f"{w['gmsh_seconds']:.2f}" if w["gmsh_seconds"] else "-"
        print(f"| {w['part']} | {w['size']:.4g} | {len(w['cuts'])} | {len(w['pieces'])} "
              f"({', '.join(w['pieces'])}) | {w['decompose']:.2f} | {w['total']:.2f} | {ours} | {gm} | {gs} |")
    for w in rows:
        if w["cuts"]:
            print(f"- {w['part']}: " + "; ".join(w["cuts"]))
        if w["error"]:
            print(f"- {w['part']} failed: {w['error']}")


if __name__ == "__main__":
    main()
