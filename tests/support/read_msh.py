"""Reads a gmsh .msh file with meshio (python3-meshio) and prints, as JSON, what the tests compare
bimrock's gmsh reader and model against, counted independently from the file's connectivity:
the cells of each type, their total area (shoelace formula), the edges shared by two cells
(internal edges) and used by one (boundary edges), and the line elements of each physical curve."""
import json
import sys
from collections import Counter

import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
xy = np.asarray(mesh.points)[:, :2]
out = {"cells": {}, "area": 0.0, "internal_edges": 0, "boundary_edges": 0, "lines_by_group": {}}
edges = Counter()
for block in mesh.cells:
    out["cells"][block.type] = out["cells"].get(block.type, 0) + int(len(block.data))
    if block.type not in ("triangle", "quad"):
        continue
    for cell in block.data:
        p = xy[cell]
        q = np.roll(p, -1, axis=0)
        out["area"] += 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))
        for a, b in zip(cell, np.roll(cell, -1)):
            edges[(min(a, b), max(a, b))] += 1
out["internal_edges"] = sum(1 for n in edges.values() if n == 2)
out["boundary_edges"] = sum(1 for n in edges.values() if n == 1)
# cell_sets: physical name -> per cell block, the indices of its cells in that block.
for name, per_block in mesh.cell_sets.items():
    if name.startswith("gmsh:"):
        continue
    n = sum(len(ids) for block, ids in zip(mesh.cells, per_block) if block.type == "line")
    if n:
        out["lines_by_group"][name] = n
json.dump(out, sys.stdout)
