"""history.h5 holds what docs/model-format.md says it holds: every dataset path of the
document's table opens with h5py in a run's file with the documented shape, and the document's
h5py one-liners run. (Issue 31: the document described /mesh/points and /mesh/cells/<array>,
which the file never had.)"""
import re

import h5py
import numpy as np

from conftest import SOURCE_DIR, run_cli

FORMAT = (SOURCE_DIR / "docs" / "model-format.md").read_text(encoding="utf-8")


def documented_table():
    """(paths, shape text) of each row of the history.h5 table."""
    start = FORMAT.index("a time-history run also writes, on the writer")
    table = FORMAT[start:FORMAT.index("\n\n", FORMAT.index("| dataset |", start))]
    rows = []
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) == 3 and cells[0].startswith("`/"):
            rows.append((re.findall(r"`(/[^`]+)`", cells[0]), cells[1]))
    return rows


def test_every_documented_dataset_opens_with_its_shape(tmp_path):
    folder = tmp_path / "run"
    run_cli("run", SOURCE_DIR / "examples" / "paper" / "parallel.yaml", "--quiet", "--out", folder,
            "--set", "output.hdf5=true", "--set", "analysis.end=0.2")
    rows = documented_table()
    assert len(rows) >= 5
    with h5py.File(folder / "history.h5") as f:
        n_rows = len(f["time"])
        n_nodes, n_elements = 4, 3
        sizes = {"rows": n_rows, "nodes": n_nodes, "elements": n_elements, "3": 3,
                 "columns": len(f["history_columns"])}
        for paths, shape in rows:
            shapes = shape.split(",") if shape else []   # one per path, or one for all
            for k, path in enumerate(paths):
                path = path.replace("<row>", "000001").replace("<array>", "axial_force_N")
                assert path in f, f"docs/model-format.md names {path}, which history.h5 does not hold"
                if shapes:
                    dims = shapes[k if len(shapes) == len(paths) else 0]
                    expected = tuple(sizes[d.strip()] for d in dims.split("×"))
                    assert f[path].shape == expected, path
        # The document's h5py recipes.
        last = [f[f"mesh/steps/{r:06d}/points"][1] for r in range(len(f["time"]))]
        assert len(last) == n_rows and np.ptp([p[1] for p in last]) > 0          # node B rises
        assert f["history"][:].shape == (n_rows, sizes["columns"])
    assert "f[f\"mesh/steps/{r:06d}/points\"][i] for r in range(len(f[\"time\"]))" in FORMAT
