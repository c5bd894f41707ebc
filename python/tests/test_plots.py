# Result.plot_blocks and plot_history (matplotlib, Agg): the displaced corners follow eq. 1
# (checked on a rigid motion, whose corners move by a closed form), and each plot draws what it
# says: every block, every carried increment.
import math

import matplotlib
import numpy as np

import bimrock
from bimrock import _moved

from conftest import example

matplotlib.use("Agg")


def test_a_rigid_motion_moves_the_corners_by_its_closed_form():
    square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]])
    centroid = np.array([1.0, 0.5])
    theta = 1e-3
    moved = _moved(square, centroid, np.array([0.1, -0.2, theta, 0.0, 0.0, 0.0]))
    r = square - centroid
    expected = square + [0.1, -0.2] + theta * np.column_stack((-r[:, 1], r[:, 0]))
    assert np.allclose(moved, expected, rtol=0, atol=1e-15)
    # A uniform strain eps_x stretches x about the centroid.
    stretched = _moved(square, centroid, np.array([0, 0, 0, 0.01, 0, 0]))
    assert np.allclose(stretched[:, 0] - square[:, 0], 0.01 * r[:, 0], rtol=0, atol=1e-15)


def test_the_plots_draw_every_block_and_every_increment():
    result = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    ax = result.plot_blocks()
    drawn = ax.collections[1].get_paths()
    assert len(drawn) == len(result.blocks["polygons"])
    mechanism = result.plot_blocks(mechanism=True)
    assert mechanism.get_title().startswith("mechanism")
    history = result.plot_history()
    (line,) = history.get_lines()
    assert len(line.get_xdata()) == len(result.history["stage_factor"])
    assert math.isclose(line.get_ydata()[-1], result.history["stage_factor"][-1])
