#!/usr/bin/python3
"""Mutation campaign against the `cooperage` command (issue 21, "Done when").

usage: fuzz/campaign.py KIND COUNT --bin BUILD/bin/cooperage [--seed S] [--out DIR]
  KIND: journal | cad | mesh

Mutates inputs as an attacker or a careless user would and runs the real
binary on each, one at a time (one core), in a fresh directory:
  journal: example and test journals with numbers, names, attributes,
           elements and exports changed, bytes flipped, truncated, spliced;
           `cooperage run -q J`.
  cad:     STEP/BREP files (tests data, ../shared/real-cad or
           $COOPERAGE_REAL_CAD) byte-flipped,
           truncated (also to 1 KB), with numbers changed, lines dropped or
           doubled, spliced; `cooperage info F` then `cooperage mesh F
           --size D/8 -o out.vtu`.
  mesh:    .exo/.msh/.vtu files (tests data and fresh meshes of the examples)
           with bytes flipped (the netCDF header in particular), numbers
           changed, truncated; `cooperage quality F`.
Every run is classified; a case fails on any of: a signal, exit code 3 or
another code than 0/1/2, more than 60 s, more than 3 error lines or an
error line over 500 characters, a file left behind (after a failure: any
new file; after success: anything but the exports), a sanitizer report on
stderr, and exit 0 with an export that fails the independent checks below.
Runs are capped at 2 M elements (--max-elements; see MAX_ELEMENTS).
Independent checks (this file's own readers: meshio for .vtu/.msh/.inp, a
netCDF classic reader written here for .exo): every hex/wedge positive at
all corners, no element face shared by more than two elements, the boundary
closed (every boundary edge in an even number of boundary faces), the total
volume against the CAD's (`cooperage info --json`): when every face is
planar, within the run's own tolerance (1 %, or the journal's
volume_tolerance) -- facets then lose nothing; with curved faces within
25 %, which leaves room for facets of coarse round faces (the program
credits that sliver from the surfaces, which this script cannot see).
Writes DIR/results.jsonl (one line per case) and DIR/summary-FIRST.json;
failing inputs are kept in DIR/failures/. Exit status 1 when any case failed.
"""
import argparse
import glob
import json
import os
import random
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
REAL_CAD = os.environ.get("COOPERAGE_REAL_CAD", os.path.join(ROOT, "..", "shared", "real-cad"))
TIME_LIMIT = 60.0
# A mutated size can ask for a legitimate 40 M-element run (a brick 20,000
# long at size 0.25), which takes minutes and is no hang; the campaign caps
# runs at 2 M elements (--max-elements), so that every run of a correct
# program ends well inside TIME_LIMIT and a refusal above the cap is tested.
MAX_ELEMENTS = "2e6"

# ---------------------------------------------------------------------------
# independent readers and checks


def read_netcdf_classic(path):
    """Variables of a netCDF classic / 64-bit offset file as numpy arrays
    (non-record variables only; enough for Exodus meshes)."""
    data = open(path, "rb").read()
    pos = 0

    def u(n):
        nonlocal pos
        v = int.from_bytes(data[pos:pos + n], "big")
        pos += n
        return v

    def name():
        nonlocal pos
        n = u(4)
        s = data[pos:pos + n].decode("latin1")
        pos += (n + 3) // 4 * 4
        return s

    sizes = {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8}
    fmts = {1: "b", 2: "S1", 3: ">i2", 4: ">i4", 5: ">f4", 6: ">f8"}
    if data[:3] != b"CDF" or data[3] not in (1, 2):
        raise ValueError("not netCDF classic")
    offset = 4 if data[3] == 1 else 8
    pos = 4  # past the magic
    u(4)  # numrecs
    tag, n = u(4), u(4)
    dims = []
    for _ in range(n):
        name()
        dims.append(u(4))

    def atts():
        nonlocal pos
        tag, n = u(4), u(4)
        for _ in range(n):
            name()
            t, k = u(4), u(4)
            pos += (k * sizes[t] + 3) // 4 * 4

    atts()
    tag, n = u(4), u(4)
    out = {}
    for _ in range(n):
        nm = name()
        rank = u(4)
        ids = [u(4) for _ in range(rank)]
        atts()
        t = u(4)
        u(4)
        begin = u(offset)
        shape = [dims[i] for i in ids]
        if 0 in shape:
            continue  # record variable
        count = int(np.prod(shape)) if shape else 1
        out[nm] = np.frombuffer(data, dtype=fmts[t], count=count, offset=begin).reshape(shape)
    return out


