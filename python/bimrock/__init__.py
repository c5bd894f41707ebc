"""bimrock for Python: cases of the block-interfaces model (Zhang & Lu), their analyses and
results as numpy arrays. SI units throughout (m, N, Pa, Pa/m, N/m^3); stresses tension positive.
The API is described in docs/python.md; the case schema in docs/case-file.md.

    import bimrock
    case = bimrock.Case.from_file("examples/pull_out/case.yaml")
    result = case.run()
    print(result.collapse["carried_factor"], result.collapse["failed_factor"])
"""

import copy
import json
import os

import numpy as np

from . import _core
from ._core import InputError, ModelError, install_factor_memory

__version__ = _core.__version__
__all__ = ["Case", "Result", "InputError", "ModelError", "install_factor_memory"]

# The sections of a case that leave its blocks and interfaces as they are: update() may replace
# them and the geometry is kept. Blocks, domain, mesh, joints and supports make the geometry.
UPDATABLE_SECTIONS = frozenset({"title", "analysis", "materials", "joint_materials", "loads",
                                "stages", "initial_stress", "bolts", "monitors",
                                "factor_of_safety", "output", "limits"})


def _plain(value):
    """numpy scalars and arrays as Python numbers and lists, for json."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not a case value (give numbers, strings, "
                    "lists and dicts)")


def _to_text(document):
    # JSON is YAML: strings come out quoted (text to the reader, never a number), numbers plain
    # with every digit (json writes the shortest text that reads back the same double).
    if not isinstance(document, dict):
        raise TypeError("a case is a dict of sections, as a case file is a map")
    return json.dumps(document, default=_plain, allow_nan=True)


def _moved(polygon, centroid, d):
    """The corners of a block moved by its unknowns d = [u0, v0, theta, eps_x, eps_y, gamma_xy]
    (eq. 1: u = Q(x, y) d about the centroid)."""
    x = polygon[:, 0] - centroid[0]
    y = polygon[:, 1] - centroid[1]
    u = d[0] - y * d[2] + x * d[3] + 0.5 * y * d[5]
    v = d[1] + x * d[2] + y * d[4] + 0.5 * x * d[5]
    return polygon + np.column_stack((u, v))


class Case:
    """A case read and its model built (blocks cut, interfaces found, materials and loads
    resolved). Make one with from_file() or from_dict(); run() analyses it, update() changes
    its materials, loads or stages without building the geometry again."""

    def __init__(self, core, document, name, from_file=None):
        self._core = core
        self._document = document  # None until asked for, for a case read from a file
        self._name = name
        self._file = from_file

    @classmethod
    def from_file(cls, path):
        """Reads a case file (YAML, docs/case-file.md) and builds its model. Bad input raises
        InputError naming the file, line and item."""
        path = os.fspath(path)
        return cls(_core.CaseModel.file(path), None, path, from_file=path)

    @classmethod
    def from_dict(cls, document, name="<dict>", folder=None):
        """Builds the case given as Python data in the schema of a case file (a dict of sections,
        lists, numbers and strings). Bad input raises InputError naming `name` and the item path
        (e.g. "materials.rock.E"). A mesh file is found relative to `folder` (default: the
        working folder)."""
        document = copy.deepcopy(document)
        label = os.path.join(os.fspath(folder), name) if folder is not None else name
        core = _core.CaseModel.text(_to_text(document), label, False)
        return cls(core, document, label)

    @property
    def document(self):
        """The case as Python data (a copy): change it and give sections to update()."""
        if self._document is None:
            with open(self._file, encoding="utf-8") as f:
                self._document = _core.yaml_to_python(f.read())
        return copy.deepcopy(self._document)

    def update(self, **sections):
        """Replaces whole sections of the case (materials, joint_materials, loads, stages,
        monitors, analysis, factor_of_safety, output, limits, title) and makes the model anew on
        the same blocks and interfaces: only the analysis is paid for again. The materials keep
        their names and order. Returns self."""
        other = sorted(set(sections) - UPDATABLE_SECTIONS)
        if other:
            raise ValueError(f"update() cannot change {', '.join(other)}: they make the "
                             "geometry; build a new Case")
        document = self.document
        for key, value in sections.items():
            if value is None:
                document.pop(key, None)
            else:
                document[key] = copy.deepcopy(value)
        self._core = self._core.rebuild(_to_text(document), self._name)
        self._document = document
        return self

    def check(self):
        """The model's size (blocks, interfaces, support_interfaces, unknowns, stages), its kind
        of analysis and the estimated peak memory [bytes]; raises InputError where its results
        would exceed the case's limits, as `bimrock check` and `bimrock run` do."""
        return self._core.check()

    def run(self, progress=None):
        """Analyses the case: elastic without stages; else the stages and, with a
        factor_of_safety section, the factor of safety. progress(info), if given, is called after
        every carried increment with a dict (stage, stage_name, increment, increments,
        stage_factor, seconds), and after every F the factor of safety's search carried
        (stage_name 'factor of safety', stage_factor F). Ctrl-C (or an exception raised by
        progress) stops the analysis at the next increment or trial and is raised here; the
        case can be run again."""
        return Result(self._core.run(progress))

    @property
    def title(self):
        return self._core.title

    @property
    def block_materials(self):
        return self._core.block_materials

    @property
    def joint_materials(self):
        return self._core.joint_materials

    @property
    def monitors(self):
        return self._core.monitors

    @property
    def stages(self):
        return self._core.stages


