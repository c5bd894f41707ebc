# bimrock beside scipy.sparse.linalg in one process: each one's solutions are the same as
# without the other (the library sets nothing of the process, e.g. SuiteSparse's allocator).
import json

import numpy as np
import pytest

import bimrock
from conftest import example

sparse = pytest.importorskip("scipy.sparse")
linalg = pytest.importorskip("scipy.sparse.linalg")


def scipy_solves():
    n = 2000
    rng = np.random.default_rng(7)
    a = sparse.random(n, n, density=2e-3, random_state=3, format="csr") + sparse.identity(n) * 4
    a = (a + a.T).tocsc()
    b = rng.standard_normal(n)
    x_lu = linalg.splu(a).solve(b)
    x_cg, info = linalg.cg(a, b, tol=1e-12, atol=0.0)
    assert info == 0
    assert np.linalg.norm(a @ x_lu - b) < 1e-10 * np.linalg.norm(b)
    return x_lu, x_cg


def test_each_solves_as_it_does_alone(pull_out_command):
    before = scipy_solves()
    first = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    after = scipy_solves()
    for x, y in zip(before, after):
        assert np.array_equal(x, y)
    second = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    assert np.array_equal(first.blocks["unknowns"], second.blocks["unknowns"])
    assert first.collapse["failed_factor"] == second.collapse["failed_factor"]
    # ... and as the command does in a process of its own, without scipy.
    summary = json.loads((pull_out_command / "summary.json").read_text())
    assert first.collapse["failed_factor"] == summary["collapse"]["failed_factor"]
    assert first.monitors["A"].tolist() == [summary["monitors"][0]["ux_m"],
                                            summary["monitors"][0]["uy_m"]]