def read_mesh(path):
    """(points, [(kind, cells)]) with kind in hex, wedge, quad, tri."""
    if path.endswith(".exo"):
        v = read_netcdf_classic(path)
        pts = np.stack([v.get("coordx"), v.get("coordy"),
                        v.get("coordz", np.zeros_like(v["coordx"]))], axis=1).astype(float)
        blocks = []
        for k in sorted(x for x in v if re.fullmatch(r"connect\d+", x)):
            c = v[k].astype(int) - 1
            kind = {8: "hex", 6: "wedge", 4: "quad", 3: "tri"}.get(c.shape[1])
            if kind:
                blocks.append((kind, c))
        return pts, blocks
    import meshio
    m = meshio.read(path)
    names = {"hexahedron": "hex", "wedge": "wedge", "quad": "quad", "triangle": "tri"}
    return np.asarray(m.points, float), [(names[b.type], np.asarray(b.data, int))
                                         for b in m.cells if b.type in names]


HEX_CORNERS = [(0, 1, 3, 4), (1, 2, 0, 5), (2, 3, 1, 6), (3, 0, 2, 7),
               (4, 7, 5, 0), (5, 4, 6, 1), (6, 5, 7, 2), (7, 6, 4, 3)]
WEDGE_CORNERS = [(0, 1, 2, 3), (1, 2, 0, 4), (2, 0, 1, 5), (3, 5, 4, 0), (4, 3, 5, 1), (5, 4, 3, 2)]
HEX_FACES = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1), (4, 5, 6, 7)]
WEDGE_FACES = [(0, 1, 4, 3), (1, 2, 5, 4), (0, 3, 5, 2), (0, 2, 1), (3, 4, 5)]
HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
WEDGE_TETS = [(0, 1, 2, 3), (1, 2, 3, 4), (2, 5, 3, 4)]


def corner_dets(p, cells, corners):
    q = p[cells]
    dets = []
    for c, a, b, d in corners:
        e1, e2, e3 = q[:, a] - q[:, c], q[:, b] - q[:, c], q[:, d] - q[:, c]
        dets.append(np.einsum("ij,ij->i", e1, np.cross(e2, e3)))
    return np.min(np.stack(dets, 1), axis=1)


def tet_volume(p, cells, tets):
    q = p[cells]
    return sum(np.einsum("ij,ij->i", q[:, b] - q[:, a], np.cross(q[:, c] - q[:, a], q[:, d] - q[:, a]))
               for a, b, c, d in tets) / 6.0


def check_mesh(path, cad_volume, tolerance=0.25):
    """'' when the mesh passes, else the first problem; tolerance is the
    allowed relative volume deviation."""
    pts, blocks = read_mesh(path)
    if len(pts) == 0 or not np.isfinite(pts).all():
        return "no nodes or non-finite coordinates"
    vol_blocks = [(k, c) for k, c in blocks if k in ("hex", "wedge")]
    if not vol_blocks:
        return "" if blocks else "no elements"
    faces = {}  # sorted nodes -> [uses, nodes in ring order]
    volume = 0.0
    for kind, c in vol_blocks:
        if c.min() < 0 or c.max() >= len(pts):
            return "node index out of range"
        corners, table, tets = ((HEX_CORNERS, HEX_FACES, HEX_TETS) if kind == "hex"
                                else (WEDGE_CORNERS, WEDGE_FACES, WEDGE_TETS))
        if (corner_dets(pts, c, corners) <= 0).any():
            return kind + " with a non-positive corner Jacobian"
        volume += tet_volume(pts, c, tets).sum()
        for row in c:
            for f in table:
                ring = tuple(int(row[i]) for i in f)
                entry = faces.setdefault(tuple(sorted(ring)), [0, ring])
                entry[0] += 1
    if max(n for n, _ in faces.values()) > 2:
        return "an element face shared by more than two elements"
    edges = {}
    for n, ring in faces.values():
        if n != 1:
            continue
        for i in range(len(ring)):
            a, b = ring[i], ring[(i + 1) % len(ring)]
            e = (min(a, b), max(a, b))
            edges[e] = edges.get(e, 0) + 1
    if any(n % 2 for n in edges.values()):
        return "the boundary is not closed"
    if cad_volume and cad_volume > 0 and abs(volume - cad_volume) > tolerance * cad_volume:
        return "volume %.6g against the CAD's %.6g" % (volume, cad_volume)
    return ""


# ---------------------------------------------------------------------------
# mutators

