#!/usr/bin/python3
"""Independent read-back of an exported mesh for the exporter tests.

usage: readback.py FILE [--gmsh]

Reads FILE with meshio (and, with --gmsh, also with the gmsh module) and
prints one fact per line for the C++ test to compare with its own values:
  NODES n | SUM sx sy sz | SUMSQ s | CELLS type n | VOLMIN v | VOLSUM v
  SJMIN/SJMAX (vtu scaled_jacobian) | BLOCK type id n (vtu block_id)
  SURF tag n0 n1 n2 [n3]  (surface elements with their entity tag, 0-based)
  FACE name n.. (inp *SURFACE faces, sorted 0-based nodes)
  GMSH_* (gmsh module)
Exit status 3 when meshio is missing (the test skips), 1 on a failed check.
"""
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # pragma: no cover
    print("MISSING", e)
    sys.exit(3)


def tet(p, a, b, c, d):
    return np.einsum("ij,ij->i", p[:, b] - p[:, a],
                     np.cross(p[:, c] - p[:, a], p[:, d] - p[:, a])) / 6.0


# Standard decompositions (Exodus / gmsh / meshio node order):
# hex into 6 tets around the diagonal 0-6, wedge into 3 tets.
HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
WEDGE_TETS = [(0, 1, 2, 3), (1, 2, 3, 4), (2, 5, 3, 4)]


def volumes(points, cells, tets):
    p = points[cells]
    return sum(tet(p, *t) for t in tets)


def self_check():
    cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                     [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    wedge = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]], float)
    for t in HEX_TETS:
        assert tet(cube[None], *t)[0] > 0, t
    for t in WEDGE_TETS:
        assert tet(wedge[None], *t)[0] > 0, t
    assert abs(volumes(cube, np.array([range(8)]), HEX_TETS)[0] - 1) < 1e-14
    assert abs(volumes(wedge, np.array([range(6)]), WEDGE_TETS)[0] - 0.5) < 1e-14


# Abaqus faces (1-based in the manual), for the *SURFACE check.
ABAQUS_FACES = {
    8: {1: (1, 2, 3, 4), 2: (5, 8, 7, 6), 3: (1, 5, 6, 2), 4: (2, 6, 7, 3),
        5: (3, 7, 8, 4), 6: (4, 8, 5, 1)},
    6: {1: (1, 2, 3), 2: (4, 6, 5), 3: (1, 4, 5, 2), 4: (2, 5, 6, 3), 5: (3, 6, 4, 1)},
}


def inp_faces(path):
    """Parses *ELEMENT, *ELSET and *SURFACE of an .inp by hand."""
    elems, elsets, surfaces = {}, {}, {}
    mode, name = None, None
    for raw in open(path):
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            kw = [s.strip() for s in line[1:].split(",")]
            params = dict((s.split("=") + [""])[:2] for s in kw[1:])
            params = {k.strip().upper(): v.strip() for k, v in params.items()}
            mode = kw[0].upper()
            if mode == "ELSET":
                name = params["ELSET"]
                elsets[name] = []
            elif mode == "SURFACE":
                name = params["NAME"]
                surfaces[name] = []
            continue
        items = [s.strip() for s in line.split(",") if s.strip()]
        if mode == "ELEMENT":
            elems[int(items[0])] = [int(v) for v in items[1:]]
        elif mode == "ELSET" and items[0].isdigit():
            elsets[name] += [int(v) for v in items]
        elif mode == "SURFACE":
            surfaces[name].append((items[0], int(items[1].upper().lstrip("S"))))
    for sname, parts in sorted(surfaces.items()):
        for setname, face in parts:
            for e in elsets[setname]:
                nodes = elems[e]
                local = ABAQUS_FACES[len(nodes)][face]
                print("FACE", sname, *sorted(nodes[k - 1] - 1 for k in local))


def main():
    self_check()
    path = sys.argv[1]
    m = meshio.read(path)
    pts = np.asarray(m.points, float)
    print("NODES", len(pts))
    print("SUM", *("%.12g" % s for s in pts.sum(axis=0)))
    print("SUMSQ", "%.12g" % (pts ** 2).sum())
    counts, vols = {}, []
    for i, block in enumerate(m.cells):
        counts[block.type] = counts.get(block.type, 0) + len(block.data)
        if block.type == "hexahedron":
            vols.append(volumes(pts, block.data, HEX_TETS))
        elif block.type == "wedge":
            vols.append(volumes(pts, block.data, WEDGE_TETS))
        tags = None
        if "gmsh:geometrical" in m.cell_data:
            tags = m.cell_data["gmsh:geometrical"][i]
        elif "block_id" in m.cell_data:
            tags = m.cell_data["block_id"][i]
        if tags is not None:
            for t in sorted(set(int(v) for v in tags)):
                print("BLOCK", block.type, t, int((tags == t).sum()))
            if block.type in ("quad", "triangle") and not path.endswith(".msh"):
                # (meshio renumbers .msh nodes; the gmsh module prints those)
                for t, c in zip(tags, block.data):
                    print("SURF", int(t), *c)
    for k in sorted(counts):
        print("CELLS", k, counts[k])
    if vols:
        v = np.concatenate(vols)
        print("VOLMIN", "%.12g" % v.min())
        print("VOLSUM", "%.12g" % v.sum())
    if "scaled_jacobian" in m.cell_data:
        sj = np.concatenate(m.cell_data["scaled_jacobian"])
        print("SJMIN", "%.12g" % sj.min())
        print("SJMAX", "%.12g" % sj.max())
    if path.endswith(".inp"):
        for name in sorted(m.point_sets):
            print("NSET", name, len(m.point_sets[name]))
        inp_faces(path)
    if "--gmsh" in sys.argv:
        import gmsh
        gmsh.initialize(["readback", "-v", "0"])
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        print("GMSH_NODES", len(tags), "%.12g" % np.asarray(coords).sum())
        for dim, tag in gmsh.model.getPhysicalGroups():
            print("GMSH_PHYS", dim, tag, gmsh.model.getPhysicalName(dim, tag),
                  *gmsh.model.getEntitiesForPhysicalGroup(dim, tag))
        for dim in (2, 3):
            types, etags, _ = gmsh.model.mesh.getElements(dim)
            for t, e in zip(types, etags):
                print("GMSH_ELEMS", dim, int(t), len(e))
        # gmsh's own Jacobian determinants at the element centres (> 0 for
        # a correctly oriented hex / prism in gmsh's node order).
        centre = {5: [0.0, 0.0, 0.0], 6: [1 / 3.0, 1 / 3.0, 0.0]}
        for t, uvw in centre.items():
            if t in gmsh.model.mesh.getElementTypes(3):
                _, det, _ = gmsh.model.mesh.getJacobians(t, uvw)
                print("GMSH_MINDET", t, "%.12g" % min(det))
        per = {2: 3, 3: 4}  # gmsh element type -> nodes (triangle, quad)
        for _, tag in gmsh.model.getEntities(2):
            types, _, nodes = gmsh.model.mesh.getElements(2, tag)
            for t, n in zip(types, nodes):
                k = per[int(t)]
                for i in range(0, len(n), k):
                    print("SURF", tag, *(int(v) - 1 for v in n[i:i + k]))
        gmsh.finalize()


if __name__ == "__main__":
    main()
