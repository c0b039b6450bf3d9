"""A model with an environment runs in memory and into a folder alike: the members' temperatures
are coupled to the motion both ways (thermal/thermal_coupling.hpp), and the folder gets
temperatures.csv and summary.json's "temperatures"."""
import csv
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
