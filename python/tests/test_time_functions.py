"""The closed-form functions of time of the model builder (docs/model-format.md, "Functions of
time"): each kind, as a crank's angle, turns the crank to the angle its formula gives at every
output time (each starts at 0, the crank's initial angle); their integral, read as an angular velocity, to its closed form; bad arguments are
TypeErrors naming the function and argument, bad values InputErrors at build."""
import math
import re

import numpy as np
import pytest

import deploydyn

E = 2.0e11      # Pa
AREA = 1.0e-4   # m²
STEP = 0.05     # s
END = 3.0       # s


def crank(profile, reading="angle", end=END):
    return (deploydyn.ModelBuilder("crank")
            .node("A", 0, 0).node("B", 1, 0)
            .material("steel", E=E)
            .bar("crank", "A", "B", area=AREA, material="steel", mass=1.0)
            .support("A")
            .bar_angle_driver("motor", element="crank", pivot="A", profile=profile, reading=reading)
            .analysis(type="static", end=end, step=STEP)
            .build())


def angles(result):
    return np.unwrap(np.arctan2(result["y.B"], result["x.B"]))


def ramp(t, t0, v0, t1, v1, shape):
    s = np.clip((t - t0) / (t1 - t0), 0.0, 1.0)
    return v0 + (v1 - v0) * shape(s)


def cycloid_shape(s):
    return s - np.sin(2 * np.pi * s) / (2 * np.pi)


def cosine_shape(s):
    return 0.5 * (1 - np.cos(np.pi * s))


SPIN_UP = deploydyn.piecewise([(0.5, 1.5, deploydyn.cycloidal(0.5, 0.0, 1.5, 0.8)),
                               (1.5, 2.0, 0.8),
                               (2.0, 2.8, deploydyn.cosine_ramp(2.0, 0.8, 2.8, 0.3))])


def spin_up(t):
    return np.where(t < 1.5, ramp(t, 0.5, 0.0, 1.5, 0.8, cycloid_shape),
                    np.where(t < 2.0, 0.8, ramp(t, 2.0, 0.8, 2.8, 0.3, cosine_shape)))


@pytest.mark.parametrize("profile, formula", [
    (deploydyn.cycloidal(0.5, 0.0, 2.5, 1.2), lambda t: ramp(t, 0.5, 0.0, 2.5, 1.2, cycloid_shape)),
    (deploydyn.cosine_ramp(0.5, 0.0, 2.5, 1.2), lambda t: ramp(t, 0.5, 0.0, 2.5, 1.2, cosine_shape)),
    (deploydyn.polynomial([0.0, 0.3, -0.05]), lambda t: 0.3 * t - 0.05 * t**2),
    (deploydyn.polynomial([0.0, 0.5, -0.1], interval=(1, 2)),
     lambda t: (lambda tau: 0.5 * tau - 0.1 * tau**2)(np.clip(t - 1, 0, 1))),
    (deploydyn.harmonic(0.4, 0.7, phase=math.pi / 6, offset=-0.2),
     lambda t: -0.2 + 0.4 * np.sin(2 * np.pi * 0.7 * t + math.pi / 6)),
    (SPIN_UP, spin_up),
    (deploydyn.sum_of(SPIN_UP, deploydyn.harmonic(0.05, 2.0), deploydyn.polynomial([0, 0.1])),
     lambda t: spin_up(t) + 0.05 * np.sin(2 * np.pi * 2.0 * t) + 0.1 * t),
])
def test_each_kind_turns_the_crank_to_its_formula(profile, formula):
    result = crank(profile).run(check=True)
    np.testing.assert_allclose(angles(result), formula(np.asarray(result["t"])), atol=1e-9)


def test_read_as_angular_velocity_a_ramp_turns_by_its_integral():
    # ∫ of a ramp 0 → 1 over [0.5, 2.5], then held, up to 3 s: (2.5 − 0.5)/2 + 0.5 = 1.5 rad.
    for profile in (deploydyn.cycloidal(0.5, 0, 2.5, 1), deploydyn.cosine_ramp(0.5, 0, 2.5, 1)):
        result = crank(profile, reading="angular_velocity").run(check=True)
        assert angles(result)[-1] == pytest.approx(1.5, abs=1e-9)


def test_functions_reach_the_model_file_as_written():
    written = crank(deploydyn.sum_of(SPIN_UP, "paper_eq23")).to_yaml()
    for kind in ("type: sum", "type: piecewise", "type: cycloidal", "type: cosine_ramp", "type: smooth_trapezoid"):
        assert kind in written


@pytest.mark.parametrize("call, message", [
    (lambda: deploydyn.cycloidal(0, "0", 1, 1), "cycloidal: v0 must be a number"),
    (lambda: deploydyn.polynomial("1, 2"), "polynomial: coefficients must be a sequence of numbers"),
    (lambda: deploydyn.harmonic(1.0, None), "harmonic: frequency must be a number"),
    (lambda: deploydyn.piecewise([(0, 1)]), "piecewise: pieces[0] must be a (t_from, t_to, function) triple"),
    (lambda: deploydyn.piecewise([(0, 1, [1, 2])]), "piecewise: pieces[0] function must be a number"),
    (lambda: deploydyn.sum_of(1, None), "sum_of: terms[1] must be a number"),
])
def test_bad_arguments_are_type_errors_naming_the_function(call, message):
    with pytest.raises(TypeError, match=re.escape(message)):
        call()


@pytest.mark.parametrize("profile, message", [
    (deploydyn.harmonic(1.0, 0.0), "drivers.motor.profile.frequency: must be positive (Hz), got 0"),
    (deploydyn.piecewise([(0, 1, 0.0), (1.5, 2, 0.0)]), "drivers.motor.profile.pieces.1.from: must be the previous piece's `to` = 1 s"),
    (deploydyn.piecewise([(0, 1, deploydyn.cycloidal(0, 0, 1, 1)), (1, 2, 0.0)]),
     "pieces must join without a jump in value"),
    (deploydyn.sum_of(), "drivers.motor.profile.terms: expected a list of 1 to 10000 functions, got 0 item(s)"),
])
def test_bad_values_are_input_errors_at_build(profile, message):
    with pytest.raises(deploydyn.InputError, match=re.escape(message)):
        crank(profile)
