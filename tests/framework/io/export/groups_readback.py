#!/usr/bin/python3
"""Reads the named element blocks, side sets and node sets of an exported
mesh back with independent readers, for the exporter tests.

usage: groups_readback.py FILE

Prints one fact per line:
  .exo  EXO_BLOCK id name elem_type count | EXO_SIDESET id name count |
        EXO_NODESET id name count   (netCDF4, the Exodus variables read directly)
        MESHIO_CELLS type count     (meshio reads the file, WEDGE blocks included)
  .msh  MESHIO_PHYS dim tag name    (meshio field_data)
        GMSH_PHYS dim tag name elements  (gmsh: elements of the group's entities)
  .inp  INP_ELSET name count | INP_NSET name count (meshio) |
        INP_SURFACE name faces      (*SURFACE lines, parsed here)
Exit status 3 when a reader is missing (the test skips), 1 on an error.
"""
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # pragma: no cover
    print("MISSING", e)
    sys.exit(3)


def chars(row):
    """An Exodus name: a row of chars (bytes or, auto-converted, a str), NUL-padded."""
    if isinstance(row, (str, np.str_)):
        text = str(row)
    else:
        text = b"".join(bytes(c) for c in np.asarray(row).ravel()).decode()
    return text.split("\0")[0].strip()


def exodus(path):
    try:
        import netCDF4
    except ImportError as e:  # pragma: no cover
        print("MISSING", e)
        sys.exit(3)
    with netCDF4.Dataset(path) as nc:
        v = nc.variables
        for kind, prop, names, count_of in (
            ("EXO_BLOCK", "eb_prop1", "eb_names", lambda i: len(nc.dimensions["num_el_in_blk%d" % i])),
            ("EXO_SIDESET", "ss_prop1", "ss_names", lambda i: len(nc.dimensions["num_side_ss%d" % i])),
            ("EXO_NODESET", "ns_prop1", "ns_names", lambda i: len(nc.dimensions["num_nod_ns%d" % i])),
        ):
            if prop not in v:
                continue
            ids = v[prop][:]
            rows = v[names][:] if names in v else [[]] * len(ids)
            for i, (bid, row) in enumerate(zip(ids, rows), start=1):
                extra = []
                if kind == "EXO_BLOCK":
                    extra = [v["connect%d" % i].elem_type]
                print(kind, int(bid), chars(row), *extra, count_of(i))
    m = meshio.read(path)
    for block in m.cells:
        print("MESHIO_CELLS", block.type, len(block.data))


def gmsh_groups(path):
    m = meshio.read(path)
    for name, (tag, dim) in sorted(m.field_data.items()):
        print("MESHIO_PHYS", int(dim), int(tag), name)
    import gmsh
    gmsh.initialize(["groups_readback", "-v", "0"])
    gmsh.open(path)
    for dim, tag in gmsh.model.getPhysicalGroups():
        n = 0
        for e in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            _, etags, _ = gmsh.model.mesh.getElements(dim, e)
            n += sum(len(t) for t in etags)
        print("GMSH_PHYS", dim, tag, gmsh.model.getPhysicalName(dim, tag), n)
    gmsh.finalize()


def abaqus(path):
    m = meshio.read(path)
    for name, parts in sorted(m.cell_sets.items()):
        print("INP_ELSET", name, sum(len(p) for p in parts))
    for name, nodes in sorted(m.point_sets.items()):
        print("INP_NSET", name, len(nodes))
    # *SURFACE, TYPE=ELEMENT, NAME=n then "elset, Sk" lines: count the faces.
    elsets = {name: sum(len(p) for p in parts) for name, parts in m.cell_sets.items()}
    surface, faces = None, {}
    for raw in open(path):
        line = raw.strip()
        if line.startswith("*"):
            surface = None
            words = [w.strip() for w in line[1:].split(",")]
            if words[0].upper() == "SURFACE":
                params = dict(w.split("=", 1) for w in words[1:] if "=" in w)
                params = {k.strip().upper(): val.strip() for k, val in params.items()}
                surface = params["NAME"]
                faces[surface] = 0
        elif surface and line:
            faces[surface] += elsets[line.split(",")[0].strip()]
    for name, n in sorted(faces.items()):
        print("INP_SURFACE", name, n)


def main():
    path = sys.argv[1]
    if path.endswith(".exo"):
        exodus(path)
    elif path.endswith(".msh"):
        gmsh_groups(path)
    elif path.endswith(".inp"):
        abaqus(path)
    else:
        sys.exit("unknown extension: " + path)


if __name__ == "__main__":
    main()
