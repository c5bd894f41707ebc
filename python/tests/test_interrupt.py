# Ctrl-C during run() stops the analysis at the next carried increment and raises
# KeyboardInterrupt; the process, and the case, can run again and give the same results.
import os
import signal
import threading

import numpy as np
import pytest

import bimrock
from conftest import example
from test_case_input import pull_out_dict


def test_ctrl_c_from_outside_stops_the_analysis_at_the_next_increment():
    # Friction on the bed joints: a run of some seconds, most of it in bisections near the limit.
    document = pull_out_dict()
    document["joint_materials"]["horizontal"]["friction"] = 20.0
    document["stages"][1]["increments"] = 12
    case = bimrock.Case.from_dict(document)
    seen = []
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # A builtin as the callback runs no Python code: only the analysis's own check of the
        # signal, after each increment, can stop it.
        case.run(progress=seen.append)
    timer.join()
    whole = case.run()
    assert 0 < len(seen) < whole.history["stage"].size
    assert whole.collapse is not None


def test_ctrl_c_stops_the_analysis_and_the_case_runs_again():
    case = bimrock.Case.from_file(example("pull_out", "case.yaml"))
    seen = []

    def progress(info):
        seen.append(info)
        if len(seen) == 3:
            os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C: Python's handler notes it

    with pytest.raises(KeyboardInterrupt):
        case.run(progress=progress)
    assert len(seen) == 3  # stopped at once, not at the end of the stages
    assert [i["stage_name"] for i in seen] == ["gravity", "pull", "pull"]

    counted = []
    again = case.run(progress=lambda info: counted.append(info["increment"]))
    fresh = bimrock.Case.from_file(example("pull_out", "case.yaml")).run()
    assert len(counted) == again.history["stage"].size > 3
    assert np.array_equal(again.blocks["unknowns"], fresh.blocks["unknowns"])
    assert again.collapse["failed_factor"] == fresh.collapse["failed_factor"]


def test_an_exception_of_the_progress_callback_ends_the_run():
    case = bimrock.Case.from_file(example("pull_out", "case.yaml"))

    class Enough(Exception):
        pass

    def progress(info):
        if info["stage_name"] == "pull" and info["stage_factor"] > 0.2:
            raise Enough(info["stage_factor"])

    with pytest.raises(Enough):
        case.run(progress=progress)
    assert case.run().collapse is not None


def test_the_factor_of_safety_search_reports_its_trials_and_stops_when_asked():
    case = bimrock.Case.from_file(example("slope_stability", "dry.yaml"))
    whole = case.run()
    trials = []
    case.run(progress=lambda info: trials.append(info))
    searched = [i["stage_factor"] for i in trials if i["stage_name"] == "factor of safety"]
    assert searched == whole.factor_of_safety["trials"][1:].tolist()  # F = 1 is the start

    def progress(info):
        if info["stage_name"] == "factor of safety" and info["increment"] == 3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        case.run(progress=progress)
    assert case.run().factor_of_safety["lower"] == whole.factor_of_safety["lower"]
