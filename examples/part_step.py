"""Writes examples/part.step, the CAD part of the README's `cooperage mesh`
and Python examples, with Gmsh's OpenCASCADE kernel (python3-gmsh):
a 40 x 24 x 6 plate with a through hole, and a round boss (radius 6, height
10) standing on it as a second solid. Cooperage imprints the boss's footprint
on the plate, so the two volumes share their nodes there; both are swept by
cooper. Units: millimetres.

    /usr/bin/python3 examples/part_step.py
"""

import os

import gmsh

here = os.path.dirname(os.path.abspath(__file__))
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("part")
occ = gmsh.model.occ
plate = occ.addBox(0, 0, 0, 40, 24, 6)
occ.addCylinder(14, 12, 6, 0, 0, 10, 6)  # the boss
hole = occ.addCylinder(31, 12, -1, 0, 0, 8, 3.5)
occ.cut([(3, plate)], [(3, hole)])
occ.synchronize()
gmsh.write(os.path.join(here, "part.step"))
gmsh.finalize()
