#!/usr/bin/python3
"""The end-to-end benchmark's parts, built in Gmsh's OCC kernel (Gmsh 4.8.4,
Debian's /usr/bin/python3): each is written once as a STEP file that
Cooperage reads, and meshed all-hex by Gmsh the way a skilled Gmsh user would.

    /usr/bin/python3 models.py step MODEL OUT.step
    /usr/bin/python3 models.py gmsh MODEL SIZE OUT.msh

`gmsh` prints one JSON line: hexes, generate() seconds, whole seconds.
Gmsh builds its own copy of the geometry (extrusion and transfinite meshing
need the entities created by extrude/ThruSections, not an imported solid);
the shapes are the same as the STEP files'.

Parts (the issue 20 set):
  * plate_holes: 10 x 6 x 1 plate, three through holes r 0.8 (one-to-one);
    Gmsh: the face with holes meshed in quads (frontal-Delaunay + Blossom)
    and extruded with layers.
  * cylinder_boss: cylinder r 2 h 3 with a coaxial boss r 1 h 1.5
    (many-to-one); Gmsh: split by hand into disc + annulus, extruded twice.
  * stepped_shaft: coaxial cylinders r 2, 1.5 and 1, each 1 high, stacked
    (many-to-one, three levels); Gmsh: split by hand into a disc and two
    annuli, extruded, then the inner two again, then the disc.
  * block_appendage: a 6 x 4 x 1 block with a 2 x 2 x 1.5 block standing on
    its middle (many-to-one); Gmsh: the base face split by hand into the
    square under the appendage and the frame around it, extruded, then the
    square again.
  * curved_loft_hole: a loft from a circle r 2 at z 0 to a circle r 2.6 at
    z 3 moved 0.6 sideways, with a lofted hole (r 0.8 to 1.1): B-spline side
    faces (an oblique cone, as OCCT lofts it); Gmsh: four lofted quadrant
    blocks, transfinite volumes. (Three sections would give Gmsh's
    ThruSections side faces with six corners, which its transfinite
    meshing refuses.)
"""

import json
import math
import sys
import time

import gmsh

QUAD_SIZE_FACTOR = 1.08  # as bench/peers/gmsh_models.py: ~1 quad per size^2

LOFT_SECTIONS = [  # (z, outer radius, centre x, hole radius)
    (0.0, 2.0, 0.0, 0.8),
    (3.0, 2.6, 0.6, 1.1),
]


def intervals(length, size):
    return max(1, int(math.floor(length / size + 0.5)))


def _quads(size):
    gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    h = size * QUAD_SIZE_FACTOR
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)


# ---- solids for the STEP files ------------------------------------------------

def solid_plate_holes():
    occ = gmsh.model.occ
    box = occ.addBox(0, 0, 0, 10, 6, 1)
    holes = [(3, occ.addCylinder(x, 3, -0.5, 0, 0, 2, 0.8)) for x in (2.5, 5.0, 7.5)]
    occ.cut([(3, box)], holes)


def solid_cylinder_boss():
    occ = gmsh.model.occ
    body = occ.addCylinder(0, 0, 0, 0, 0, 3, 2)
    boss = occ.addCylinder(0, 0, 3, 0, 0, 1.5, 1)
    occ.fuse([(3, body)], [(3, boss)])


STEPS = [(2.0, 1.0), (1.5, 1.0), (1.0, 1.0)]  # stepped_shaft: (radius, height), bottom up


def solid_stepped_shaft():
    occ = gmsh.model.occ
    z, parts = 0.0, []
    for r, h in STEPS:
        parts.append((3, occ.addCylinder(0, 0, z, 0, 0, h, r)))
        z += h
    occ.fuse(parts[:1], parts[1:])


def solid_block_appendage():
    occ = gmsh.model.occ
    base = occ.addBox(0, 0, 0, 6, 4, 1)
    lug = occ.addBox(2, 1, 1, 2, 2, 1.5)
    occ.fuse([(3, base)], [(3, lug)])


