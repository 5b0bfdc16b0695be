#!/usr/bin/python3
"""Which surfaces of a --dim 2 mesh stay below a scaled Jacobian of 0.2, and
whether their sharpest corner explains it (issue 16).

usage: bench/realcad/corner_bounds.py --bin BUILD/bin/cooperage [--div 40] FILE ...

No element at a corner of interior angle a can have a scaled Jacobian above
sin(a) (a quad's corner sine; a triangle's is scaled by 2/sqrt(3)), so a face
with a 3-degree corner cannot reach 0.2 by any mesh. For each file, meshed as
run_realcad.py does (`cooperage mesh F --size D/DIV --dim 2`), this prints every
surface whose worst element is below 0.2 with its sharpest corner
(`cooperage info --json`, "sharpest_corner") and "at bound" when the worst
element is within 10 % of min(0.2, bound), "BELOW" otherwise: the faces where
the mesher, not the geometry, is the limit. Per-surface minima are the run's
own quality table (printed on stdout when it is not a terminal).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_realcad import DEFAULT_FOLDER, diagonal, info  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--div", type=float, default=40.0)
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.files:
            path = name if os.path.exists(name) else os.path.join(DEFAULT_FOLDER, name)
            model = info(args.bin, path)
            corner = {s["id"]: (s["sharpest_corner"] or {"degrees": 360.0})["degrees"]
                      for s in model["surfaces"]}
            r = subprocess.run([args.bin, "mesh", path, "--size", repr(diagonal(model) / args.div),
                                "--dim", "2", "-o", os.path.join(tmp, "out.vtu")],
                               capture_output=True, text=True, timeout=600)
            worst = {}  # surface -> (min SJ, element type)
            for line in r.stdout.splitlines():
                t = line.split()
                if len(t) > 5 and t[0] == "surface":
                    worst[int(t[1])] = min(worst.get(int(t[1]), (2.0, "")), (float(t[5]), t[3]))
            at_bound = below = 0
            for sid, (sj, kind) in sorted(worst.items()):
                if sj >= 0.2:
                    continue
                a = corner.get(sid, 360.0)
                bound = 1.0 if a >= 90 else math.sin(math.radians(a)) * (2 / math.sqrt(3) if kind == "tri" else 1)
                ok = sj >= 0.9 * min(0.2, bound)
                at_bound += ok
                below += not ok
                print("%s surface %d: %s worst %.3f, sharpest corner %.1f degrees (bound %.3f) %s"
                      % (os.path.basename(path), sid, kind, sj, a, bound, "at bound" if ok else "BELOW"))
            print("%s: exit %d; surfaces below 0.2: %d at their corner's bound, %d below it"
                  % (os.path.basename(path), r.returncode, at_bound, below))


if __name__ == "__main__":
    main()