WEIRD_NUMBERS = ["0", "-1", "1e-9", "4.9e-324", "1e300", "-1e300", "nan", "inf", "2147483647",
                 "65535", "65536", "-0", "1e7", "1e-7", "0x10", "1,5", ""]


def mutate_numbers(text, rng, weird=WEIRD_NUMBERS):
    nums = list(re.finditer(r"-?\d+\.?\d*(?:[eE][-+]?\d+)?", text))
    if not nums:
        return text
    m = rng.choice(nums)
    r = rng.random()
    if r < 0.4:
        new = rng.choice(weird)
    else:
        try:
            v = float(m.group())
            new = repr(v * rng.choice([1e-4, 1e-2, 0.5, 2, 1e2, 1e4, -1]))
        except ValueError:
            new = "1"
    return text[:m.start()] + new + text[m.end():]


def flip_bytes(data, rng, n=None, region=None):
    b = bytearray(data)
    if not b:
        return bytes(b)
    lo, hi = region or (0, len(b))
    hi = min(hi, len(b))
    for _ in range(n or rng.randint(1, 8)):
        i = rng.randrange(lo, hi) if hi > lo else rng.randrange(len(b))
        b[i] = rng.choice([b[i] ^ (1 << rng.randrange(8)), rng.randrange(256), 0, 0xFF])
    return bytes(b)


def truncate(data, rng):
    if len(data) < 2:
        return data
    return data[:rng.choice([1024, rng.randrange(1, len(data))])]


def splice(a, b, rng):
    return a[:rng.randrange(len(a) + 1)] + b[rng.randrange(len(b) + 1):]


def lines_op(data, rng):
    lines = data.split(b"\n")
    if len(lines) < 3:
        return data
    i = rng.randrange(len(lines))
    op = rng.random()
    if op < 0.4:
        del lines[i]
    elif op < 0.8:
        lines.insert(i, lines[rng.randrange(len(lines))])
    else:
        lines[i] = lines[i][::-1]
    return b"\n".join(lines)


JOURNAL_INSERTS = [
    '<curve id="1" intervals="{n}"/>', '<curve id="2" intervals="{n}" firmness="hard"/>',
    '<volume id="1" scheme="map"/>', '<volume id="2" scheme="cooper"/>',
    '<surface id="1" scheme="pave"/>', '<volume id="1" elements="wedge"/>',
    '<vertex_type surface="1" vertex="1" type="corner"/>',
    '<curve id="3" bias="geometric" ratio="{r}"/>',
]
EXPORT_NAMES = ["nodir/x.exo", ".", "/", "sub", "sub/x.exo", "a" * 300 + ".exo",
                "b" * 245 + ".exo", "x.txt", "dup.exo", "dup.exo", "x.msh", "x.vtu", "x.inp",
                "../escape.vtu", "/proc/x.exo", "x.e", "X.EXO", "é.vtu", "a b.msh"]


def mutate_journal(text, others, rng):
    for _ in range(rng.randint(1, 3)):
        op = rng.random()
        if op < 0.3:
            text = mutate_numbers(text, rng)
        elif op < 0.4:
            # a long name or tag
            big = "n" * rng.choice([65, 300, 10000])
            text = re.sub(r'name="[^"]*"', 'name="%s"' % big, text, count=1) if rng.random() < 0.5 \
                else text.replace("<brick", "<" + big, 1)
        elif op < 0.5:
            ins = rng.choice(JOURNAL_INSERTS).format(n=rng.choice([0, 1, 3, 1000, 65535, 2147483647]),
                                                     r=rng.choice(["1.1", "0", "1e300"]))
            text = text.replace("</mesh>", "  %s\n  </mesh>" % ins, 1) if "</mesh>" in text else \
                text.replace("<mesh ", "<mesh>%s</mesh><mesh " % ins, 1)
        elif op < 0.6:
            exp = rng.choice(EXPORT_NAMES)
            text = text.replace("</cooperage>", '  <export file="%s"/>\n</cooperage>' % exp, 1)
        elif op < 0.65:
            text = re.sub(r'<mesh ', '<mesh threads="%s" ' % rng.choice(["2147483647", "64", "0"]),
                          text, count=1)
        elif op < 0.75:
            text = lines_op(text.encode(), rng).decode("latin1")
        elif op < 0.85:
            text = flip_bytes(text.encode("latin1", "replace"), rng).decode("latin1")
        elif op < 0.92:
            text = splice(text, rng.choice(others), rng)
        else:
            text = truncate(text.encode("latin1", "replace"), rng).decode("latin1")
    return text


