# A case given as Python data is the case file's: the same results to the bit, and bad input
# raises InputError naming the item as the file reader does.
import numpy as np
import pytest

import bimrock
from conftest import example

# examples/pull_out/case.yaml written out as Python data (make_case.py's bricks).
W, H = 2.0, 0.5


def pull_out_bricks():
    for j in range(4):
        xs = [0.0, 1.0, 3.0, 5.0, 6.0] if j % 2 else [0.0, 2.0, 4.0, 6.0]
        for x0, x1 in zip(xs[:-1], xs[1:]):
            yield {"material": "rock",
                   "vertices": [[x0, j * H], [x1, j * H], [x1, (j + 1) * H], [x0, (j + 1) * H]]}


def pull_out_dict():
    return {
        "schema": 1,
        "title": "Example 2 of Zhang & Lu: pull-out at A, increments of 2 kN",
        "analysis": {"plane": "strain", "thickness": 1.0},
        "materials": {"rock": {"E": 89.0e9, "nu": 0.26, "unit_weight": 16.0e3}},
        "joint_materials": {
            "vertical": {"kn": 395.9e9, "ks": 438.8e9, "cohesion": 20.0e3, "friction": 0.0},
            "horizontal": {"kn": 531.9e9, "ks": 438.8e9, "cohesion": 20.0e3, "friction": 0.0},
            "base": {"kn": 531.9e9, "ks": 438.8e9},
        },
        "joints": {"default": "vertical", "rules": [{"material": "horizontal", "orientation": 0}]},
        "supports": [{"line": [[0, 0], [6, 0]], "type": "fixed", "joint": "base"}],
        "monitors": [{"name": "A", "at": [6.0, 0.75]}],
        "stages": [
            {"name": "gravity", "loads": {"gravity": [0, -1]}},
            {"name": "pull", "increments": 30,
             "loads": {"points": [{"at": [6.0, 0.75], "force": [60000, 0]}]}},
        ],
        "blocks": list(pull_out_bricks()),
    }


def assert_same_results(a, b):
    for part in ("blocks", "interfaces"):
        pa, pb = getattr(a, part), getattr(b, part)
        assert pa.keys() == pb.keys()
        for key in pa:
            assert np.array_equal(pa[key], pb[key]), f"{part}.{key}"
    ha, hb = a.history, b.history
    for key in ("stage", "increment", "stage_factor", "yielding_points", "open_points"):
        assert np.array_equal(ha[key], hb[key]), key
    for name in ha["monitors"]:
        assert np.array_equal(ha["monitors"][name], hb["monitors"][name])
    assert a.collapse["carried_factor"] == b.collapse["carried_factor"]
    assert a.collapse["failed_factor"] == b.collapse["failed_factor"]
    assert np.array_equal(a.collapse["mechanism"]["block_velocities"],
                          b.collapse["mechanism"]["block_velocities"])


def test_the_same_case_from_yaml_and_from_a_dict_gives_the_same_bits():
    from_file = bimrock.Case.from_file(example("pull_out", "case.yaml"))
    from_dict = bimrock.Case.from_dict(pull_out_dict())
    assert from_file.check() == from_dict.check()
    assert_same_results(from_file.run(), from_dict.run())


def test_a_file_document_round_trips_through_python_data():
    case = bimrock.Case.from_file(example("pull_out", "case.yaml"))
    assert case.document == pull_out_dict()


def test_a_wrong_value_names_its_item_without_a_line():
    bad = pull_out_dict()
    bad["joint_materials"]["vertical"]["kn"] = "stiff"
    with pytest.raises(bimrock.InputError) as e:
        bimrock.Case.from_dict(bad, name="wall")
    assert e.value.item == "joint_materials.vertical.kn"
    assert e.value.line == 0  # a line of the text made from the dict would mislead
    assert str(e.value).startswith("wall: joint_materials.vertical.kn: ")
    assert isinstance(e.value, ValueError)


def test_an_invalid_model_names_its_item():
    bad = pull_out_dict()
    bad["materials"]["rock"]["nu"] = 0.7
    with pytest.raises(bimrock.InputError, match="Poisson") as e:
        bimrock.Case.from_dict(bad)
    assert e.value.item == "materials.rock"
    bad = pull_out_dict()
    bad["stages"][1]["loads"]["points"][0]["at"] = [7.0, 0.75]
    with pytest.raises(bimrock.InputError, match="lies in no block") as e:
        bimrock.Case.from_dict(bad)
    assert e.value.item == "stages[1].loads.points[0]"


def test_an_unknown_key_and_a_bad_file_are_named_as_the_command_names_them(tmp_path):
    bad = pull_out_dict()
    bad["materials"]["rock"]["young"] = 1e9
    with pytest.raises(bimrock.InputError, match="young"):
        bimrock.Case.from_dict(bad)
    case_file = tmp_path / "case.yaml"
    case_file.write_text("schema: 1\nmaterials:\n  rock: {E: -1, nu: 0.2}\n"
                         "blocks:\n  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1]]}\n")
    with pytest.raises(bimrock.InputError) as e:
        bimrock.Case.from_file(case_file)
    assert e.value.file == str(case_file)
    assert e.value.line == 3
    assert str(e.value).startswith(f"{case_file}:3: materials.rock: ")
    with pytest.raises(bimrock.InputError, match="no such file"):
        bimrock.Case.from_file(tmp_path / "missing.yaml")


def test_a_structure_that_is_not_supported_raises_model_error():
    loose = pull_out_dict()
    del loose["supports"]
    case = bimrock.Case.from_dict(loose)
    with pytest.raises(bimrock.ModelError):
        case.run()


def test_update_equals_a_case_built_anew_and_refuses_the_geometry():
    case = bimrock.Case.from_dict(pull_out_dict())
    changed = pull_out_dict()
    changed["joint_materials"]["horizontal"]["cohesion"] = 15.0e3
    changed["stages"][1]["increments"] = 12
    case.update(joint_materials=changed["joint_materials"], stages=changed["stages"])
    assert case.document == changed
    result = case.run()
    assert_same_results(result, bimrock.Case.from_dict(changed).run())
    # The brick is sheared out along its two bed joints: P = 2C = 30 kN of the stage's 60 kN.
    assert result.collapse["carried_factor"] <= 0.5 <= result.collapse["failed_factor"] <= 0.5005
    with pytest.raises(ValueError, match="blocks"):
        case.update(blocks=[])
    renamed = changed["materials"]
    renamed["granite"] = renamed.pop("rock")
    with pytest.raises(bimrock.InputError, match="build a new model"):
        case.update(materials=renamed)


def test_update_bolts_holds_or_frees_the_tunnel_crown():
    # examples/tunnel_excavation: its crown wedge falls in the bench's stage without bolts, and
    # stands with them (bolted.yaml is case.yaml plus the bolts).
    case = bimrock.Case.from_file(str(example("tunnel_excavation", "bolted.yaml")))
    bolts = case.document["bolts"]
    assert case.run().collapse is None
    case.update(bolts=None)
    assert "bolts" not in case.document
    unbolted = case.run()
    assert unbolted.collapse["stage"] == 3  # bench
    case.update(bolts=bolts)
    assert case.run().collapse is None
