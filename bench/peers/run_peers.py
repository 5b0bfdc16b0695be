#!/usr/bin/python3
"""Peer comparison: Cooperage and Gmsh on the same models at matched element
counts, with the quality of both outputs computed by the same code
(`cooperage quality FILE --json`). Prints a Markdown table for
bench/RESULTS.md.

    /usr/bin/python3 bench/peers/run_peers.py [--quick] [--sizes 10k,100k]
        [--models brick_1x1x1,...] [--timeout 300] [--cooperage PATH]

Exit status: 0 when the table was produced (a tool that cannot mesh a model,
or times out, is a row of the table, not an error); 1 on a harness error
(a tool's output that cannot be read, malformed JSON, ...); 2 on bad usage
(e.g. no cooperage binary). See README.md.
"""

import argparse
import contextlib
import datetime
import json
import math
import os
import platform
import re
import shlex
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
# The build scripts/setup.sh makes, next to this checkout's sources.
DEFAULT_COOPERAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build",
                                 "bin", "cooperage")
PYTHON = "/usr/bin/python3"  # Debian's, with python3-gmsh

# Sizes per model: element size for ~10k, ~100k and ~1M elements.
# Bricks: n^3 (1x1x1) and (2/h)(3/h)(4/h); quarter annulus: the arcs take
# the geometric mean of the inner and outer arcs' goals, ~ (1/h)^2 2.2/h; plate: ~53.97/h^2 quads x 1/h
# layers; cylinder with boss: ~ (4 pi (3/h) + pi (1.5/h)) / h^2.
MODELS = [
    ("brick_1x1x1", {"10k": 1 / 22, "100k": 1 / 46, "1M": 1 / 100}),
    ("brick_2x3x4", {"10k": 0.135, "100k": 0.0625, "1M": 0.029}),
    ("quarter_annulus", {"10k": 1 / 16, "100k": 1 / 35, "1M": 1 / 76}),
    ("plate_three_holes", {"10k": 0.175, "100k": 0.08, "1M": 0.0375}),
    ("cylinder_boss", {"10k": 0.16, "100k": 0.075, "1M": 0.035}),
]
SIZE_LABELS = ["10k", "100k", "1M"]

# Matched element counts: both tools put ~1 quad per size^2 of area on their
# quad faces (pave since its coarser refinement; Gmsh at QUAD_SIZE_FACTOR in
# gmsh_models.py), so both run at the same size. A model listed here would
# run Cooperage at a size this many times larger.
COOPERAGE_SIZE_FACTOR = {}


def nominal_count(model, h):
    """Element count a size-h mesh should have: curve intervals round(L/h)
    (halves up) on structured parts; area/h^2 quads x round(height/h) layers
    on swept parts. The reference for Gmsh's count when Cooperage has none."""
    n = lambda length: max(1, int(math.floor(length / h + 0.5)))
    if model == "brick_1x1x1":
        return n(1) ** 3
    if model == "brick_2x3x4":
        return n(2) * n(3) * n(4)
    if model == "quarter_annulus":
        return n(1) * n(1) * n(0.5 * math.pi * math.sqrt(2.0))
    if model == "plate_three_holes":
        return (60 - 3 * math.pi * 0.8 ** 2) / h ** 2 * n(1)
    if model == "cylinder_boss":
        return 3 * math.pi / h ** 2 * n(3) + math.pi / h ** 2 * n(4.5)
    return None


class HarnessError(Exception):
    pass


def run_limited(cmd, timeout, cwd=None):
    """Run cmd (a list) in its own process group with a wall-clock limit.
    Returns dict: rc (None on timeout), stdout, stderr, wall (s), maxrss (MiB)."""
    t0 = time.perf_counter()
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, cwd=cwd, start_new_session=True)
        rc = None
        rusage = None
        while True:
            pid, status, rusage = os.wait4(proc.pid, os.WNOHANG)
            if pid == proc.pid:
                rc = os.waitstatus_to_exitcode(status)
                proc.returncode = rc
                break
            if time.perf_counter() - t0 > timeout:
                os.killpg(proc.pid, signal.SIGKILL)  # the group we started
                _, status, rusage = os.wait4(proc.pid, 0)
                proc.returncode = -9
                rc = None
                break
            time.sleep(0.005)
        wall = time.perf_counter() - t0
        out.seek(0)
        err.seek(0)
        stdout = out.read().decode(errors="replace")
        stderr = err.read().decode(errors="replace")
    return {"rc": rc, "stdout": stdout, "stderr": stderr, "wall": wall,
            "maxrss": rusage.ru_maxrss / 1024.0 if rusage else None}


def last_line(text):
    lines = [l.strip() for l in text.strip().splitlines() if l.strip()]
    return lines[-1] if lines else ""


