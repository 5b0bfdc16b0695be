#!/usr/bin/python3
"""Two builds on the real CAD (../shared/real-cad): does a change move any mesh?

usage: bench/realcad/compare_builds.py OLD/bin/cooperage NEW/bin/cooperage
           [--dims 2,3] [--div 40] [--folder ../shared/real-cad] [FILE ...]

For each file F and dimension DIM, both builds run
  cooperage mesh F --size D/DIV --dim DIM -o OUT.vtu --threads 1 --quiet
(D: the bounding-box diagonal, `cooperage info --json` of the old build)
and the results are compared: exit codes and stderr equal, and the .vtu
files byte for byte. One line per file and dimension ("same" or what
differs); exit status 1 when anything differs, 77 when the folder is absent.
A change meant to alter no mesh (a refactoring, a rule that should not fire
on these parts) shows here as all "same".
"""
import argparse
import filecmp
import glob
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_realcad import DEFAULT_FOLDER, diagonal, info  # noqa: E402


def compare(old, new, path, dim, div, work):
    model = info(old, path)
    if model is None:
        return "info failed"
    size = diagonal(model) / div
    runs = []
    for tag, binary in (("old", old), ("new", new)):
        out = os.path.join(work, "%s_%d_%s.vtu" % (os.path.basename(path), dim, tag))
        r = subprocess.run([binary, "mesh", path, "--size", repr(size), "--dim", str(dim), "-o", out,
                            "--threads", "1", "--quiet"], capture_output=True, text=True, timeout=600)
        runs.append((r.returncode, r.stderr.strip(), out))
    (rc_old, err_old, out_old), (rc_new, err_new, out_new) = runs
    try:
        if rc_old != rc_new or err_old != err_new:
            return "DIFF exit %d -> %d\n  old: %s\n  new: %s" % (rc_old, rc_new, err_old[:300],
                                                                 err_new[:300])
        if rc_old == 0 and not filecmp.cmp(out_old, out_new, shallow=False):
            return "DIFF mesh"
        return "same (exit %d)" % rc_old
    finally:
        for out in (out_old, out_new):
            if os.path.exists(out):
                os.remove(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--dims", default="2,3")
    ap.add_argument("--div", type=float, default=40.0)
    ap.add_argument("--folder", default=DEFAULT_FOLDER)
    ap.add_argument("files", nargs="*")
    a = ap.parse_intermixed_args()
    files = a.files or sorted(f for f in glob.glob(os.path.join(a.folder, "*"))
                              if f.lower().endswith((".step", ".stp", ".brep")))
    if not files:
        print("no real CAD at %s: skipped" % a.folder)
        return 77
    dims = [int(d) for d in a.dims.split(",")]
    jobs = [(f, d) for d in dims for f in files]
    differ = 0
    with tempfile.TemporaryDirectory(prefix="compare_builds") as work, ThreadPoolExecutor(2) as pool:
        results = pool.map(lambda j: compare(a.old, a.new, j[0], j[1], a.div, work), jobs)
        for (f, d), verdict in zip(jobs, results):
            differ += not verdict.startswith("same")
            print("%-45s --dim %d  %s" % (os.path.basename(f), d, verdict), flush=True)
    print("%d of %d differ" % (differ, len(jobs)))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
