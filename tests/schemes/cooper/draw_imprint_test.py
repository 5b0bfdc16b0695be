#!/usr/bin/python3
"""fuzz/draw_imprint.py on a hand-written pair of ends (a square with a
square hole over a plain square): the SVG holds one polygon per loop (the
hole dashed), one line per rib, one dot per fixed node, the labels and the
reason; --zoom scales the drawing to the window asked for.

usage: draw_imprint_test.py SOURCE_DIR WORK_DIR
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def draw(source, work, name, *extra):
    script = os.path.join(source, "fuzz", "draw_imprint.py")
    ends = os.path.join(source, "tests", "schemes", "cooper", "data",
                        "imprint_ends_two_squares.json")
    out = os.path.join(work, name)
    subprocess.run([sys.executable, script, ends, out, *extra], check=True)
    return ET.parse(out).getroot()


def main():
    source, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    root = draw(source, work, "ends.svg", "--ids")
    polygons = root.findall(SVG + "polygon")
    assert len(polygons) == 3, len(polygons)  # upper outer, upper hole, lower
    colours = sorted(p.get("stroke") for p in polygons)
    assert colours == ["blue", "blue", "red"], colours
    assert sum(1 for p in polygons if p.get("stroke-dasharray")) == 1
    assert len(root.findall(SVG + "line")) == 4
    assert len(root.findall(SVG + "circle")) == 4
    texts = [t.text for t in root.findall(SVG + "text")]
    assert any(t and t.startswith("no imprinting step applies") for t in texts), texts
    assert "u1" in texts and "l2" in texts, texts
    # The unit square spans 90 % of the picture; zoomed on its lower left
    # quarter (a window 0.5 wide), its first edge is twice as long.
    def first_edge(r):
        pts = [tuple(map(float, p.split(","))) for p in
               r.findall(SVG + "polygon")[0].get("points").split()]
        return abs(pts[1][0] - pts[0][0])
    zoomed = draw(source, work, "zoom.svg", "--zoom", "0.25,0.25,0.25")
    ratio = first_edge(zoomed) / first_edge(root)
    assert abs(ratio - 2.0) < 1e-3, ratio
    print("draw_imprint: ok")


if __name__ == "__main__":
    main()
