"""Issue 31: Model.continuation carries the labels of q's columns and, per point, the columns
path.csv holds after its own (history.csv's, output.select applied): the same labels and values
as the CLI's path.csv and summary.json for the same model, and labels that name the right
entries of q."""
import csv
import json

import numpy as np
import pytest

import deploydyn
from conftest import run_cli, MISES

PATH_OWN_COLUMNS = 7  # mu, load_N, displacement_norm_m, 2 eigenvalues, n_negative, event


@pytest.mark.parametrize("select", [None, "{nodes: [C], elements: ['2'], quantities: [position, force, reaction]}"])
def test_continuation_labels_and_columns_are_the_clis(tmp_path, select):
    model_file = tmp_path / "mises.yaml"
    model_file.write_text(MISES)
    folder = tmp_path / "out"
    overrides = ["--set", f"output.select={select}"] if select else []
    run_cli("run", model_file, "--quiet", "--out", folder, *overrides)
    with open(folder / "path.csv") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    summary = json.loads((folder / "summary.json").read_text())

    model = deploydyn.load(model_file, overrides={"output.select": select} if select else None)
    path = model.continuation("load", end=1.1, eigenvalues=2)
    # The coordinates as the CLI names them (summary.json's event modes, one entry per coordinate).
    assert path["coordinates"] == list(summary["events"][0]["mode"])
    assert len(path["coordinates"]) == path["q"].shape[1]
    # path.csv's columns after its own, and their values at the same points.
    assert path["columns"] == header[PATH_OWN_COLUMNS:]
    assert path["values"].shape == (len(rows), len(path["columns"]))
    written = np.array([[float(v) for v in row[PATH_OWN_COLUMNS:]] for row in rows])
    assert path["values"] == pytest.approx(written, rel=1e-12, abs=1e-12)
    # The labels name q's entries: the apex's coordinates are its position columns.
    for axis in ("x", "y"):
        column = path["columns"].index(f"{axis}.C")
        np.testing.assert_allclose(path["q"][:, path["coordinates"].index(f"{axis}.C")], path["values"][:, column],
                                   rtol=0, atol=1e-15)
    if select:
        assert path["columns"] == ["x.C", "y.C", "force.2", "reaction.A.x", "reaction.A.y", "reaction.B.x",
                                   "reaction.B.y"]
