# What Python returns is what `bimrock run` writes for the same case (its CSV and JSON files,
# read back here), and Result.write() writes the command's folder.
import csv
import json

import numpy as np

import bimrock
from conftest import example, run_command


def table(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([float(r[key]) for r in rows]) for key in rows[0]
            if key not in ("material", "joint_material", "stage_name", "state")}


def columns(t, *names):
    return np.column_stack([t[n] for n in names])


def test_nonlinear_results_equal_the_commands_files(pull_out_command):
    result = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    blocks = table(pull_out_command / "blocks.csv")
    b = result.blocks
    assert np.array_equal(b["centroids"], columns(blocks, "x0_m", "y0_m"))
    assert np.array_equal(b["unknowns"], columns(blocks, "u0_m", "v0_m", "theta_rad", "eps_x",
                                                 "eps_y", "gamma_xy"))
    assert np.array_equal(b["stresses"], columns(blocks, "sigma_x_Pa", "sigma_y_Pa", "tau_xy_Pa"))

    faces = table(pull_out_command / "interfaces.csv")
    f = result.interfaces
    assert np.array_equal(f["blocks"], columns(faces, "block_i", "block_j"))
    assert np.array_equal(f["ends"], columns(faces, "x_a_m", "y_a_m", "x_b_m", "y_b_m"))
    for k in (1, 2):
        assert np.array_equal(f["deltas"][:, k - 1], columns(faces, f"delta_n{k}_m", f"delta_s{k}_m"))
        assert np.array_equal(f["stresses"][:, k - 1],
                              columns(faces, f"sigma_n{k}_Pa", f"tau{k}_Pa"))

    history = table(pull_out_command / "history.csv")
    h = result.history
    assert np.array_equal(h["stage_factor"], history["stage_factor"])
    assert np.array_equal(h["yielding_points"], history["yielding_points"])
    assert np.array_equal(h["monitors"]["A"], columns(history, "ux_A_m", "uy_A_m"))

    summary = json.loads((pull_out_command / "summary.json").read_text())
    c = result.collapse
    assert c["stage_name"] == "pull"
    assert c["carried_factor"] == summary["collapse"]["carried_factor"]
    assert c["failed_factor"] == summary["collapse"]["failed_factor"]
    # The closed form of examples/pull_out: P = 2C = 40 kN of the stage's 60 kN.
    assert c["carried_factor"] <= 2 / 3 <= c["failed_factor"] <= 2 / 3 * 1.001
    mechanism = table(pull_out_command / "mechanism.csv")
    assert np.array_equal(c["mechanism"]["block_velocities"],
                          columns(mechanism, "u", "v", "theta_per_m", "eps_x_per_m",
                                  "eps_y_per_m", "gamma_xy_per_m"))
    assert np.array_equal(result.mean_strain, [summary["mean_strain"][k]
                                               for k in ("eps_x", "eps_y", "gamma_xy")])


def without_timings(summary_file):
    summary = json.loads(summary_file.read_text())
    summary.pop("timings_s")
    return summary


def test_write_writes_the_commands_folder(pull_out_command, tmp_path):
    result = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    out = tmp_path / "out"
    result.write(out)
    ours = sorted(p.relative_to(out) for p in out.rglob("*"))
    theirs = sorted(p.relative_to(pull_out_command) for p in pull_out_command.rglob("*"))
    assert ours == theirs
    timed = {"summary.json", "history.csv"}  # wall-clock times, compared without them below
    for name in ours:
        if (out / name).is_dir() or name.name in timed:
            continue
        assert (out / name).read_bytes() == (pull_out_command / name).read_bytes(), name
    assert without_timings(out / "summary.json") == without_timings(pull_out_command / "summary.json")
    assert without_seconds(out / "history.csv") == without_seconds(pull_out_command / "history.csv")


def without_seconds(history_file):
    lines = history_file.read_text().splitlines()
    assert lines[0].endswith(",seconds")
    return [line.rsplit(",", 1)[0] for line in lines]


def test_an_elastic_case_equals_the_command_and_writes_its_folder(tmp_path):
    case_file = example("jointed_rock_mass", "case1_vertical.yaml")
    command = run_command(case_file, tmp_path / "cmd")
    result = bimrock.Case.from_file(case_file).run()
    assert result.analysis == "elastic" and result.collapse is None and result.history["stage"].size == 0
    blocks = table(command / "blocks.csv")
    assert np.array_equal(result.blocks["unknowns"],
                          columns(blocks, "u0_m", "v0_m", "theta_rad", "eps_x", "eps_y", "gamma_xy"))
    summary = json.loads((command / "summary.json").read_text())
    assert np.array_equal(result.mean_strain, [summary["mean_strain"][k]
                                               for k in ("eps_x", "eps_y", "gamma_xy")])
    out = tmp_path / "py"
    result.write(out)
    assert (out / "blocks.csv").read_bytes() == (command / "blocks.csv").read_bytes()
    assert without_timings(out / "summary.json") == without_timings(command / "summary.json")
