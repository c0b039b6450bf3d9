"""Model.run(restart_from=, at=), Model.modes(hinges=, from_=) and the builder's initial
velocities (spin, node_velocity): the same as the command's `run --restart-from/--at` and
`modes --hinges/--from`, and a spun free bar's ½ I ω²."""
import numpy as np
import pytest

import deploydyn
from conftest import run_cli

PARALLEL = "examples/paper/parallel.yaml"
BOOM = "examples/boom/boom.yaml"


def spun_bar(**extra):
    """A free bar of 1 m and 2 kg about its centre; I = m L²/12 = 1/6 kg·m²."""
    b = (deploydyn.ModelBuilder("spun bar")
         .node("A", -0.5, 0).node("B", 0.5, 0)
         .material("steel", E=2e11)
         .bar("bar", "A", "B", area=1e-4, material="steel", mass=2.0)
         .analysis(type="dynamic", end=0.1, step=1e-3, output_interval=1e-2))
    for method, args in extra.items():
        getattr(b, method)(*args)
    return b


def test_builder_spin_starts_with_half_i_omega_squared_and_writes_the_file_keys():
    builder = spun_bar(spin=(3.0, [0, 0]))
    assert builder.to_dict()["initial_velocities"] == {"spin": {"rate": 3.0, "centre": [0, 0]}}
    result = builder.build().run(check=True)
    assert result["kinetic"][0] == pytest.approx(0.5 * (2.0 / 12.0) * 3.0**2, rel=1e-12)
    at_rest = spun_bar().build().run(check=True)
    assert at_rest["kinetic"][0] == 0.0


def test_builder_node_velocity_across_a_guide_keeps_its_part_along_it():
    """A pinned, B on a guide along x: B given (1.5, 2) m/s starts with (1.5, 0); its kinetic
    energy is ½ (2m/6) v² with the bar's consistent mass (tests/solvers/initial_velocities_test.cpp)."""
    model = (spun_bar(node_velocity=("B", [1.5, 2.0]))
             .support("A").support("B", fix=["y"])
             .build())
    assert "initial_velocities:" in model.to_yaml()
    result = model.run(check=True)
    assert result["kinetic"][0] == pytest.approx(0.5 * (2.0 / 3.0) * 1.5**2, rel=1e-12)
    with pytest.raises(deploydyn.InputError, match="analysis type static starts at rest"):
        spun_bar(node_velocity=("B", [1.5, 2.0])).analysis(type="static").build()


def test_run_restarted_from_a_folder_continues_the_single_run_bit_for_bit(source_dir, tmp_path):
    model = deploydyn.load(source_dir / PARALLEL, overrides={"analysis.end": 1.0})
    whole = model.run(out=tmp_path / "whole", check=True, keep_every_state=True)
    model.with_overrides({"analysis.end": 0.5}).run(out=tmp_path / "first", check=True)
    second = model.run(out=tmp_path / "second", restart_from=tmp_path / "first", check=True)
    from_half = whole.t >= 0.5 - 1e-12
    assert np.array_equal(second.values, whole.values[from_half])
    # In memory, the same values; from a chosen output time of the whole run, too.
    assert np.array_equal(model.run(restart_from=tmp_path / "first", check=True).values, second.values)
    at = model.run(restart_from=tmp_path / "whole", at=0.25, check=True)
    assert np.array_equal(at.values, whole.values[whole.t >= 0.25 - 1e-12])


def test_restart_mistakes_name_the_python_arguments(source_dir, tmp_path):
    model = deploydyn.load(source_dir / PARALLEL, overrides={"analysis.end": 0.1})
    model.run(out=tmp_path / "run", check=True)
    with pytest.raises(ValueError, match=r"Model.run: restart folder \(restart_from\): no folder"):
        model.run(restart_from=tmp_path / "nowhere")
    with pytest.raises(ValueError, match=r"restart time \(at\): 0.05 s is not a time"):
        model.with_overrides({"analysis.end": 1.0}).run(restart_from=tmp_path / "run", at=0.05)
    with pytest.raises(ValueError, match="give restart_from too"):
        model.run(at=0.05)
    with pytest.raises(ValueError, match="give out too"):
        model.run(keep_every_state=True)
    with pytest.raises(TypeError, match="keep_every_state must be a bool"):
        model.run(out=tmp_path / "x", keep_every_state="yes")


def modes_csv_omega2(folder):
    with open(folder / "modes.csv", encoding="utf-8") as f:
        columns = f.readline().strip().split(",")
    return np.loadtxt(folder / "modes.csv", delimiter=",", skiprows=1, ndmin=2)[:, columns.index("omega2")]


@pytest.mark.parametrize("hinges", ["held", "latched"])
def test_modes_with_held_or_latched_hinges_are_the_commands(source_dir, tmp_path, hinges):
    model = deploydyn.load(source_dir / BOOM)
    modes = model.modes(count=3, hinges=hinges)
    run_cli("modes", source_dir / BOOM, "--hinges", hinges, "--count", 3, "--out", tmp_path / hinges)
    assert modes["failures"] == [""]
    assert modes["omega2"][0] == pytest.approx(modes_csv_omega2(tmp_path / hinges), rel=1e-12)
    with pytest.raises(ValueError, match="hinges must be 'free', 'held' or 'latched'"):
        model.modes(count=3, hinges="stowed")


def test_modes_from_a_run_folder_are_the_commands(source_dir, tmp_path):
    """The paper's linkage at the end of a run to 0.5 s (its driver holds it there)."""
    model = deploydyn.load(source_dir / PARALLEL, overrides={"analysis.end": 0.5})
    model.run(out=tmp_path / "run", check=True)
    modes = model.modes(count=3, from_=tmp_path / "run")
    run_cli("modes", source_dir / PARALLEL, "--set", "analysis.end=0.5", "--from", tmp_path / "run", "--count", 3,
            "--out", tmp_path / "modes")
    assert modes["failures"] == [""]
    assert modes["times"].tolist() == [pytest.approx(0.5)]
    assert modes["omega2"][0] == pytest.approx(modes_csv_omega2(tmp_path / "modes"), rel=1e-12)
    # Not the modes at t = 0 of the model.
    assert not np.allclose(modes["omega2"][0], model.modes(count=3)["omega2"][0], rtol=1e-6)
    with pytest.raises(ValueError, match=r"Model.modes: restart folder \(from_\): no folder"):
        model.modes(count=3, from_=tmp_path / "nowhere")
