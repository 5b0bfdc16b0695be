#!/usr/bin/python3
"""Rigid-motion campaign (issue 15: every must-mesh part is "rotation
invariant"; the paper's orientation insensitivity): a moved part gives the
moved mesh.

usage: fuzz/motion_campaign.py COUNT --bin BUILD/bin/cooperage [--seed S] [--out DIR] [--case C ...]
       [--finer-retries N]

Builds the random parts of parity_campaign.py (same seed, same parts) and
runs each twice at its own size (no finer retry unless --finer-retries
asks for them, with the other-way sweeps that come with them): as built, and turned
about a random axis through the origin by a random angle, then shifted
(the motion is seeded by the case). Both meshes are read back with meshio
(an independent reader) and compared node by node after moving the first:

  same       largest distance at most 1e-6 of the part's size
  close      at most 1e-2: the same mesh, nodes placed apart by rounding
             that a smoothing or untangling step amplified
  differ     farther, or another node count
  one fails  one of the two runs failed: a choice the motion changed
  both fail  neither meshed (the plan refused, or the run failed)

Writes DIR/results.jsonl and keeps the journals of the cases that differ
or fail one way in DIR/cases/. Exit status 1 when a case differs or fails
one way.
"""
import argparse
import json
import math
import os
import random
import shutil
import sys
import tempfile

import numpy as np
import meshio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import parity_campaign  # noqa: E402


def rotation(axis, degrees):
    a = np.asarray(axis, dtype=float)
    a /= np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    t = math.radians(degrees)
    return np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * k @ k


def final_shape(text):
    for name in ("part", "body"):
        if 'name="%s"' % name in text:
            return name
    return "block"


def run(binary, journal):
    """Exit code (None when it hung) and the first error line."""
    code, err, _, hung = parity_campaign.run([binary, "run", "-q", journal],
                                             os.path.dirname(journal))
    lines = [l for l in err.splitlines() if "error" in l]
    return code, "timed out" if hung else (lines[0][:200] if lines else "")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("count", type=int)
    ap.add_argument("--bin", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="motion_campaign")
    ap.add_argument("--case", type=int, action="append",
                    help="run only this case (repeatable; COUNT is then ignored)")
    ap.add_argument("--finer-retries", type=int, default=0,
                    help="the journals' finer_retries (default 0: each run at its own size only)")
    args = ap.parse_args()
    os.makedirs(os.path.join(args.out, "cases"), exist_ok=True)
    tally = {}
    bad = 0
    with open(os.path.join(args.out, "results.jsonl"), "w") as results, \
            tempfile.TemporaryDirectory() as work:
        for case in args.case or range(args.count):
            text, what = parity_campaign.random_part(random.Random(args.seed * 100003 + case))
            text = text.replace('decompose="off"',
                                'decompose="off" finer_retries="%d"' % args.finer_retries)
            rng = random.Random(7919 * args.seed + case)
            axis = [rng.uniform(-1, 1) for _ in range(3)]
            angle = rng.uniform(-180, 180)
            shift = [rng.uniform(-5, 5) for _ in range(3)]
            shape = final_shape(text)
            motion = ('<rotate shape="%s" axis="%.6f %.6f %.6f" angle="%.6f"/>\n    '
                      '<translate shape="%s" by="%.6f %.6f %.6f"/>\n  </geometry>'
                      % (shape, *axis, angle, shape, *shift))
            journals = {}
            for key, body in (("built", text), ("moved", text.replace("</geometry>", motion))):
                journals[key] = os.path.join(work, "%s.xml" % key)
                with open(journals[key], "w") as f:
                    f.write(body.replace("out.vtu", "%s.vtu" % key))
            (code_a, why_a), (code_b, why_b) = (run(args.bin, journals[k])
                                                for k in ("built", "moved"))
            record = {"case": case, "what": what, "built": why_a, "moved": why_b}
            if code_a != 0 and code_b != 0:
                verdict = "both fail"
            elif code_a != 0 or code_b != 0:
                verdict = "one fails"
            else:
                a = meshio.read(os.path.join(work, "built.vtu"))
                b = meshio.read(os.path.join(work, "moved.vtu"))
                if len(a.points) != len(b.points):
                    verdict = "differ"
                    record["nodes"] = [len(a.points), len(b.points)]
                else:
                    moved = a.points @ rotation(axis, angle).T + np.asarray(shift)
                    size = float(np.ptp(a.points, axis=0).max())
                    d = float(np.linalg.norm(moved - b.points, axis=1).max()) / size
                    record["distance"] = d
                    verdict = "same" if d <= 1e-6 else "close" if d <= 1e-2 else "differ"
            record["verdict"] = verdict
            tally[verdict] = tally.get(verdict, 0) + 1
            if verdict in ("differ", "one fails"):
                bad += 1
                for key in journals:
                    shutil.copy(journals[key], os.path.join(
                        args.out, "cases", "seed%d_case%d_%s.xml" % (args.seed, case, key)))
            results.write(json.dumps(record) + "\n")
            results.flush()
            print("case %d: %s %s" % (case, verdict, record.get("distance", "")), flush=True)
    print("seed %d: %s" % (args.seed, json.dumps(tally, sort_keys=True)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
