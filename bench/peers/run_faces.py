#!/usr/bin/python3
"""Face comparison: Cooperage's pave and Gmsh's quads (Frontal-Delaunay +
Blossom) on the benchmark faces of bench/face_models.cpp, with the same
geometry (Gmsh imports the BREP Cooperage built) and the same boundary node
counts per curve (those of Cooperage's interval assignment). Quality of both
by Cooperage's own `cooperage quality FILE --json`; irregular nodes (interior
nodes whose number of edges is not 4) computed here from the .msh files with
meshio. Prints a Markdown table for bench/RESULTS.md.

    /usr/bin/python3 bench/peers/run_faces.py [--bench PATH] [--cooperage PATH]
        [--work DIR] [--timeout S] [--json FILE]

Steps: (1) `cooperage_bench --benchmark_filter=BM_PaveFace` with
COOPERAGE_FACES_OUT=<work> writes <face>.brep/.msh/.json and reports the
mesh() time; (2) gmsh_faces.py meshes each face in its own process;
(3) `cooperage quality` on both .msh files.

Time: Cooperage's is the mean real time of the scheme's mesh() (Google
Benchmark); Gmsh's is its generate(2) call (1D transfinite + 2D + recombine).
On the cylindrical patch `cooperage quality` on a surface-only .msh measures
the quad scaled Jacobian against each element's own normal (not the
surface's), so an inverted quad would not show there; BM_PaveFace's min_SJ
uses the surface normal.
Exit status: 0 table printed (a failing tool is a row); 1 harness error;
2 bad usage.
"""

import argparse
import contextlib
import io
import json
import os
import subprocess
import sys
import time
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3"  # Debian's, with python3-gmsh and python3-meshio


class HarnessError(Exception):
    pass


def run(cmd, timeout, env=None):
    t0 = time.perf_counter()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
        return r.returncode, r.stdout, r.stderr, time.perf_counter() - t0
    except subprocess.TimeoutExpired:
        return None, "", "timeout after %g s" % timeout, time.perf_counter() - t0


def last_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return lines[-1] if lines else ""