def solid_curved_loft_hole():
    occ = gmsh.model.occ
    outer, inner = [], []
    for z, big, cx, small in LOFT_SECTIONS:
        outer.append(occ.addCurveLoop([occ.addCircle(cx, 0, z, big)]))
        inner.append(occ.addCurveLoop([occ.addCircle(cx, 0, z, small)]))
    vo = occ.addThruSections(outer, makeSolid=True, makeRuled=False)
    vi = occ.addThruSections(inner, makeSolid=True, makeRuled=False)
    occ.cut(vo, vi)


# ---- Gmsh's all-hex routes --------------------------------------------------------

def gmsh_plate_holes(size):
    occ = gmsh.model.occ
    rect = occ.addRectangle(0, 0, 0, 10, 6)
    disks = [(2, occ.addDisk(x, 3, 0, 0.8, 0.8)) for x in (2.5, 5.0, 7.5)]
    face, _ = occ.cut([(2, rect)], disks)
    occ.extrude(face, 0, 0, 1, numElements=[intervals(1, size)], recombine=True)
    occ.synchronize()
    _quads(size)
    return "face quads (frontal-Delaunay + Blossom) extruded with layers"


def _top_faces(entities, z, within):
    """The faces among `entities` lying in the plane at height z whose
    bounding box lies within `within` (x0, y0, x1, y1)."""
    faces = []
    for dim, tag in entities:
        if dim != 2:
            continue
        x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(dim, tag)
        if abs(z0 - z) < 1e-7 and abs(z1 - z) < 1e-7 and x0 > within[0] - 1e-6 and \
                y0 > within[1] - 1e-6 and x1 < within[2] + 1e-6 and y1 < within[3] + 1e-6:
            faces.append((dim, tag))
    return faces


def _extrude_stack(base, stack, size):
    """A many-to-one part split by hand, extruded as a Gmsh user would:
    `base` (faces at z = 0) by the first height, then the top faces within
    each level's footprint (x0, y0, x1, y1) by the next height; the last
    level has no footprint."""
    occ = gmsh.model.occ
    layer, z = base, 0.0
    for h, within in stack:
        made = occ.extrude(layer, 0, 0, h, numElements=[intervals(h, size)], recombine=True)
        occ.synchronize()
        z += h
        if within is not None:
            layer = _top_faces(made, z, within)
    _quads(size)


def gmsh_cylinder_boss(size):
    occ = gmsh.model.occ
    inner = occ.addDisk(0, 0, 0, 1, 1)
    outer = occ.addDisk(0, 0, 0, 2, 2)
    base, _ = occ.fragment([(2, outer)], [(2, inner)])
    _extrude_stack(base, [(3, (-1, -1, 1, 1)), (1.5, None)], size)
    return "split by hand into disc + annulus, quads extruded with layers"


def gmsh_stepped_shaft(size):
    occ = gmsh.model.occ
    disks = [(2, occ.addDisk(0, 0, 0, r, r)) for r, _ in STEPS]
    base, _ = occ.fragment(disks[:1], disks[1:])
    footprints = [(-r, -r, r, r) for r, _ in STEPS[1:]] + [None]
    _extrude_stack(base, [(h, f) for (_, h), f in zip(STEPS, footprints)], size)
    return "split by hand into a disc and two annuli, quads extruded three times"


def gmsh_block_appendage(size):
    occ = gmsh.model.occ
    rect = occ.addRectangle(0, 0, 0, 6, 4)
    square = occ.addRectangle(2, 1, 0, 2, 2)
    base, _ = occ.fragment([(2, rect)], [(2, square)])
    _extrude_stack(base, [(1, (2, 1, 4, 3)), (1.5, None)], size)
    return "split by hand into the square and its frame, quads extruded twice"