def mutate_cad(data, others, rng):
    for _ in range(rng.randint(1, 3)):
        op = rng.random()
        if op < 0.25:
            data = flip_bytes(data, rng)
        elif op < 0.4:
            data = truncate(data, rng)
        elif op < 0.65:
            text = data.decode("latin1")
            for _ in range(rng.randint(1, 5)):
                text = mutate_numbers(text, rng, ["0", "1e300", "-1e300", "1e-300", "nan",
                                                  "999999", "-5", "1e20", "2147483648"])
            data = text.encode("latin1")
        elif op < 0.85:
            data = lines_op(data, rng)
        else:
            data = splice(data, rng.choice(others), rng)
    return data


def mutate_mesh(data, others, rng, ext):
    op = rng.random()
    if ext == ".exo":
        if op < 0.5:
            return flip_bytes(data, rng, region=(0, 1200))  # the netCDF header
        if op < 0.7:
            # a 32-bit count in the header set to something huge
            b = bytearray(data)
            i = rng.randrange(4, min(1200, len(b) - 4)) & ~3
            b[i:i + 4] = struct.pack(">I", rng.choice([0x7FFFFFFF, 0xFFFFFFFF, 0x10000000, 0]))
            return bytes(b)
        if op < 0.85:
            return truncate(data, rng)
        return flip_bytes(data, rng)
    if op < 0.4:
        text = data.decode("latin1")
        for _ in range(rng.randint(1, 4)):
            text = mutate_numbers(text, rng, ["-1", "0", "2147483647", "99999999999", "1e308",
                                              "nan", "18446744073709551615", "3"])
        return text.encode("latin1")
    if op < 0.6:
        return lines_op(data, rng)
    if op < 0.8:
        return truncate(data, rng)
    return flip_bytes(data, rng)


# ---------------------------------------------------------------------------
# running


def run(cmd, cwd, env):
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=TIME_LIMIT + 5)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        timed_out = True
    seconds = time.monotonic() - t0
    return {"rc": proc.returncode, "seconds": round(seconds, 3), "timed_out": timed_out,
            # stdout as the file system decodes names (an export named with
            # a Latin-1 byte is listed by os.listdir the same way)
            "out": out.decode("utf-8", "surrogateescape"), "err": err.decode("utf-8", "replace")}


def classify(r):
    """The failures of one run (empty: fine)."""
    bad = []
    if r["timed_out"] or r["seconds"] > TIME_LIMIT:
        bad.append("hang")
    elif r["rc"] < 0:
        bad.append("signal %d" % -r["rc"])
    elif r["rc"] == 3:
        bad.append("exit 3")
    elif r["rc"] not in (0, 1, 2):
        bad.append("exit %d" % r["rc"])
    err_lines = [line for line in r["err"].splitlines() if line.strip()]
    if "Sanitizer" in r["err"] or "runtime error:" in r["err"]:
        bad.append("sanitizer")
    if r["rc"] == 2 and (len(err_lines) > 3 or any(len(x) > 500 for x in err_lines)):
        bad.append("long error")
    return bad


CURVED_TOLERANCE = 0.25  # facets of coarse round faces; see the docstring


def volume_tolerance(info, journal_text=""):
    """The relative volume deviation a mesh of this model may have: the
    run's own (1 %, or the largest volume_tolerance the journal sets, in
    percent, at most 100) when every face is planar, else CURVED_TOLERANCE."""
    if any(s.get("type") != "plane" for s in info.get("surfaces", [])):
        return CURVED_TOLERANCE
    percent = 1.0
    for value in re.findall(r'volume_tolerance\s*=\s*"([^"]*)"', journal_text):
        try:
            v = float(value)
        except ValueError:
            continue
        if v == v and v > 0:  # not NaN: the reader refuses what is not a number
            percent = max(percent, min(v, 100.0))
    return percent / 100.0 + 1e-4  # + round-off in the written coordinates


def cad_volume(binary, target, cwd, env, journal_text=""):
    """(volume, tolerance) of the model, or (None, CURVED_TOLERANCE)."""
    r = run([binary, "info", "--json", target], cwd, env)
    if r["rc"] != 0:
        return None, CURVED_TOLERANCE
    try:
        info = json.loads(r["out"])
        return sum(v["volume"] for v in info["volumes"]), volume_tolerance(info, journal_text)
    except (ValueError, KeyError, TypeError):
        return None, CURVED_TOLERANCE


