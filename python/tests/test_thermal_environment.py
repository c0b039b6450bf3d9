"""A model with an environment runs in memory and into a folder alike: the members' temperatures
are coupled to the motion both ways (thermal/thermal_coupling.hpp), and the folder gets
temperatures.csv and summary.json's "temperatures"."""
import csv
import json
import os
import pathlib

import deploydyn

EXAMPLE = pathlib.Path(os.environ["DEPLOYDYN_SOURCE_DIR"]) / "examples/thermal/boom_out_of_eclipse.yaml"
ALPHA = 2.3e-5
REFERENCE_K = 293.15


def test_in_memory_and_folder_runs_couple_the_same_temperatures(tmp_path):
    model = deploydyn.load(EXAMPLE)
    in_memory = model.run(check=True)
    in_folder = model.run(out=tmp_path, check=True)
    assert list(in_memory.history["strain.boom"]) == list(in_folder.history["strain.boom"])
    with open(tmp_path / "temperatures.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(in_folder.history["t"])
    for row, strain in zip(rows, in_folder.history["strain.boom"]):
        assert abs(strain - ALPHA * (float(row["T.boom"]) - REFERENCE_K)) < 1e-10
    extremes = in_folder.summary["temperatures"]
    assert extremes["max_member"] == "boom"
    assert abs(extremes["max_K"] - float(rows[-1]["T.boom"])) < 1e-9
    # Started at its stress-free temperature the boom starts unstrained: the strain is thermal.
    still = deploydyn.load(EXAMPLE, overrides=["environment.initial_temperature=293.15"]).run(check=True)
    assert abs(still.history["strain.boom"][0]) < 1e-12


def test_a_run_in_memory_gives_the_temperatures_a_folder_holds(tmp_path):
    """Result.temperatures: temperatures.csv's columns and rows, from memory and from the folder
    alike, and summary["temperatures"] in both; with section gradients also dT_section.<beam>."""
    model = deploydyn.load(EXAMPLE)
    in_memory = model.run(check=True)
    in_folder = model.run(out=tmp_path, check=True)
    assert list(in_memory.temperatures) == ["t", "T.boom"]
    assert list(in_folder.temperatures) == list(in_memory.temperatures)
    for column, values in in_folder.temperatures.items():
        assert list(in_memory.temperatures[column]) == list(values), column
    assert list(in_memory.temperatures["t"]) == list(in_memory.history["t"])
    # Cold out of eclipse (200 K), broadside later: it warms, and the summary says by how much.
    temperatures = in_memory.temperatures["T.boom"]
    assert temperatures[0] == 200.0 and temperatures[-1] > 270.0
    assert in_memory.summary["temperatures"] == in_folder.summary["temperatures"]
    assert abs(in_memory.summary["temperatures"]["max_K"] - max(temperatures)) < 1e-9

    tube = {
        "nodes": {"A": [0, 0], "B": [1, 0]},
        "materials": {"alu": {"E": 7.0e10, "alpha": ALPHA, "density": 2700, "specific_heat": 900,
                              "absorptivity": 0.6, "emissivity": 0.8, "conductivity": 10}},
        "sections": {"tube": {"shape": "circular_tube", "outer_diameter": 0.02, "wall_thickness": 0.001}},
        "elements": {"arm": {"type": "beam", "nodes": ["A", "B"], "section": "tube", "material": "alu"}},
        "supports": [{"node": "A", "fix": ["x", "y", "rotation"]}],
        "environment": {"type": "orbit", "sun_direction": [0, 1, 0], "reference_temperature": REFERENCE_K,
                        "section_gradients": True},
        "analysis": {"type": "static", "end": 100, "step": 10}}
    graded = deploydyn.loads(json.dumps(tube)).run(check=True).temperatures
    assert list(graded) == ["t", "T.arm", "dT_section.arm"]
    assert graded["dT_section.arm"][0] == 0.0 and graded["dT_section.arm"][-1] > 0.0
    # Without an environment: none.
    del tube["environment"]
    assert deploydyn.loads(json.dumps(tube)).run(check=True).temperatures == {}


def test_the_builder_gives_the_materials_and_environment_of_the_model_file():
    """ModelBuilder.material's thermal properties and ModelBuilder.environment write the model
    file's keys: the example with those two parts from the builder runs exactly as the file."""
    import json

    import yaml

    built = (deploydyn.ModelBuilder("boom")
             .material("aluminium", E=7.0e10, alpha=ALPHA, density=2700, specific_heat=900,
                       absorptivity=0.6, emissivity=0.8)
             .environment("orbit", sun_direction=[1, 0, 0], solar_constant=1361, sink_temperature=3,
                          eclipses=[[0, 300]], penumbra=30, reference_temperature=REFERENCE_K,
                          initial_temperature=200)
             .to_dict())
    spec = yaml.safe_load(EXAMPLE.read_text())
    # (PyYAML reads 7.0e10 as text: YAML 1.1 wants a dot before the exponent.)
    as_numbers = {key: float(value) for key, value in spec["materials"]["aluminium"].items()}
    assert built["materials"] == {"aluminium": as_numbers}
    assert built["environment"] == spec["environment"]
    spec["materials"], spec["environment"] = built["materials"], built["environment"]
    from_builder = deploydyn.loads(json.dumps(spec)).run(check=True)
    from_file = deploydyn.load(EXAMPLE).run(check=True)
    assert list(from_builder.history["strain.boom"]) == list(from_file.history["strain.boom"])
    hotter = dict(spec, environment=dict(spec["environment"], initial_temperature=250))
    assert list(deploydyn.loads(json.dumps(hotter)).run(check=True).history["strain.boom"]) != \
        list(from_file.history["strain.boom"])
