#!/usr/bin/python3
"""Gmsh side of the face comparison (run_faces.py): one benchmark face of
bench/face_models.cpp meshed with quads by Gmsh, on the same geometry and
with the same boundary node counts per curve as Cooperage's pave.

    /usr/bin/python3 gmsh_faces.py FACE.brep FACE.json OUT.msh

FACE.brep is the solid Cooperage built (written by cooperage_bench with
COOPERAGE_FACES_OUT set), imported into Gmsh's OCC kernel; FACE.json names the
face (area, centre) and its curves (intervals, length, centre). The face is
found by its centre and area, each curve by its centre and length; every
boundary curve gets setTransfiniteCurve(tag, intervals + 1) (uniform), all
other entities are removed, and the face is meshed with Gmsh's quad route:
Mesh.Algorithm=6 (Frontal-Delaunay), Mesh.RecombineAll=1,
Mesh.RecombinationAlgorithm=1 (Blossom). Interior sizes come from the
boundary spacing (Mesh.MeshSizeFactor does not change them in 4.8.4: tried).
Writes .msh 4.1 ASCII and prints one JSON object: quads, triangles, the
generate() seconds and the boundary node counts actually set.
Run with Debian's /usr/bin/python3 (python3-gmsh 4.8.4).
"""

import argparse
import json
import math
import sys
import time

import gmsh


def _dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def _closest(candidates, centre, size, scale):
    """The tag whose (centre, size) is nearest: distance / scale + relative size difference."""
    occ = gmsh.model.occ
    best, best_score = None, float("inf")
    for dim, tag in candidates:
        score = (_dist(occ.getCenterOfMass(dim, tag), centre) / scale
                 + abs(occ.getMass(dim, tag) - size) / size)
        if score < best_score:
            best, best_score = tag, score
    return best, best_score


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("brep")
    p.add_argument("face_json")
    p.add_argument("out")
    a = p.parse_args()
    with open(a.face_json) as f:
        face = json.load(f)

    t_start = time.perf_counter()
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    occ.importShapes(a.brep)
    occ.synchronize()
    scale = math.sqrt(face["area"])
    surface, score = _closest(gmsh.model.getEntities(2), face["centre"], face["area"], scale)
    if score > 0.05:
        sys.exit("gmsh_faces: no surface matches %s (best score %.3g)" % (face["name"], score))
    boundary = gmsh.model.getBoundary([(2, surface)], combined=False, oriented=False)
    curves = sorted({abs(t) for _, t in boundary})
    counts = {}
    for c in face["curves"]:
        tag, score = _closest([(1, t) for t in curves], c["centre"], c["length"], scale)
        if score > 0.05 or tag in counts:
            sys.exit("gmsh_faces: curve %d of %s has no match (score %.3g)"
                     % (c["id"], face["name"], score))
        counts[tag] = c["intervals"]
    if len(counts) != len(curves):
        sys.exit("gmsh_faces: %s: %d curves in Gmsh, %d in Cooperage"
                 % (face["name"], len(curves), len(counts)))

    # Keep only the face, its curves and their points.
    points = {abs(t) for _, t in gmsh.model.getBoundary([(1, c) for c in curves],
                                                        combined=False, oriented=False)}
    occ.remove(gmsh.model.getEntities(3))
    occ.remove([e for e in gmsh.model.getEntities(2) if e[1] != surface])
    occ.remove([e for e in gmsh.model.getEntities(1) if e[1] not in counts])
    occ.remove([e for e in gmsh.model.getEntities(0) if e[1] not in points])
    occ.synchronize()
    if gmsh.model.getEntities(2) != [(2, surface)]:
        sys.exit("gmsh_faces: could not isolate the face: %s" % gmsh.model.getEntities(2))

    for tag, n in counts.items():
        gmsh.model.mesh.setTransfiniteCurve(tag, n + 1)
    gmsh.option.setNumber("Mesh.Algorithm", 6)  # frontal-Delaunay (8 crashes in 4.8.4)
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)  # Blossom
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    t0 = time.perf_counter()
    gmsh.model.mesh.generate(2)
    mesh_seconds = time.perf_counter() - t0
    gmsh.model.addPhysicalGroup(2, [surface], surface)
    gmsh.write(a.out)

    quads = tris = 0
    types, tags, _ = gmsh.model.mesh.getElements(2, surface)
    for t, ts in zip(types, tags):
        name = gmsh.model.mesh.getElementProperties(t)[0].lower()
        if name.startswith("quad"):
            quads += len(ts)
        elif name.startswith("triangle"):
            tris += len(ts)
    gmsh.finalize()
    print(json.dumps({"face": face["name"], "quads": quads, "tris": tris,
                      "boundary_nodes": sum(counts.values()), "mesh_seconds": mesh_seconds,
                      "seconds": time.perf_counter() - t_start}))


if __name__ == "__main__":
    main()