def export_files(journal_text):
    return re.findall(r'<export\s+file="([^"]*)"', journal_text)


def case_journal(binary, text, tmp, env):
    path = os.path.join(tmp, "job.xml")
    open(path, "w", encoding="latin1").write(text)
    before = set(os.listdir(tmp))
    r = run([binary, "run", "-q", "--max-elements", MAX_ELEMENTS, path], tmp, env)
    bad = classify(r)
    after = set(os.listdir(tmp))
    new = sorted(after - before)
    wrote = [os.path.basename(line[6:]) for line in r["out"].splitlines() if line.startswith("wrote ")]
    if r["rc"] not in (0, 1):
        if new:
            bad.append("leftover %s" % new[:3])
    elif "exports skipped" in r["out"]:
        # A failed quality check skips the mesh exports but still writes the
        # HTML report it announces: the report is how one sees what failed.
        strays = [f for f in new if not (f in wrote and f.lower().endswith((".html", ".htm")))]
        if strays:
            bad.append("leftover %s" % strays[:3])
    else:
        strays = [f for f in new if f not in wrote]
        if strays:
            bad.append("leftover %s" % strays[:3])
        wrote = [line[6:] for line in r["out"].splitlines() if line.startswith("wrote ")]
        if r["rc"] == 0 and wrote and not bad:
            vol, tol = cad_volume(binary, path, tmp, env, text)
            for w in wrote:
                if not os.path.isfile(w):
                    bad.append("missing export")
                    break
                if not w.lower().endswith((".exo", ".e", ".g", ".msh", ".vtu", ".inp")):
                    continue  # an HTML report, not a mesh
                try:
                    problem = check_mesh(w, vol, tol)
                except Exception as e:  # an unreadable export is a failure
                    problem = "unreadable export (%s)" % e
                if problem:
                    bad.append("bad mesh: " + problem)
                    break
    return r, bad


def case_cad(binary, data, ext, tmp, env):
    path = os.path.join(tmp, "part" + ext)
    open(path, "wb").write(data)
    before = set(os.listdir(tmp))
    r = run([binary, "info", path], tmp, env)
    bad = classify(r)
    runs = [r]
    if r["rc"] == 0 and not bad:
        vol, tol = None, CURVED_TOLERANCE
        info = run([binary, "info", "--json", path], tmp, env)
        size = 1.0
        try:
            j = json.loads(info["out"])
            vol = sum(v["volume"] for v in j["volumes"])
            tol = volume_tolerance(j)
            lo = np.min([v["box_min"] for v in j["volumes"]], 0)
            hi = np.max([v["box_max"] for v in j["volumes"]], 0)
            size = float(np.linalg.norm(hi - lo)) / 8 or 1.0
        except (ValueError, KeyError):
            pass
        m = run([binary, "mesh", path, "--size", "%.6g" % size, "-o", "out.vtu", "-q",
                 "--max-elements", MAX_ELEMENTS], tmp, env)
        runs.append(m)
        bad += classify(m)
        new = sorted(set(os.listdir(tmp)) - before)
        if m["rc"] != 0 and new:
            bad.append("leftover %s" % new[:3])
        if m["rc"] == 0 and not bad:
            try:
                problem = check_mesh(os.path.join(tmp, "out.vtu"), vol, tol)
            except Exception as e:
                problem = "unreadable export (%s)" % e
            if problem:
                bad.append("bad mesh: " + problem)
    else:
        new = sorted(set(os.listdir(tmp)) - before)
        if new:
            bad.append("leftover %s" % new[:3])
    return runs, bad


def case_mesh(binary, data, ext, tmp, env):
    path = os.path.join(tmp, "mesh" + ext)
    open(path, "wb").write(data)
    before = set(os.listdir(tmp))
    r = run([binary, "quality", path], tmp, env)
    bad = classify(r)
    if r["rc"] == 1:
        bad.append("exit 1")  # quality has no failing checks
    new = sorted(set(os.listdir(tmp)) - before)
    if new:
        bad.append("leftover %s" % new[:3])
    return r, bad


