"""Reads a .vtu with meshio (python3-meshio) and prints what the tests check, as JSON:
the number of points, the cells of each type, and every cell and point array as flat lists in
the file's cell order. Used by tests to read back our VTK output with an independent reader."""
import json
import sys

import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
out = {"points": int(len(mesh.points)), "cells": {}, "cell_data": {}, "point_data": {}}
for block in mesh.cells:
    out["cells"][block.type] = out["cells"].get(block.type, 0) + int(len(block.data))
for name, blocks in mesh.cell_data.items():
    out["cell_data"][name] = np.concatenate([np.asarray(b).reshape(len(b), -1) for b in blocks]).tolist()
for name, values in mesh.point_data.items():
    out["point_data"][name] = np.asarray(values).reshape(len(values), -1).tolist()
json.dump(out, sys.stdout)