def write_journal(model, size, job_dir, export_name):
    """The model's journal with the mesh size set and one export, written
    into job_dir (exports resolve against the journal's directory)."""
    tree = ET.parse(os.path.join(HERE, "models", model + ".xml"))
    root = tree.getroot()
    mesh = root.find("mesh")
    if mesh is None:
        mesh = ET.Element("mesh")
        root.insert(list(root).index(root.find("geometry")) + 1, mesh)
    mesh.set("size", repr(size))
    for e in root.findall("export"):
        root.remove(e)
    ET.SubElement(root, "export", {"file": export_name})
    path = os.path.join(job_dir, "job.xml")
    tree.write(path, encoding="UTF-8", xml_declaration=True)
    return path


def merge_blocks(path):
    """path (.msh) rewritten as <path>.merged.vtu with one cell block per type."""
    import warnings
    import meshio
    import numpy
    mesh = meshio.read(path)
    by_type = {}
    for block in mesh.cells:
        by_type.setdefault(block.type, []).append(block.data)
    merged = meshio.Mesh(mesh.points, [(t, numpy.concatenate(v)) for t, v in by_type.items()])
    out = path + ".merged.vtu"
    with warnings.catch_warnings(), open(os.devnull, "w") as null, \
            contextlib.redirect_stderr(null):
        warnings.simplefilter("ignore")
        merged.write(out, binary=False)  # ASCII: what the VTU reader surely reads
    return out


def quality(cooperage, path, timeout):
    """Hex-block quality of a mesh file by `cooperage quality --json`."""
    r = run_limited([cooperage, "quality", path, "--json"], timeout)
    if r["rc"] != 0:
        raise HarnessError("cooperage quality %s: %s" % (path, last_line(r["stderr"]) or "timeout"))
    try:
        q = json.loads(r["stdout"])
    except ValueError as e:
        raise HarnessError("cooperage quality %s: bad JSON (%s)" % (path, e))
    hexes = [b for b in q["blocks"] if b["type"] == "hex"]
    if len(hexes) > 1 and not path.endswith(".merged.vtu"):
        # Several hex blocks (Gmsh writes one per volume entity): block medians
        # do not give the whole mesh's median, so merge the blocks of each type
        # into one (same nodes and connectivity, .vtu without block ids) and
        # ask again. Not timed.
        return quality(cooperage, merge_blocks(path), timeout)
    other = sum(b["count"] for b in q["blocks"] if b["type"] != "hex")
    other += sum(q.get("skipped", {}).values())
    res = {"hex": sum(b["count"] for b in hexes), "non_hex": other, "min_sj": None,
           "median_sj": None, "median_exact": True, "inverted": 0}
    if hexes:
        sj = [b["metrics"]["scaled_jacobian"] for b in hexes]
        res["min_sj"] = min(s["min"] for s in sj)
        res["inverted"] = sum(s.get("inverted", 0) for s in sj)
        if len(hexes) == 1:
            res["median_sj"] = sj[0]["median"]
        else:  # count-weighted median of the block medians (approximate)
            pairs = sorted((s["median"], b["count"]) for s, b in zip(sj, hexes))
            half, acc = res["hex"] / 2.0, 0
            for m, c in pairs:
                acc += c
                if acc >= half:
                    res["median_sj"] = m
                    break
            res["median_exact"] = False
    return res


def run_cooperage(cooperage, model, size, work, timeout, threads):
    job_dir = os.path.join(work, "cooperage")
    os.makedirs(job_dir, exist_ok=True)
    journal = write_journal(model, size, job_dir, "mesh.exo")
    out = os.path.join(job_dir, "mesh.exo")
    if os.path.exists(out):
        os.remove(out)
    # Not -q: the progress lines on stderr ("cooperage: STAGE (N items) at Ts")
    # give the meshing time, from the start of planning to the start of export.
    cmd = [cooperage, "run", journal, "--threads", str(threads)]
    r = run_limited(cmd, timeout)
    stages = dict(re.findall(r"^cooperage: (\w+).* at ([0-9.]+)s$", r["stderr"], re.M))
    mesh_s = None
    if "plan" in stages and "export" in stages:
        mesh_s = float(stages["export"]) - float(stages["plan"])
    row = {"tool": "Cooperage", "wall": r["wall"], "maxrss": r["maxrss"], "mesh_s": mesh_s,
           "file": out, "rc": r["rc"]}
    if r["rc"] is None:
        row["status"] = "timeout after %g s" % timeout
    elif r["rc"] not in (0, 1) or not os.path.exists(out):
        # 1 = a quality check failed (the model journals have none); 2, 3 = cannot mesh
        row["status"] = "not yet (exit %s: %s)" % (r["rc"], last_line(r["stderr"]) or last_line(r["stdout"]))
    else:
        row["status"] = "ok"
    return row