def mesh_seeds(binary, out):
    """Mesh files: the test data plus fresh meshes of a few examples."""
    files = sorted(glob.glob(os.path.join(ROOT, "tests", "framework", "io", "read", "data", "*")))
    os.makedirs(out, exist_ok=True)
    for ex in ["brick", "bracket", "plate_wedges", "sharp_corner_mixed", "cylinder_boss"]:
        d = tempfile.mkdtemp(dir=out)
        shutil.copy(os.path.join(ROOT, "examples", ex + ".xml"), d)
        text = open(os.path.join(d, ex + ".xml")).read()
        text = re.sub(r'\s*<export[^>]*/>', "", text)
        for e in (".exo", ".msh", ".vtu"):
            text = text.replace("</cooperage>", '<export file="%s%s"/></cooperage>' % (ex, e))
        open(os.path.join(d, ex + ".xml"), "w").write(text)
        subprocess.run([binary, "run", "-q", ex + ".xml"], cwd=d, capture_output=True)
        files += sorted(glob.glob(os.path.join(d, ex + ".*")))
    return [f for f in files if f.endswith((".exo", ".msh", ".vtu"))]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["journal", "cad", "mesh"])
    ap.add_argument("count", type=int)
    ap.add_argument("--bin", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=None)
    ap.add_argument("--start", type=int, default=0, help="first case number (to resume)")
    args = ap.parse_args()
    binary = os.path.abspath(args.bin)
    out = os.path.abspath(args.out or "campaign-%s" % args.kind)
    os.makedirs(os.path.join(out, "failures"), exist_ok=True)
    env = dict(os.environ)
    env.setdefault("ASAN_OPTIONS", "detect_leaks=0:abort_on_error=0")
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    if args.kind == "journal":
        seeds = sorted(glob.glob(os.path.join(ROOT, "examples", "*.xml")) +
                       glob.glob(os.path.join(ROOT, "tests", "**", "data", "*.xml"), recursive=True))
        texts = [open(f, encoding="latin1").read() for f in seeds]
    elif args.kind == "cad":
        seeds = sorted(glob.glob(os.path.join(ROOT, "tests", "framework", "geometry", "occ", "data", "*.*")) +
                       [f for f in glob.glob(os.path.join(REAL_CAD, "*")) if f.endswith(
                           (".step", ".stp", ".brep")) and os.path.getsize(f) <= 400000])
        blobs = [open(f, "rb").read() for f in seeds]
    else:
        seeds = mesh_seeds(binary, os.path.join(out, "seeds"))
        blobs = [open(f, "rb").read() for f in seeds]

    counts = {}
    results = open(os.path.join(out, "results.jsonl"), "a")
    t_start = time.time()
    for i in range(args.start, args.start + args.count):
        rng = random.Random(args.seed * 1000003 + i)
        tmp = tempfile.mkdtemp(prefix="case-", dir=out)
        k = rng.randrange(len(seeds))
        source = os.path.basename(seeds[k])
        if args.kind == "journal":
            text = mutate_journal(texts[k], texts, rng)
            r, bad = case_journal(binary, text, tmp, env)
            payload, ext = text.encode("latin1", "replace"), ".xml"
            rcs = [r["rc"]]
            secs = r["seconds"]
            errs = r["err"]
        elif args.kind == "cad":
            ext = os.path.splitext(seeds[k])[1]
            payload = mutate_cad(blobs[k], blobs, rng)
            runs, bad = case_cad(binary, payload, ext, tmp, env)
            rcs = [x["rc"] for x in runs]
            secs = sum(x["seconds"] for x in runs)
            errs = "".join(x["err"] for x in runs)
        else:
            ext = os.path.splitext(seeds[k])[1]
            payload = mutate_mesh(blobs[k], blobs, rng, ext)
            r, bad = case_mesh(binary, payload, ext, tmp, env)
            rcs = [r["rc"]]
            secs = r["seconds"]
            errs = r["err"]
        for b in bad:
            key = b.split(":")[0].split(" [")[0]
            counts[key] = counts.get(key, 0) + 1
        for rc in rcs:
            counts["rc=%d" % rc] = counts.get("rc=%d" % rc, 0) + 1
        if bad:
            open(os.path.join(out, "failures", "case%06d%s" % (i, ext)), "wb").write(payload)
        results.write(json.dumps({"case": i, "source": source, "rc": rcs, "seconds": secs,
                                  "bad": bad, "err": errs[-400:]}) + "\n")
        results.flush()
        shutil.rmtree(tmp, ignore_errors=True)
    summary = {"kind": args.kind, "cases": args.count, "first": args.start, "seed": args.seed,
               "binary": binary, "wall_seconds": round(time.time() - t_start), "counts": counts}
    json.dump(summary, open(os.path.join(out, "summary-%d.json" % args.start), "w"), indent=1)
    print(json.dumps(summary, indent=1))
    failures = sum(n for k, n in counts.items() if not k.startswith("rc="))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