def gmsh_curved_loft_hole(size):
    """Four quadrant blocks, each lofted through its (outer arc, radial line,
    inner arc, radial line) wires; transfinite with round(length/size)
    intervals per curve (opposite curves of a block share the larger count)."""
    occ = gmsh.model.occ
    blocks = []
    for q in range(4):
        a0, a1 = q * math.pi / 2, (q + 1) * math.pi / 2
        wires = []
        for z, big, cx, small in LOFT_SECTIONS:
            c = occ.addPoint(cx, 0, z)
            p = [occ.addPoint(cx + r * math.cos(a), r * math.sin(a), z)
                 for r, a in ((big, a0), (big, a1), (small, a1), (small, a0))]
            edges = [occ.addCircleArc(p[0], c, p[1]), occ.addLine(p[1], p[2]),
                     occ.addCircleArc(p[2], c, p[3]), occ.addLine(p[3], p[0])]
            wires.append(occ.addWire(edges))
        blocks += occ.addThruSections(wires, makeSolid=True, makeRuled=False)
    occ.fragment(blocks[:1], blocks[1:])
    occ.synchronize()
    # Sweep direction: round(height/size); arcs: the outer arc's count (the
    # inner arc must match it); radial lines: round(width/size).
    n_arc = intervals(0.5 * math.pi * max(s[1] for s in LOFT_SECTIONS), size)
    n_rad = intervals(max(s[1] - s[3] for s in LOFT_SECTIONS), size)
    for _, c in gmsh.model.getEntities(1):
        x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(1, c)
        if z1 - z0 > 1e-6:
            n = intervals(LOFT_SECTIONS[-1][0] - LOFT_SECTIONS[0][0], size)
        elif gmsh.model.getType(1, c) in ("Circle", "BSpline", "Ellipse"):
            n = n_arc
        else:
            n = n_rad
        gmsh.model.mesh.setTransfiniteCurve(c, n + 1)
    for _, s in gmsh.model.getEntities(2):
        gmsh.model.mesh.setTransfiniteSurface(s)
        gmsh.model.mesh.setRecombine(2, s)
    for _, v in gmsh.model.getEntities(3):
        gmsh.model.mesh.setTransfiniteVolume(v)
    return "four lofted quadrant blocks, transfinite volumes"


MODELS = {
    "plate_holes": (solid_plate_holes, gmsh_plate_holes),
    "cylinder_boss": (solid_cylinder_boss, gmsh_cylinder_boss),
    "curved_loft_hole": (solid_curved_loft_hole, gmsh_curved_loft_hole),
    "stepped_shaft": (solid_stepped_shaft, gmsh_stepped_shaft),
    "block_appendage": (solid_block_appendage, gmsh_block_appendage),
}


def _start():
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)


def write_step(name, out):
    """The part as one solid in a STEP file; returns its volume."""
    _start()
    try:
        gmsh.model.add(name)
        MODELS[name][0]()
        gmsh.model.occ.synchronize()
        volume = sum(gmsh.model.occ.getMass(3, v) for _, v in gmsh.model.getEntities(3))
        gmsh.write(out)
    finally:
        gmsh.finalize()
    return volume


def mesh_gmsh(name, size, out):
    t_start = time.perf_counter()
    _start()
    try:
        gmsh.model.add(name)
        route = MODELS[name][1](size)
        gmsh.model.addPhysicalGroup(3, [v for _, v in gmsh.model.getEntities(3)], 1)
        t0 = time.perf_counter()
        gmsh.model.mesh.generate(3)
        mesh_seconds = time.perf_counter() - t0
        hexes = sum(len(t) for et, t in zip(*gmsh.model.mesh.getElements(3)[:2]) if et == 5)
        others = sum(len(t) for et, t in zip(*gmsh.model.mesh.getElements(3)[:2]) if et != 5)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 1)  # Gmsh's fastest output
        gmsh.write(out)
    finally:
        gmsh.finalize()
    return {"hexes": hexes, "other_elements": others, "mesh_seconds": mesh_seconds,
            "total_seconds": time.perf_counter() - t_start, "route": route}


def main(argv):
    if len(argv) == 3 and argv[0] == "step":
        print(json.dumps({"volume": write_step(argv[1], argv[2])}))
        return 0
    if len(argv) == 4 and argv[0] == "gmsh":
        print(json.dumps(mesh_gmsh(argv[1], float(argv[2]), argv[3])))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
