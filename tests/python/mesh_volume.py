"""Independent geometry for the tests: the volume of hexahedra and wedges
from their corners (split into tetrahedra), in numpy only."""

import numpy

# Each hex (VTK/Exodus order) as six tetrahedra around the 0-6 diagonal:
# exact for any hex whose faces are planar, close for slightly warped ones.
HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
# A VTK wedge (0,1,2 one triangle, 3,4,5 the other) as three tetrahedra.
WEDGE_TETS = [(0, 1, 2, 3), (1, 2, 3, 4), (2, 3, 4, 5)]


def total_volume(points, cells, tets):
    """Sum of |volume| of the tetrahedra of every cell."""
    points = numpy.asarray(points, dtype=float)
    cells = numpy.asarray(cells)
    total = 0.0
    for a, b, c, d in tets:
        pa, pb, pc, pd = (points[cells[:, k]] for k in (a, b, c, d))
        total += numpy.abs(numpy.einsum("ij,ij->i", pb - pa, numpy.cross(pc - pa, pd - pa))).sum() / 6
    return total
