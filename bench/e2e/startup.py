#!/usr/bin/python3
"""Start-up of the cooperage command and the Python package, two builds
compared (issue 20: start-up under 50 ms). Rounds are interleaved so that a
change in the machine's speed hits both builds alike; medians of wall time.

  bench/e2e/startup.py OLD_BUILD NEW_BUILD [--rounds 30]

OLD_BUILD and NEW_BUILD are build directories (bin/cooperage, python/).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def commands(build):
    cli = os.path.join(build, "bin", "cooperage")
    part = os.path.join(ROOT, "examples", "part.step")
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    return {
        "--version": ([cli, "--version"], None),
        "run -q brick.xml": ([cli, "run", "-q", "brick.xml"], None),
        "info part.step": ([cli, "info", part], None),
        "mesh part.step --size 4 -o x.vtu -q":
            ([cli, "mesh", part, "--size", "4", "-o", "x.vtu", "-q"], None),
        'python3 -c "import cooperage"': (["/usr/bin/python3", "-c", "import cooperage"], env),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=30)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="cooperage-startup-")
    shutil.copy(os.path.join(ROOT, "examples", "brick.xml"), work)
    builds = {"old": commands(args.old), "new": commands(args.new)}
    times = {}
    try:
        for _ in range(args.rounds):
            for name, cmds in builds.items():
                for label, (cmd, env) in cmds.items():
                    t = time.perf_counter()
                    subprocess.run(cmd, cwd=work, env=env, check=True,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                    times.setdefault((label, name), []).append(time.perf_counter() - t)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("| command | old [ms] | new [ms] | change |")
    print("|---|---|---|---|")
    for label in builds["old"]:
        a = statistics.median(times[(label, "old")]) * 1e3
        b = statistics.median(times[(label, "new")]) * 1e3
        print(f"| `{label}` | {a:.1f} | {b:.1f} | {b - a:+.1f} |")


if __name__ == "__main__":
    main()
