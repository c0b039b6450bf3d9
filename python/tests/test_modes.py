"""Model.modes: natural frequencies from Python, against a closed form and the CLI's table."""
import math

import numpy as np
import pytest

import deploydyn
from conftest import SOURCE_DIR, run_cli


def oscillator(mass_kind, **analysis):
    """A bar along x from a pin to a node sliding along x, with a 10 kg point mass."""
    analysis = analysis or {"type": "static", "end": 1.0, "step": 0.5}
    return (deploydyn.ModelBuilder("bar-mass oscillator")
            .node("A", 0, 0).node("B", 2.0, 0, mass=10.0)
            .material("steel", E=2e11)
            .bar("1", "A", "B", area=1e-4, material="steel", mass=3.0)
            .support("A").support("B", fix=["y"])
            .analysis(mass=mass_kind, **analysis)
            .build())


@pytest.mark.parametrize("mass_kind, share", [("lumped", 0.5), ("consistent", 1.0 / 3.0)])
def test_bar_mass_oscillator_frequency(mass_kind, share):
    modes = oscillator(mass_kind).modes(count=1)
    expected = 2e11 * 1e-4 / 2.0 / (10.0 + share * 3.0)
    assert modes["omega2"].shape == (1, 1)
    assert modes["omega2"][0, 0] == pytest.approx(expected, rel=1e-9)
    assert modes["frequency"][0, 0] == pytest.approx(math.sqrt(expected) / (2 * math.pi), rel=1e-9)
    # The mode moves x.B only, normalized to φᵀMφ = 1.
    phi = modes["modes"][0, :, 0]
    moving = modes["coordinates"].index("x.B")
    assert abs(phi[moving]) == pytest.approx(1.0 / math.sqrt(10.0 + share * 3.0), rel=1e-9)


def test_linkage_modes_at_several_times_and_errors(source_dir):
    model = deploydyn.load(source_dir / "examples" / "paper" / "parallel.yaml")
    modes = model.modes(count=3, at=[0.0, 2.5])
    assert modes["omega2"].shape == (2, 3)
    assert modes["modes"].shape == (2, 8, 3)
    assert np.all(np.diff(modes["omega2"], axis=1) >= 0)
    assert modes["failures"] == ["", ""]
    with pytest.raises(ValueError, match="at most 3"):
        model.modes(count=4)
    with pytest.raises(TypeError, match="count must be an int"):
        model.modes(count=2.5)


def test_continuation_finds_the_cold_parallel_jam(source_dir):
    """The thermal path of the parallel linkage towards −200 °C turns back at the closed-form
    −84.8435 °C (tests/verification/thermal_jam_verification_test.cpp derives it)."""
    model = deploydyn.load(source_dir / "examples" / "paper" / "parallel.yaml",
                           overrides={"thermal.dT": -200})
    path = model.continuation("thermal", end=1.0, max_steps=3000)
    assert path["q"].shape[1] == 8 and path["mu"].shape == path["displacement_norm"].shape
    assert path["eigenvalues"].shape[1] == 3
    limit = [e for e in path["events"] if e["kind"] == "limit_point"]
    assert limit, path["message"]
    assert limit[0]["mu"] * -200 == pytest.approx(-84.8434928418712, abs=1e-3)
    with pytest.raises(ValueError, match="parameter must be 'thermal', 'load' or 'driver'"):
        model.continuation("pressure", end=1.0)


def test_continuation_can_stop_at_its_first_event(source_dir):
    """stop_at="first_event": the same path ends at the limit point, that point its last, as the
    model key `stop_at: first_event` does."""
    model = deploydyn.load(source_dir / "examples" / "paper" / "parallel.yaml",
                           overrides={"thermal.dT": -200})
    whole = model.continuation("thermal", end=1.0, max_steps=3000)
    first = model.continuation("thermal", end=1.0, max_steps=3000, stop_at="first_event")
    assert first["end"] == "first_event", first["message"]
    assert len(first["events"]) == 1 and first["events"][0]["kind"] == "limit_point"
    assert first["events"][0]["mu"] == pytest.approx(whole["events"][0]["mu"], abs=1e-9)
    assert first["mu"][-1] == pytest.approx(first["events"][0]["mu"], abs=1e-9)
    assert len(first["mu"]) < len(whole["mu"])
    with pytest.raises(ValueError, match="stop_at must be 'end' or 'first_event'"):
        model.continuation("thermal", end=1.0, stop_at="limit")


