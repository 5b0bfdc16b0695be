"""Cooperage: all-hexahedral meshing of CAD solids by sweeping.

    import cooperage
    mesh = cooperage.mesh("part.step", size=2)
    mesh.write("part.exo"); mesh.report("part.html")

See docs/python.md for the whole interface.
"""

from ._core import Error, InputError, Mesh, MeshingError, __version__, mesh, plan, run

__all__ = ["Error", "InputError", "Mesh", "MeshingError", "mesh", "plan", "run", "__version__"]


def _to_meshio(self):
    """The mesh as a meshio.Mesh (points, cells, and cell_sets named "volume 2",
    "surface 12", ... with one index array per cell block). Needs meshio."""
    import meshio  # optional dependency, imported on use
    import numpy

    cells = self.cells
    order = list(cells)
    cell_sets = {}
    for name, by_type in self.cell_sets.items():
        cell_sets[name] = [
            by_type.get(kind, numpy.zeros(0, dtype=numpy.int64)) for kind in order
        ]
    return meshio.Mesh(
        numpy.array(self.points),
        [(kind, numpy.array(cells[kind])) for kind in order],
        cell_sets=cell_sets,
    )


Mesh.to_meshio = _to_meshio