def quality(cooperage, path, timeout):
    """min and median quad scaled Jacobian of a .msh by `cooperage quality --json`."""
    rc, out, err, _ = run([cooperage, "quality", path, "--json"], timeout)
    if rc != 0:
        raise HarnessError("cooperage quality %s: %s" % (path, last_line(err) or last_line(out)))
    q = json.loads(out)
    quads = [b for b in q["blocks"] if b["type"] == "quad"]
    if not quads:
        raise HarnessError("%s: no quad block in %s" % (path, [b["type"] for b in q["blocks"]]))
    sj = [(b["metrics"]["scaled_jacobian"], b["count"]) for b in quads]
    # one block per surface here; the median of several blocks: count-weighted medians
    median = sorted(sj, key=lambda s: s[0]["median"])[len(sj) // 2][0]["median"]
    return min(s["min"] for s, _ in sj), median


def irregular_per_100(path):
    """Interior nodes whose edge count is not 4, per 100 quads; and the quad/tri counts.
    Interior: not on an edge used by one element only."""
    import meshio
    with contextlib.redirect_stdout(io.StringIO()):  # meshio prints a blank line per read
        m = meshio.read(path)
    edge_use = defaultdict(int)
    quads = tris = 0
    for block in m.cells:
        if block.type not in ("quad", "triangle"):
            continue
        if block.type == "quad":
            quads += len(block.data)
        else:
            tris += len(block.data)
        k = block.data.shape[1]
        for cell in block.data:
            for i in range(k):
                a, b = int(cell[i]), int(cell[(i + 1) % k])
                edge_use[(min(a, b), max(a, b))] += 1
    boundary = set()
    degree = defaultdict(int)
    for (a, b), n in edge_use.items():
        degree[a] += 1
        degree[b] += 1
        if n == 1:
            boundary.update((a, b))
    irregular = sum(1 for v, d in degree.items() if v not in boundary and d != 4)
    return (100.0 * irregular / quads if quads else None), quads, tris, len(boundary)

# The build scripts/setup.sh makes, next to this checkout's sources.
BUILD_BIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin")


def fmt(x, spec="%.3f"):
    return "—" if x is None else spec % x


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bench", default=os.environ.get("COOPERAGE_BENCH",
                                                     os.path.join(BUILD_BIN, "cooperage_bench")))
    p.add_argument("--cooperage", default=os.environ.get("COOPERAGE",
                                                         os.path.join(BUILD_BIN, "cooperage")))
    p.add_argument("--work", default="/tmp/cooperage-faces")
    p.add_argument("--timeout", type=float, default=300)
    p.add_argument("--json", help="write all raw results here")
    a = p.parse_args()
    for exe in (a.bench, a.cooperage):
        if not os.access(exe, os.X_OK):
            print("run_faces: no executable %s" % exe, file=sys.stderr)
            return 2
    os.makedirs(a.work, exist_ok=True)

    try:
        env = dict(os.environ, COOPERAGE_FACES_OUT=a.work)
        bench_json = os.path.join(a.work, "pave_faces_bench.json")
        rc, out, err, _ = run([a.bench, "--benchmark_filter=BM_PaveFace/",
                               "--benchmark_out=" + bench_json, "--benchmark_out_format=json"],
                              a.timeout * 8, env)
        if rc != 0:
            raise HarnessError("cooperage_bench: %s" % (last_line(err) or last_line(out)))
        with open(bench_json) as f:
            benchmarks = json.load(f)["benchmarks"]
        rows = []
        for b in benchmarks:
            if b.get("run_type", "iteration") != "iteration":
                continue
            name = b["label"]
            face_json = os.path.join(a.work, name + ".json")
            with open(face_json) as f:
                face = json.load(f)
            nodes = sum(c["intervals"] for c in face["curves"])
            coop_msh = os.path.join(a.work, name + ".msh")
            ms = b["real_time"] * {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1}[b["time_unit"]]
            row = {"face": name, "tool": "Cooperage pave", "boundary_nodes": nodes,
                   "seconds": ms, "status": "ok", "file": coop_msh}
            rows.append(row)
            gmsh_msh = os.path.join(a.work, name + ".gmsh.msh")
            grc, gout, gerr, _ = run([PYTHON, os.path.join(HERE, "gmsh_faces.py"),
                                      os.path.join(a.work, name + ".brep"), face_json, gmsh_msh],
                                     a.timeout)
            g = {"face": name, "tool": "Gmsh 6+Blossom", "boundary_nodes": nodes,
                 "file": gmsh_msh}
            if grc == 0:
                info = json.loads(last_line(gout))
                g.update(status="ok", seconds=info["mesh_seconds"])
                if info["boundary_nodes"] != nodes:
                    raise HarnessError("%s: Gmsh got %d boundary nodes, Cooperage %d"
                                       % (name, info["boundary_nodes"], nodes))
            else:
                g.update(status="failed (%s)" % (last_line(gerr) or "exit %s" % grc))
            rows.append(g)
            for r in rows[-2:]:
                if r["status"] != "ok":
                    continue
                r["min_sj"], r["median_sj"] = quality(a.cooperage, r["file"], a.timeout)
                r["irregular_per_100"], r["quads"], r["tris"], bnodes = irregular_per_100(r["file"])
                if bnodes != nodes:
                    raise HarnessError("%s (%s): %d boundary nodes in the file, %d expected"
                                       % (name, r["tool"], bnodes, nodes))
            print("[faces] %-14s done" % name, file=sys.stderr)
    except HarnessError as e:
        print("run_faces: %s" % e, file=sys.stderr)
        return 1

    print("| face | boundary nodes | tool | quads | min SJ | median SJ | irregular / 100 quads | time |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["status"] != "ok":
            print("| %s | %d | %s | %s | | | | |" % (r["face"], r["boundary_nodes"], r["tool"],
                                                    r["status"]))
            continue
        quads = "{:,}".format(r["quads"]) + (" (+%d tris)" % r["tris"] if r["tris"] else "")
        print("| %s | %d | %s | %s | %s | %s | %s | %.1f ms |"
              % (r["face"], r["boundary_nodes"], r["tool"], quads, fmt(r["min_sj"]),
                 fmt(r["median_sj"]), fmt(r["irregular_per_100"], "%.2f"), 1e3 * r["seconds"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