def test_continuation_in_the_driver_time_deploys_the_parallelogram(source_dir):
    """μ = t: the quasi-static deployment at ΔT = 0 ends with the driven bar D–C turned by
    ∫ω = 0.365 · 4 rad from 5°, and A–B parallel to it (a parallelogram)."""
    model = deploydyn.load(source_dir / "examples" / "paper" / "parallel.yaml")
    path = model.continuation("driver", end=5.0)
    assert path["end"] == "reached_end", path["message"]
    assert path["mu"][0] == 0.0 and path["mu"][-1] == pytest.approx(5.0, abs=1e-12)
    names = ["x.A", "y.A", "x.B", "y.B", "x.C", "y.C", "x.D", "y.D"]
    q = dict(zip(names, path["q"][-1]))
    driven = math.atan2(q["y.C"] - q["y.D"], q["x.C"] - q["x.D"])
    crank = math.atan2(q["y.B"] - q["y.A"], q["x.B"] - q["x.A"])
    assert driven == pytest.approx(math.radians(5.0) + 0.365 * 4.0, abs=1e-10)
    assert crank == pytest.approx(driven, abs=1e-10)


@pytest.mark.parametrize("mass_kind, share", [("lumped", 0.5), ("consistent", 1.0 / 3.0)])
def test_modal_model_runs_in_memory_and_into_a_folder(tmp_path, mass_kind, share):
    expected = 2e11 * 1e-4 / 2.0 / (10.0 + share * 3.0)
    model = oscillator(mass_kind, type="modal", modes=1, at=[0, 0.5])  # run() computes its modes
    assert model.analysis["type"] == "modal"
    in_memory = model.run(check=True)
    on_disk = model.run(out=tmp_path / "modes", check=True)
    for result in (in_memory, on_disk):
        assert result.columns == ["frame", "t", "mode", "omega2", "frequency", "dT_C"]
        assert list(result.t) == [0.0, 0.5]
        assert result["omega2"] == pytest.approx([expected, expected], rel=1e-9)
        assert result.summary["modes"][1]["omega2"][0] == pytest.approx(expected, rel=1e-9)
    assert (tmp_path / "modes" / "vtk" / "frame_000001.vtu").exists()
    assert list(deploydyn.read_result(tmp_path / "modes")["omega2"]) == list(on_disk["omega2"])
    # Model.modes still returns numpy arrays for the same model.
    assert isinstance(model.modes(count=1)["omega2"], np.ndarray)


SUNLIT_STRING = SOURCE_DIR / "tests" / "thermal" / "models" / "sunlit_string.yaml"


def test_the_modes_of_a_model_with_an_environment_are_those_of_its_steady_field(tmp_path):
    """A steel string pinned at both ends, broadside to the sun in orbit, settles at
    T*⁴ = α_s S/(ε σ π) + T_sink⁴ (below T_ref: in tension): its modes are those of the same
    string at the given ΔT = T* − T_ref, as `deploydyn modes` gives them, not those at ΔT = 0."""
    steady_K = (0.5 * 1361.0 / (0.8 * 5.670374419e-8 * np.pi) + 3.0 ** 4) ** 0.25
    files = {}
    for name, load in (("sun", "environment: {type: orbit, sun_direction: [0, 0, 1], reference_temperature: 293.15}"),
                       ("given", f"thermal: {{dT: {steady_K - 293.15!r}}}"), ("cold", "thermal: {dT: 0}")):
        files[name] = tmp_path / f"{name}.yaml"
        files[name].write_text(SUNLIT_STRING.read_text() + load + "\n")
    sun, given, cold = (deploydyn.load(files[n]).modes(count=3)["omega2"][0] for n in ("sun", "given", "cold"))
    assert sun == pytest.approx(given, rel=1e-10)
    assert sun[0] > 100.0 * max(abs(cold[0]), 1e-3)  # untensioned, the string is free sideways
    printed = run_cli("modes", files["sun"], "--count", "3").stdout.split("\n")
    assert [float(line.split()[2]) for line in printed if line.strip().startswith("0 ")] == pytest.approx(sun, rel=1e-7)
