"""A model file loaded and run from Python gives what the command line gives."""
import json
import pathlib

import numpy as np

import deploydyn
from conftest import read_history, run_cli

END = 0.2  # s: 200 steps of the general linkage, 41 output rows


def without_wall_time(summary):
    return {k: v for k, v in summary.items() if k != "wall_time"}


def test_package_is_the_built_one():
    core = pathlib.Path(deploydyn._core.__file__)
    assert core.parent == pathlib.Path(deploydyn.__file__).parent


def test_version_is_the_projects():
    """deploydyn.__version__ is the version of CMakeLists.txt's project(), as the CLI's --version."""
    import os
    import re
    cmake = pathlib.Path(os.environ["DEPLOYDYN_SOURCE_DIR"]) / "CMakeLists.txt"
    version = re.search(r"project\(deploydyn VERSION ([0-9.]+)", cmake.read_text()).group(1)
    assert deploydyn.__version__ == version
    assert run_cli("--version").stdout.strip() == f"deploydyn {version}"


def test_model_contents(general_model):
    model = deploydyn.load(general_model)
    assert model.name == "general four-bar linkage"
    assert model.dimension == 2
    assert list(model.nodes) == ["A", "B", "C", "D"]
    assert model.nodes["D"] == (0.8, 0.0)
    assert model.elements["2"]["nodes"] == ("B", "C")
    assert model.elements["2"]["E"] == 5.0e6
    assert model.drivers["motor"]["effort"] == "torque"
    assert model.analysis["end"] == 5.0
    assert model.temperature_changes() == {"1": 0.0, "2": 0.0, "3": 0.0}


def test_in_memory_run_equals_the_cli_run(general_model, tmp_path):
    result = deploydyn.load(general_model, overrides={"analysis.end": END}).run()
    assert result.ok, result.message

    run_cli("run", general_model, "--out", tmp_path, "--quiet", "--set", f"analysis.end={END}")
    columns, values = read_history(tmp_path / "history.csv")

    assert result.columns == columns                      # names and order, exactly
    assert list(result.history) == columns
    assert result.values.shape == (41, len(columns))
    # history.csv holds 17 significant digits: what it reads back is what was computed.
    np.testing.assert_array_equal(result.values, values)
    for i, name in enumerate(columns):
        np.testing.assert_array_equal(result[name], values[:, i])
    assert result.t[-1] == END

    cli_summary = json.loads((tmp_path / "summary.json").read_text())
    assert without_wall_time(result.summary) == without_wall_time(cli_summary)


def test_run_into_a_folder_writes_what_the_cli_writes(general_model, tmp_path):
    model = deploydyn.load(general_model, overrides=[f"analysis.end={END}"])
    result = model.run(out=tmp_path / "py")
    run_cli("run", general_model, "--out", tmp_path / "cli", "--quiet", "--set", f"analysis.end={END}")

    assert result.folder == tmp_path / "py"
    assert ((tmp_path / "py" / "history.csv").read_bytes()
            == (tmp_path / "cli" / "history.csv").read_bytes())
    in_memory = model.run()
    np.testing.assert_array_equal(result.values, in_memory.values)
    assert without_wall_time(result.summary) == without_wall_time(in_memory.summary)
    again = deploydyn.read_result(tmp_path / "cli")
    np.testing.assert_array_equal(again.values, in_memory.values)


def test_saved_model_reads_back_the_same(general_model, tmp_path):
    model = deploydyn.load(general_model, overrides={"thermal.dT": 130, "analysis.end": 0.05})
    model.save(tmp_path / "saved.yaml")
    again = deploydyn.load(tmp_path / "saved.yaml")
    assert again.to_yaml() == model.to_yaml()
    np.testing.assert_array_equal(again.run().values, model.run().values)


def test_elements_show_their_materials_temperature_tables():
    """A material's E(T) and α(T) tables beside E and α (at the reference temperature, 20 °C
    here: the tables' values there), as the file gives them; a plain material has none."""
    model = deploydyn.loads("""
nodes: {A: [0, 0], B: [1, 0], C: [2, 0]}
materials:
  steel: {E: {temperature_C: [20, 100, 400], value: [2.1e11, 2.05e11, 1.7e11]},
          alpha: {temperature_C: [0, 200], value: [1.1e-5, 1.5e-5]}, density: 7850}
  plain: {E: 7.0e10, alpha: 2.3e-5, density: 2700}
elements:
  hot: {nodes: [A, B], area: 1.0e-4, material: steel}
  cold: {nodes: [B, C], area: 1.0e-4, material: plain}
supports: [{node: A}, {node: C}]
""", "tables.yaml")
    hot = model.elements["hot"]
    assert hot["E_table"] == {"temperature_C": (20.0, 100.0, 400.0), "value": (2.1e11, 2.05e11, 1.7e11)}
    assert hot["alpha_table"] == {"temperature_C": (0.0, 200.0), "value": (1.1e-5, 1.5e-5)}
    assert hot["E"] == 2.1e11
    assert abs(hot["alpha"] - (1.1e-5 + 20.0 / 200.0 * 0.4e-5)) < 1e-18
    cold = model.elements["cold"]
    assert "E_table" not in cold and "alpha_table" not in cold
    assert cold["E"] == 7.0e10