class Result:
    """The results of one run, as numpy arrays (SI units, 0-based indices in the order of the
    case). Each property computes its arrays when asked: keep what you use."""

    def __init__(self, core):
        self._core = core

    @property
    def analysis(self):
        """'elastic' or 'nonlinear'."""
        return self._core.analysis

    @property
    def blocks(self):
        """dict of arrays, one row per block: polygons (a list of (k, 2) corners, counter-
        clockwise) [m], centroids (n, 2) [m], areas (n,) [m^2], material
        (n,) index, unknowns (n, 6) [u0, v0, theta, eps_x, eps_y, gamma_xy] (eq. 1), strains
        (n, 3), stresses (n, 3) [sigma_x, sigma_y, tau_xy] [Pa], plastic_strains (n, 3)."""
        return self._core.blocks

    @property
    def interfaces(self):
        """dict of arrays, one row per interface (supports last): blocks (m, 2) [i, j] (j = -1:
        the ground), joint_material (m,) index (-1: a rigid support), ends (m, 4) [x_a, y_a, x_b,
        y_b] [m], normals (m, 2) from i into j, and at the two integration points: points
        (m, 2, 2) [m], deltas (m, 2, 2) [delta_n, delta_s] [m] (delta_n > 0 opens), stresses
        (m, 2, 2) [sigma_n, tau] [Pa] (sigma_n > 0 tension), plastic (m, 2, 2) [m]."""
        return self._core.interfaces

    @property
    def history(self):
        """Nonlinear: one entry per carried increment: stage, increment, stage_factor,
        yielding_points, open_points (arrays), and monitors: name -> (k, 2) displacements [m]."""
        return self._core.history

    @property
    def collapse(self):
        """None, or the stage that could not be carried: stage, stage_name, carried_factor and
        failed_factor (the bracket of the collapse load factor), unstable_at_first_load,
        undecided_inside (the bracket is wider than its tolerance), associated_bound (load
        control stopped undecided at carried_factor, and failed_factor is where associated flow
        is proven to fail, a bound for any flow rule), limit_point (the peak of the
        equilibrium path, followed under displacement control: carried_factor = failed_factor),
        limit_point_plateau_m and limit_point_elastic_m (how far the controlled block moved at
        that peak, and under the stage's whole load elastically), limit_point_fell (the load
        fell past the peak), and mechanism: yield_point,
        mode, multiplier (arrays), block_velocities (n, 6), block_speeds, block_states ('moves',
        'rotates', 'stands')."""
        return self._core.collapse

    @property
    def factor_of_safety(self):
        """None, or lower (the largest F carried), upper (the smallest F proven to fail, or
        None), largest_tried, undecided, trials (every F carried) and mechanism (as collapse's)."""
        return self._core.factor_of_safety

    @property
    def stopped(self):
        """None, or where a nonlinear analysis stopped without a proven collapse: stage,
        carried_factor, reason."""
        return self._core.stopped

    @property
    def mean_strain(self):
        """[eps_x, eps_y, gamma_xy] of the whole mass at the end of the run."""
        return self._core.mean_strain

    @property
    def monitors(self):
        """name -> [ux, uy] displacement at the end of the run [m]."""
        return self._core.monitors

    @property
    def timings(self):
        """phase -> wall-clock seconds."""
        return self._core.timings

    def plot_blocks(self, ax=None, magnification=None, mechanism=False):
        """Draws the blocks with matplotlib, coloured by material, displaced by their unknowns
        (eq. 1) magnified `magnification` times (None: the largest corner displacement shown as
        5% of the model's size), over the undisplaced outline in grey. With `mechanism`, the
        collapse's (or the factor of safety's) mechanism velocities instead. Returns the axes."""
        import matplotlib.pyplot as plt
        from matplotlib.collections import PolyCollection

        blocks = self.blocks
        d = blocks["unknowns"]
        if mechanism:
            source = self.collapse or self.factor_of_safety
            if source is None or "mechanism" not in source:
                raise ValueError("this run has no mechanism to draw")
            d = source["mechanism"]["block_velocities"]
        moved = [_moved(p, c, u) for p, c, u in zip(blocks["polygons"], blocks["centroids"], d)]
        corners = np.vstack(blocks["polygons"])
        size = float(np.hypot(*(corners.max(axis=0) - corners.min(axis=0))))
        largest = max((float(np.abs(m - p).max()) for m, p in zip(moved, blocks["polygons"])),
                      default=0.0)
        if magnification is None:
            magnification = 0.05 * size / largest if largest > 0.0 else 1.0
        shown = [p + magnification * (m - p) for m, p in zip(moved, blocks["polygons"])]
        if ax is None:
            _, ax = plt.subplots(figsize=(8, 6))
        ax.add_collection(PolyCollection(blocks["polygons"], facecolors="none",
                                         edgecolors="0.75", linewidths=0.5))
        colours = plt.get_cmap("Pastel1")(blocks["material"] % 9)
        ax.add_collection(PolyCollection(shown, facecolors=colours, edgecolors="0.3",
                                         linewidths=0.5))
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_title(f"{'mechanism' if mechanism else 'displacements'} x {magnification:.3g}")
        return ax

    def plot_history(self, monitor=None, ax=None):
        """Draws each carried increment's stage factor against a monitor's displacement (its
        magnitude [m]; the first monitor by default) with matplotlib. Returns the axes."""
        import matplotlib.pyplot as plt

        history = self.history
        if not history or not history["monitors"]:
            raise ValueError("a nonlinear run with a monitor has a history to plot")
        name = monitor if monitor is not None else next(iter(history["monitors"]))
        u = np.hypot(*np.asarray(history["monitors"][name]).T)
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 4))
        ax.plot(u, history["stage_factor"], "o-", markersize=3)
        ax.set_xlabel(f"displacement of monitor {name} [m]")
        ax.set_ylabel("stage factor")
        ax.grid(True, alpha=0.3)
        return ax

    def write(self, folder):
        """Writes the results folder `bimrock run` writes for this case (docs/results.md): all or
        nothing, replacing only a folder of earlier results."""
        self._core.write(os.fspath(folder))
