"""Overrides from Python: the same paths and checks as --set, and ΔT does what it should."""
import numpy as np
import pytest

import deploydyn

ALPHA = 2.0e-5  # 1/°C, every bar of the general linkage
DT = 130.0      # °C
END = 0.1       # s


def test_dT_override_adds_alpha_dT_to_the_strain(general_model):
    normal = deploydyn.load(general_model, overrides={"analysis.end": END}).run(check=True)
    hot = deploydyn.load(general_model, overrides={"analysis.end": END, "thermal.dT": DT}).run(
        check=True)
    for element in ("1", "2", "3"):
        thermal = hot[f"strain.{element}"] - hot[f"mstrain.{element}"]
        np.testing.assert_allclose(thermal, ALPHA * DT, rtol=1e-12)
        np.testing.assert_allclose(normal[f"strain.{element}"] - normal[f"mstrain.{element}"], 0.0,
                                   atol=1e-15)
    # The crank's angle is driven, the coupler and rocker lengths fix B and C: a determinate
    # linkage expands freely at t = 0, so its total strain grows by αΔT and its stress does not.
    first = 0
    for element in ("1", "2", "3"):
        grown = hot[f"strain.{element}"][first] - normal[f"strain.{element}"][first]
        assert grown == pytest.approx(ALPHA * DT, rel=1e-6)
        assert abs(hot[f"mstrain.{element}"][first]) < 1e-6 * ALPHA * DT


def test_override_forms_agree(general_model):
    expected = deploydyn.load(general_model, overrides={"thermal.dT": -170, "analysis.end": END})
    forms = [
        ["thermal.dT=-170", f"analysis.end={END}"],
        [("thermal.dT", -170), ("analysis.end", END)],
        {"thermal.dT": "-170", "analysis.end": str(END)},
    ]
    for overrides in forms:
        model = deploydyn.load(general_model, overrides=overrides)
        assert model.to_yaml() == expected.to_yaml(), overrides
    assert expected.temperature_changes()["2"] == -170.0


def test_set_and_with_overrides(general_model):
    model = deploydyn.load(general_model)
    hot = model.with_overrides({"thermal.dT": 130})
    assert model.temperature_changes()["1"] == 0.0          # unchanged
    assert hot.temperature_changes()["1"] == 130.0
    model.set("thermal.dT", 50).set({"analysis.step": 5e-4})
    assert model.temperature_changes()["1"] == 50.0
    assert model.analysis["step"] == 5e-4
    model.set("thermal.dT", 60)                              # replaces, does not stack
    assert model.overrides == [("analysis.step", "0.0005"), ("thermal.dT", "60")]


def test_bad_override_leaves_the_model_as_it_was(general_model):
    model = deploydyn.load(general_model, overrides={"thermal.dT": 10})
    with pytest.raises(deploydyn.InputError) as error:
        model.set("analysis.step", -1)
    assert str(error.value).startswith("--set analysis.step=-1: analysis.step: ")
    assert error.value.field == "analysis.step"
    assert error.value.line is None
    assert model.temperature_changes()["1"] == 10.0
    assert model.analysis["step"] == 1e-3
    with pytest.raises(ValueError, match="expected PATH=VALUE"):
        model.set("thermal.dT130")
    with pytest.raises(deploydyn.InputError):
        model.set("thermal.dT", [1, 2])


def test_python_values_extend_a_model_in_code_without_yaml():
    """A function, a list or a mapping is given as Python data: as --set takes YAML flow values."""
    import deploydyn
    from conftest import GENERAL
    model = deploydyn.load(GENERAL)
    heated = model.with_overrides({"thermal.dT": deploydyn.smooth_step(0, 0, 1, 50)})
    assert heated.temperature_changes(1.0) == {"1": 50.0, "2": 50.0, "3": 50.0}
    assert heated.temperature_changes(0.0) == {"1": 0.0, "2": 0.0, "3": 0.0}
    named = model.with_overrides({"functions": {"ramp": deploydyn.smooth_step(0, 0, 2, 130)},
                                  "thermal.dT": "ramp"})
    assert named.temperature_changes(2.0)["2"] == 130.0
    rolled = model.with_overrides({"supports.1.fix": ("y",)})
    assert rolled.overrides == [("supports.1.fix", '["y"]')]