def run_gmsh(model, size, work, timeout, threads):
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "gmsh.msh")
    if os.path.exists(out):
        os.remove(out)
    cmd = [PYTHON, os.path.join(HERE, "gmsh_models.py"), model, repr(size), out,
           "--threads", str(threads)]
    r = run_limited(cmd, timeout)
    row = {"tool": "Gmsh", "wall": r["wall"], "maxrss": r["maxrss"], "mesh_s": None,
           "file": out, "rc": r["rc"]}
    if r["rc"] is None:
        row["status"] = "timeout after %g s" % timeout
        return row
    if r["rc"] != 0:
        row["status"] = "failed (exit %s: %s)" % (r["rc"], last_line(r["stderr"]))
        return row
    try:
        info = json.loads(last_line(r["stdout"]))
    except ValueError as e:
        raise HarnessError("gmsh_models.py %s %s: bad JSON (%s)" % (model, size, e))
    row.update(status="ok", mesh_s=info["mesh_seconds"], gmsh=info)
    return row


def best_of(repeat, run):
    """The run with the least wall time of `repeat` runs (both tools are
    deterministic, so the file left by the last run is the same mesh). Stops
    at the first run that does not succeed."""
    best = None
    for _ in range(max(1, repeat)):
        row = run()
        if row["status"] != "ok":
            return row
        if best is None or row["wall"] < best["wall"]:
            best = row
        if row["mesh_s"] is not None and best["mesh_s"] is not None:
            best["mesh_s"] = min(best["mesh_s"], row["mesh_s"])
    best["repeat"] = max(1, repeat)
    return best


def fmt_int(n):
    return "{:,}".format(n) if n is not None else "—"


def fmt_s(s):
    if s is None:
        return "—"
    return "%.3f" % s if s < 10 else "%.1f" % s


def fmt_rate(n, s):
    if not n or not s:
        return "—"
    r = n / s
    return "%.2f M/s" % (r / 1e6) if r >= 1e6 else "%.0f k/s" % (r / 1e3)


def fmt_q(x):
    return "—" if x is None else "%.4f" % x


def machine():
    mem = "?"
    cpu = platform.processor() or "?"
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    mem = "%.1f GiB" % (int(line.split()[1]) / 1024.0 / 1024.0)
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%d cores (nproc), %s, %s, %s" % (os.cpu_count() or 0, mem, cpu, platform.platform())


def version_of(cmd):
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        return last_line(r.stdout or r.stderr)
    except (OSError, subprocess.TimeoutExpired):
        return "?"


