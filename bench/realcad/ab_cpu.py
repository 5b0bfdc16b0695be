#!/usr/bin/python3
"""Two (or more) builds side by side on real CAD: `cooperage mesh F --size
D/40 --threads 1` for each file, the builds interleaved round by round, the
median of each build's child CPU seconds (user + system, getrusage), so a
change's effect is measured under the same load.

usage: bench/realcad/ab_cpu.py OLD/bin/cooperage,NEW/bin/cooperage FILE... [--rounds 3] [--dim 3]
"""
import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import tempfile


def diagonal(binary, path):
    j = json.loads(subprocess.run([binary, "info", path, "--json"], capture_output=True,
                                  text=True, check=True).stdout)
    vs = j["volumes"] or j["surfaces"]
    lo = [min(v["box_min"][i] for v in vs) for i in range(3)]
    hi = [max(v["box_max"][i] for v in vs) for i in range(3)]
    return math.dist(lo, hi)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bins")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--dim", default="3")
    a = ap.parse_args()
    bins = a.bins.split(",")
    out = os.path.join(tempfile.mkdtemp(prefix="ab_cpu"), "out.vtu")
    print("| file | " + " | ".join(bins) + " |")
    print("|---|" + "---|" * len(bins))
    for f in a.files:
        size = diagonal(bins[0], f) / 40
        cpu = {b: [] for b in bins}
        for _ in range(a.rounds):
            for b in bins:
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                subprocess.run([b, "mesh", f, "--size", repr(size), "--dim", a.dim, "-o", out,
                                "--threads", "1", "-q"], capture_output=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu[b].append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
                if os.path.exists(out):
                    os.remove(out)
        print("| %s | %s |" % (os.path.basename(f),
                               " | ".join("%.2f" % statistics.median(cpu[b]) for b in bins)),
              flush=True)


if __name__ == "__main__":
    main()
