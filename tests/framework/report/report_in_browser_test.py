"""The HTML report in a real browser: headless Chromium opens the report of
`cooperage mesh ... --report`, takes a screenshot and dumps the DOM in one
run (one browser start keeps the test to a few seconds on an idle machine). Checked: the mesh picture (a canvas
of the expected size, well covered with colours) and the histogram are on
the screenshot, the page's viewer ran, and nothing went to the console.
Skipped, with a message, where Chromium is not installed."""

import json
import os
import re
import shutil
import struct
import subprocess
import zlib

import numpy
import pytest

CHROMIUM = next((p for p in ("/usr/bin/chromium", shutil.which("chromium"),
                             shutil.which("chromium-browser")) if p and os.path.exists(p)), None)
if CHROMIUM is None:
    pytest.skip("Chromium is not installed: the HTML report is not checked in a browser",
                allow_module_level=True)

CLI = os.environ["COOPERAGE_CLI"]
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
PART = os.path.join(SOURCE, "examples", "part.step")
WINDOW = (1280, 1500)
CANVAS = (520, 400)  # the viewer's canvas, CSS pixels


def read_png(path):
    """RGB(A) pixels of an 8-bit PNG as a (height, width, channels) array."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, header
    bpp = 3 if colour == 2 else 4
    raw = numpy.frombuffer(zlib.decompress(idat), dtype=numpy.uint8).reshape(height, width * bpp + 1)
    out = numpy.zeros((height, width * bpp), dtype=numpy.uint8)
    prev = numpy.zeros(width * bpp, dtype=numpy.int32)
    for y in range(height):
        kind, line = raw[y, 0], raw[y, 1:].astype(numpy.int32)
        if kind == 0:
            row = line
        elif kind == 1:  # Sub: a running sum per channel
            row = numpy.cumsum(line.reshape(width, bpp), axis=0).reshape(-1) % 256
        elif kind == 2:  # Up
            row = (line + prev) % 256
        else:  # Average, Paeth: left to right
            row, cur = line.copy(), [0] * (width * bpp)
            up = prev.tolist()
            values = line.tolist()
            for i in range(width * bpp):
                a = cur[i - bpp] if i >= bpp else 0
                b = up[i]
                if kind == 3:
                    cur[i] = (values[i] + (a + b) // 2) % 256
                else:
                    c = up[i - bpp] if i >= bpp else 0
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                    cur[i] = (values[i] + pred) % 256
            row = numpy.array(cur, dtype=numpy.int32)
        out[y] = row
        prev = row
    return out.reshape(height, width, bpp)[:, :, :3]


def coloured(pixels):
    """Pixels with a clear hue (not white, grey or black): the mesh and bars."""
    p = pixels.astype(int)
    return (p.max(axis=2) - p.min(axis=2)) > 40


def open_in_chromium(html, workdir):
    """Screenshot, DOM and log of one headless run."""
    shot = os.path.join(workdir, "shot.png")
    profile = os.path.join(workdir, "profile")
    os.makedirs(profile)
    r = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
         "--no-first-run", "--disable-background-networking", "--disable-component-update",
         "--disable-sync", "--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0",
         "--hide-scrollbars", "--force-device-scale-factor=1",
         "--window-size=%d,%d" % WINDOW, "--screenshot=" + shot, "--dump-dom",
         "file://" + os.path.abspath(html)],
        capture_output=True, text=True, timeout=90)
    assert r.returncode == 0, r.stderr[-2000:]
    return read_png(shot), r.stdout, r.stderr


def check_report(html, workdir, pictures):
    pixels, dom, log = open_in_chromium(html, workdir)
    assert pixels.shape[:2] == (WINDOW[1], WINDOW[0])
    # Nothing on the console: the page logs nothing, so any line is an error.
    console = [l for l in log.splitlines() if ":CONSOLE" in l]
    assert console == [], console
    root = re.search(r"<html[^>]*>", dom).group(0)
    assert "data-errors" not in root, root
    assert 'data-ready="%d"' % pictures in root, root
    painted = [int(v) for v in re.findall(r'data-painted="(\d+)"', dom)]
    assert len(painted) == pictures
    assert all(v > 0.05 * CANVAS[0] * CANVAS[1] for v in painted), painted
    layout = json.loads(re.search(r"data-layout=\"([^\"]*)\"", root).group(1).replace("&quot;", '"'))
    # The first picture: a canvas of the expected size, on screen, mostly coloured mesh.
    x, y, w, h = layout["canvas"]
    assert (w, h) == (CANVAS[0] + 2, CANVAS[1] + 2), layout  # 1 px border
    assert y + h <= WINDOW[1] and x + w <= WINDOW[0], layout
    mesh = coloured(pixels[y:y + h, x:x + w]).mean()
    assert mesh > 0.08, "the canvas shows %.1f%% coloured pixels" % (100 * mesh)
    # The first histogram: on screen, with coloured bars.
    x, y, w, h = layout["histogram"]
    assert (w, h) == (340, 140) and y + h <= WINDOW[1], layout
    bars = coloured(pixels[y:y + h, x:x + w]).sum()
    assert bars > 100, "the histogram shows %d coloured pixels" % bars
    # Elsewhere the page is mostly white: the colours are where they belong.
    page = coloured(pixels).mean()
    assert page < 0.5, page


@pytest.fixture(scope="module")
def meshed(tmp_path_factory):
    work = tmp_path_factory.mktemp("report")
    exo, html = work / "part.exo", work / "part.html"
    r = subprocess.run([CLI, "mesh", PART, "--size", "2", "-o", str(exo), "--report", str(html), "-q"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "wrote " + str(html) in r.stdout
    volumes = len(set(re.findall(r"^volume (\d+)", r.stdout, re.M)))  # table row and verdict
    return work, exo, html, volumes


def test_mesh_report_shows_the_coloured_mesh_and_the_histogram(meshed, tmp_path):
    work, _, html, volumes = meshed
    assert volumes >= 2, "examples/part.step has several volumes: one picture each"
    assert not [p for p in os.listdir(work) if ".tmp-" in p]
    check_report(html, str(tmp_path), volumes)


def test_quality_report_of_the_exodus_file_renders_the_same_pictures(meshed, tmp_path):
    # The same renderer and viewer as above (checked in the browser there);
    # here only that `cooperage quality --report` gives the pictures their data.
    _, exo, _, volumes = meshed
    q = tmp_path / "q.html"
    r = subprocess.run([CLI, "quality", str(exo), "--report", str(q)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    html = q.read_text()
    assert len(re.findall(r'<canvas class="mesh"', html)) == volumes
    data = json.loads(re.search(r'id="cooperage-data">(.*?)</script>', html, re.S).group(1))
    assert [p["faces"] > 100 for p in data["pictures"]] == [True] * volumes