def main(argv=None):
    p = argparse.ArgumentParser(description="Cooperage vs Gmsh peer comparison")
    p.add_argument("--quick", action="store_true", help="only the smallest size (smoke run)")
    p.add_argument("--sizes", default=",".join(SIZE_LABELS),
                   help="comma-separated size labels among %s (default: all)" % ",".join(SIZE_LABELS))
    p.add_argument("--models", default=",".join(m for m, _ in MODELS),
                   help="comma-separated models (default: all)")
    p.add_argument("--timeout", type=float, default=300, help="wall-clock limit per tool run, s")
    p.add_argument("--threads", type=int, default=1,
                   help="threads for both tools (default 1; Gmsh's hex paths are serial anyway)")
    p.add_argument("--repeat", type=int, default=1,
                   help="run each tool N times and keep the least wall time (and least mesh time)")
    p.add_argument("--cooperage", default=os.environ.get("COOPERAGE", DEFAULT_COOPERAGE),
                   help="the cooperage binary (default %s or $COOPERAGE)" % DEFAULT_COOPERAGE)
    p.add_argument("--work", default="/tmp/cooperage-peers", help="scratch directory for meshes")
    p.add_argument("--keep", action="store_true", help="keep the mesh files")
    p.add_argument("--json", help="also write all results to this JSON file")
    a = p.parse_args(argv)

    if not (os.path.isfile(a.cooperage) and os.access(a.cooperage, os.X_OK)):
        print("run_peers: no cooperage binary at %s (build cooperage_cli, or --cooperage)" % a.cooperage,
              file=sys.stderr)
        return 2
    labels = ["10k"] if a.quick else [s.strip() for s in a.sizes.split(",") if s.strip()]
    bad = [s for s in labels if s not in SIZE_LABELS]
    models = [m.strip() for m in a.models.split(",") if m.strip()]
    bad += [m for m in models if m not in dict(MODELS)]
    if bad:
        print("run_peers: unknown size or model: %s" % ", ".join(bad), file=sys.stderr)
        return 2

    started = datetime.datetime.now(datetime.timezone.utc)
    try:
        with open("/proc/loadavg") as f:
            load_at_start = " ".join(f.read().split()[:3])
    except OSError:
        load_at_start = "?"
    t_all = time.perf_counter()
    errors = []
    results = []
    for model, sizes in MODELS:
        if model not in models:
            continue
        for label in labels:
            size = sizes[label]
            work = os.path.join(a.work, model, label)
            os.makedirs(work, exist_ok=True)
            coop_size = size * COOPERAGE_SIZE_FACTOR.get(model, 1.0)
            rows = [best_of(a.repeat, lambda: run_cooperage(a.cooperage, model, coop_size, work,
                                                            a.timeout, a.threads)),
                    best_of(a.repeat, lambda: run_gmsh(model, size, work, a.timeout, a.threads))]
            for row in rows:
                row.update(model=model, label=label, size=size)
                if row["status"] == "ok":
                    try:
                        row["q"] = quality(a.cooperage, row["file"], a.timeout)
                    except HarnessError as e:
                        errors.append(str(e))
                        row["status"] = "quality failed: %s" % e
                for f in (row["file"], row["file"] + ".merged.vtu"):
                    if not a.keep and os.path.exists(f):
                        os.remove(f)
                results.append(row)
                print("[peers] %-18s %-5s %-9s %s %.2fs" % (model, label, row["tool"], row["status"],
                                                           row["wall"]), file=sys.stderr, flush=True)

    # Count ratio Gmsh / Cooperage, for the matched-count check.
    coop_n = {(r["model"], r["label"]): r["q"]["hex"] + r["q"]["non_hex"]
              for r in results if r["tool"] == "Cooperage" and "q" in r}

    lines = []
    lines.append("Date: %s. Machine: %s." % (started.strftime("%Y-%m-%d %H:%M UTC"), machine()))
    lines.append("Gmsh %s (python3-gmsh, OCC kernel); %s; threads: %d for both; "
                 "times: best of %d run(s); load average at start: %s." % (
        version_of([PYTHON, "-c", "import gmsh; gmsh.initialize(readConfigFiles=False); "
                                  "print(gmsh.option.getString('General.Version'))"]),
        version_of([a.cooperage, "--version"]), a.threads, max(1, a.repeat), load_at_start))
    lines.append("")
    lines.append("Command: `%s`" % " ".join(shlex.quote(x) for x in [PYTHON] + [os.path.relpath(sys.argv[0], REPO) if os.path.isabs(sys.argv[0]) else sys.argv[0]] + sys.argv[1:]))
    lines.append("")
    lines.append("| model | size | tool | elements | mesh s | wall s | elements/s (wall) | peak MB | min SJ | median SJ | all-hex? | notes |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        size_txt = "%s (%s)" % (("%.4g" % r["size"]), r["label"])
        if "q" not in r:
            lines.append("| %s | %s | %s | — | — | %s | — | — | — | — | — | %s |" % (
                r["model"], size_txt, r["tool"], fmt_s(r["wall"]), r["status"]))
            continue
        q = r["q"]
        n = q["hex"] + q["non_hex"]
        allhex = "yes" if q["non_hex"] == 0 else "no (%s non-hex)" % fmt_int(q["non_hex"])
        notes = []
        if r["tool"] == "Gmsh":
            notes.append(r["gmsh"]["strategy"])
            c = coop_n.get((r["model"], r["label"]))
            if c:
                notes.append("%.2f x Cooperage's count" % (n / c))
            elif nominal_count(r["model"], r["size"]):
                notes.append("%.2f x nominal count %s" % (
                    n / nominal_count(r["model"], r["size"]),
                    fmt_int(int(round(nominal_count(r["model"], r["size"]))))))
            bt = {k: v for k, v in r["gmsh"]["by_type"].items() if k != "hex"}
            if bt:
                notes.append(", ".join("%s %s" % (fmt_int(v), k) for k, v in bt.items()))
            rate_mesh = fmt_rate(n, r["mesh_s"])
            notes.append("%s in generate()" % rate_mesh)
        else:
            notes.append("mesh s from its progress lines (10 ms resolution)")
        if q["inverted"]:
            notes.append("%s inverted" % fmt_int(q["inverted"]))
        med = fmt_q(q["median_sj"]) + ("" if q["median_exact"] else " ~")
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["model"], size_txt, r["tool"], fmt_int(n), fmt_s(r["mesh_s"]), fmt_s(r["wall"]),
            fmt_rate(n, r["wall"]), "%.0f" % r["maxrss"] if r["maxrss"] else "—",
            fmt_q(q["min_sj"]), med, allhex, "; ".join(notes)))
    lines.append("")
    lines.append("Whole harness: %.1f s." % (time.perf_counter() - t_all))
    if errors:
        lines.append("")
        lines.append("Harness errors:")
        lines.extend("* " + e for e in errors)
    print("\n".join(lines))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1, default=str)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
