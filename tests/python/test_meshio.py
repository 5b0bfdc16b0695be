"""Round trips through meshio: Mesh.to_meshio() written and read back by
meshio, and Cooperage's own .vtu read by meshio, give the Mesh's arrays."""

import numpy
import pytest

import cooperage

meshio = pytest.importorskip("meshio")

MIXED = """\
<geometry>
  <brick name="a" origin="0 0 0" size="1 1 1"/>
  <brick name="b" origin="2 0 0" size="1 1 1"/>
</geometry>
<mesh size="0.25"><volume id="2" elements="wedge"/></mesh>
"""


def test_to_meshio_round_trip(journal, tmp_path):
    mesh = cooperage.run(journal(MIXED))
    assert set(mesh.cells) == {"hexahedron", "wedge", "quad", "triangle"}
    m = mesh.to_meshio()
    assert isinstance(m, meshio.Mesh)
    # Cell sets: one index array per cell block, as meshio expects.
    assert set(m.cell_sets) == set(mesh.cell_sets)
    kinds = [block.type for block in m.cells]
    for name, blocks in m.cell_sets.items():
        assert len(blocks) == len(kinds)
        for kind, indices in zip(kinds, blocks):
            expected = mesh.cell_sets[name].get(kind, numpy.zeros(0))
            assert numpy.array_equal(indices, expected), (name, kind)
    path = tmp_path / "via_meshio.vtu"
    m.write(path)  # (meshio turns the cell sets into cell data here)
    back = meshio.read(path)
    assert numpy.array_equal(back.points, mesh.points)
    for kind, cells in mesh.cells.items():
        assert numpy.array_equal(back.cells_dict[kind], cells), kind


def test_cooperage_vtu_read_by_meshio_matches_the_arrays(journal, tmp_path):
    mesh = cooperage.run(journal(MIXED))
    path = tmp_path / "own.vtu"
    mesh.write(path)
    back = meshio.read(path)
    assert numpy.allclose(back.points, mesh.points, rtol=0, atol=1e-12)
    # The .vtu holds the volume elements; meshio reads them in its order, as Mesh.cells.
    assert numpy.array_equal(back.cells_dict["hexahedron"], mesh.cells["hexahedron"])
    assert numpy.array_equal(back.cells_dict["wedge"], mesh.cells["wedge"])


def test_wedges_follow_meshio_convention(journal):
    """meshio's (Gmsh's) wedge: the normal of triangle (0,1,2) by the right-hand
    rule points into the wedge, towards (3,4,5); hexes: (0,1,2,3) likewise."""
    mesh = cooperage.run(journal(MIXED))
    p = mesh.points
    for kind, top in (("wedge", 3), ("hexahedron", 4)):
        c = mesh.cells[kind]
        normal = numpy.cross(p[c[:, 1]] - p[c[:, 0]], p[c[:, 2]] - p[c[:, 0]])
        assert (numpy.einsum("ij,ij->i", normal, p[c[:, top]] - p[c[:, 0]]) > 0).all(), kind
