#!/usr/bin/python3
"""Draws a barrel's two ends as cooper's imprinting saw them (issue 15):
the JSON that COOPERAGE_DEBUG_IMPRINT=DIR makes a failing run write
(schemes/cooper/imprint_debug.h), as an SVG in the barrel's chart.

usage: COOPERAGE_DEBUG_IMPRINT=/tmp/imp cooperage run job.xml
       fuzz/draw_imprint.py /tmp/imp/volume1-barrel4-out.json out.svg
           [--zoom=CX,CY,R] [--ids] [--png]

With COOPERAGE_DEBUG_IMPRINT_STEPS=N as well, the ends before each of the
first N steps go to volume1-barrel4-step<k>.json, drawn the same way.

Upper subcaps blue, lower subcaps red (holes dashed), ribs green, nodes of
model curves as dots. --zoom shows the square of half-width R around
(CX, CY) in chart units (written with "=": a negative CX is no option); --ids labels the nodes and the subcaps; --png also
renders OUT.png with Debian's chromium (headless).
"""
import argparse
import json
import os
import subprocess
import sys

SIZE = 1000


def bounds(points):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("svg")
    ap.add_argument("--zoom")
    ap.add_argument("--ids", action="store_true")
    ap.add_argument("--png", action="store_true")
    args = ap.parse_args()
    ends = json.load(open(args.json))
    xy = {int(k): v for k, v in ends["xy"].items()}
    if not xy:
        sys.exit("draw_imprint: no nodes in " + args.json)
    if args.zoom:
        cx, cy, r = (float(t) for t in args.zoom.split(","))
        x0, y0, x1, y1 = cx - r, cy - r, cx + r, cy + r
    else:
        x0, y0, x1, y1 = bounds(list(xy.values()))
    span = max(x1 - x0, y1 - y0) or 1.0
    scale = 0.9 * SIZE / span
    # Chart y up, SVG y down.
    def at(v):
        p = xy[v]
        return (0.05 * SIZE + (p[0] - x0) * scale, 0.95 * SIZE - (p[1] - y0) * scale)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{SIZE}" height="{SIZE}">',
           f'<rect width="{SIZE}" height="{SIZE}" fill="white"/>']
    for u, l in ends["ribs"]:
        if u in xy and l in xy:
            (a, b), (c, d) = at(u), at(l)
            out.append(f'<line x1="{a:.1f}" y1="{b:.1f}" x2="{c:.1f}" y2="{d:.1f}" '
                       'stroke="green" stroke-width="1"/>')
    for end, colour in (("upper", "blue"), ("lower", "red")):
        for cap in ends[end]:
            for k, loop in enumerate(cap["loops"]):
                pts = " ".join("%.1f,%.1f" % at(v) for v in loop if v in xy)
                dash = ' stroke-dasharray="6,3"' if k else ""
                out.append(f'<polygon points="{pts}" fill="none" stroke="{colour}" '
                           f'stroke-width="1.5" stroke-opacity="0.7"{dash}/>')
            if args.ids and cap["loops"] and cap["loops"][0]:
                loop = [at(v) for v in cap["loops"][0] if v in xy]
                x = sum(p[0] for p in loop) / len(loop)
                y = sum(p[1] for p in loop) / len(loop)
                out.append(f'<text x="{x:.1f}" y="{y:.1f}" fill="{colour}" '
                           f'font-size="16">{end[0]}{cap["id"]}</text>')
    for v in ends["fixed"]:
        if v in xy:
            x, y = at(v)
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="2" fill="black"/>')
    if args.ids:
        for v in xy:
            x, y = at(v)
            out.append(f'<text x="{x + 2:.1f}" y="{y - 2:.1f}" font-size="9">{v}</text>')
    if ends.get("why"):
        out.append(f'<text x="10" y="20" font-size="12">{ends["why"][:160]}</text>')
    out.append("</svg>")
    with open(args.svg, "w") as f:
        f.write("\n".join(out) + "\n")
    if args.png:
        png = args.svg.rsplit(".", 1)[0] + ".png"
        subprocess.run(["chromium", "--headless", "--no-sandbox", f"--screenshot={png}",
                        f"--window-size={SIZE + 40},{SIZE + 40}", "file://" + os.path.abspath(args.svg)],
                       check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


if __name__ == "__main__":
    main()
