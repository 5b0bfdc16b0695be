#!/usr/bin/python3
"""End-to-end benchmark (issue 20): the `cooperage` command run as a user
runs it -- STEP in, Exodus out, one thread, whole process -- against Gmsh's
all-hex route for the same part in the same run, at ~0.1, 1 and 10 M hexes.

    /usr/bin/python3 bench/e2e/run_e2e.py [--models plate_holes,...]
        [--sizes 0.1M,1M,10M] [--repeat 3] [--threads 1] [--no-gmsh]
        [--gmsh-max 1M] [--cooperage build/bin/cooperage] [--work DIR]
        [--json FILE]

Each (model, size) runs Cooperage and Gmsh alternately `--repeat` times,
each run in its own process; the table gives the median wall time, hexes
per second, the peak resident memory of the process (wait4's ru_maxrss)
and its bytes per hex, and the ratio of Gmsh's time per hex to Cooperage's
(> 1: Cooperage is faster). Sizes are chosen from the part's volume,
size = (volume / hexes)^(1/3); the counts then land near the target (paved
caps put ~1 quad per size^2). Long: at 10 M hexes a Cooperage run takes
seconds, a Gmsh run minutes and several GB (--gmsh-max limits Gmsh's
largest size; rows above it say "not run").
"""

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MODELS_PY = os.path.join(HERE, "models.py")
ALL_MODELS = [
    "plate_holes", "cylinder_boss", "stepped_shaft", "block_appendage", "curved_loft_hole"
]


def count(text):
    t = text.strip().upper()
    scale = {"K": 1e3, "M": 1e6}.get(t[-1], 1.0)
    return int(float(t.rstrip("KM")) * scale)


def timed(cmd, timeout):
    """Runs cmd in its own process; returns (returncode or None on timeout,
    stdout, stderr, wall seconds, peak RSS bytes from wait4's ru_maxrss,
    CPU seconds user + system)."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=out, stderr=err, text=True)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
        timed_out = not timer.is_alive()
        timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return (None if timed_out else p.returncode), out.read(), (
            "timeout" if timed_out else err.read()), wall, usage.ru_maxrss * 1024, (
            usage.ru_utime + usage.ru_stime)


def cooperage_hexes(stdout):
    m = re.search(r"hexes (\d+)", stdout)
    return int(m.group(1)) if m else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--models", default=",".join(ALL_MODELS))
    ap.add_argument("--sizes", default="0.1M,1M,10M")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--no-gmsh", action="store_true")
    ap.add_argument("--gmsh-max", default="1M", help="largest target Gmsh runs at")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--cooperage", default=os.environ.get(
        "COOPERAGE", os.path.join(ROOT, "build", "bin", "cooperage")))
    ap.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "cooperage-e2e"))
    ap.add_argument("--json")
    a = ap.parse_args(argv)
    if not os.access(a.cooperage, os.X_OK):
        print("no cooperage binary at " + a.cooperage, file=sys.stderr)
        return 2
    os.makedirs(a.work, exist_ok=True)
    py = "/usr/bin/python3"
    gmsh_max = count(a.gmsh_max)
    rows = []
    for model in a.models.split(","):
        step = os.path.join(a.work, model + ".step")
        made = subprocess.run([py, MODELS_PY, "step", model, step], capture_output=True,
                              text=True, check=True)
        volume = json.loads(made.stdout.strip().splitlines()[-1])["volume"]
        for target_text in a.sizes.split(","):
            target = count(target_text)
            size = (volume / target) ** (1.0 / 3.0)
            tools = ["cooperage"] + ([] if a.no_gmsh or target > gmsh_max else ["gmsh"])
            runs = {t: [] for t in tools}
            for _ in range(a.repeat):  # interleaved, so both see the same load
                for tool in tools:
                    if tool == "cooperage":
                        out_file = os.path.join(a.work, model + ".exo")
                        cmd = [a.cooperage, "mesh", step, "--size", repr(size), "-o", out_file,
                               "--threads", str(a.threads)]
                    else:
                        out_file = os.path.join(a.work, model + ".msh")
                        cmd = [py, MODELS_PY, "gmsh", model, repr(size), out_file]
                    rc, out, err, wall, rss, cpu = timed(cmd, a.timeout)
                    if rc != 0:
                        runs[tool].append({"error": (err or "").strip()[-300:], "wall": wall})
                        continue
                    hexes = cooperage_hexes(out) if tool == "cooperage" else json.loads(
                        out.strip().splitlines()[-1])["hexes"]
                    runs[tool].append({"wall": wall, "cpu": cpu, "rss": rss, "hexes": hexes})
                    if os.path.exists(out_file):
                        os.remove(out_file)
            summary = {}
            for tool, rs in runs.items():
                ok = [r for r in rs if "error" not in r]
                if not ok:
                    summary[tool] = {"error": rs[-1]["error"] if rs else "not run"}
                    continue
                wall = statistics.median(r["wall"] for r in ok)
                cpu = statistics.median(r["cpu"] for r in ok)
                hexes = ok[0]["hexes"]
                rss = max(r["rss"] for r in ok)
                summary[tool] = {"wall": wall, "cpu": cpu, "hexes": hexes, "rss": rss,
                                 "per_hex_us": 1e6 * wall / max(hexes, 1),
                                 "cpu_per_hex_us": 1e6 * cpu / max(hexes, 1)}
            rows.append({"model": model, "target": target_text, "size": size, "tools": summary})
            print_row(rows[-1])
            sys.stdout.flush()
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


HEADER_DONE = False


def print_row(row):
    global HEADER_DONE
    if not HEADER_DONE:
        print("| model | target | size | tool | hexes | wall s | CPU s | M hexes/s (wall) | "
              "peak MB | bytes/hex | Gmsh per hex / Cooperage's (wall; CPU) |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        HEADER_DONE = True
    c = row["tools"].get("cooperage", {})
    g = row["tools"].get("gmsh")
    for tool, r in row["tools"].items():
        if "error" in r:
            print("| %s | %s | %.4g | %s | %s | | | | | | |" % (
                row["model"], row["target"], row["size"], tool, "failed: " + r["error"]))
            continue
        ratio = ""
        if tool == "gmsh" and "per_hex_us" in c:
            ratio = "%.1fx; %.1fx" % (r["per_hex_us"] / c["per_hex_us"],
                                     r["cpu_per_hex_us"] / c["cpu_per_hex_us"])
        print("| %s | %s | %.4g | %s | %d | %.3f | %.3f | %.2f | %.0f | %.0f | %s |" % (
            row["model"], row["target"], row["size"], tool, r["hexes"], r["wall"], r["cpu"],
            r["hexes"] / r["wall"] / 1e6, r["rss"] / 1e6, r["rss"] / max(r["hexes"], 1), ratio))
    if g is None:
        print("| %s | %s | %.4g | gmsh | not run (--gmsh-max / --no-gmsh) | | | | | | |" % (
            row["model"], row["target"], row["size"]))


if __name__ == "__main__":
    sys.exit(main())
