"""ParaView, a real client, reads what deploydyn writes (docs/model-format.md, `output`): the VTK
series vtk/deploydyn.pvd and the HDF5 file's index history.xdmf of a 3D roof run give every
output time, the structure's points and cells, and at a chosen time the axial forces and
displacements that history.csv has; and a screenshot of the roof rendered from the xdmf shows
it (not a blank picture).

Runs pvpython (Debian's python3-paraview, installed by scripts/install-deps.sh) under xvfb-run
(ParaView's Debian build renders through X). Skipped, saying so, when either is missing."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest
from PIL import Image

from conftest import read_history, run_cli

PVPYTHON = shutil.which("pvpython")
XVFB_RUN = shutil.which("xvfb-run")
CHECK = __file__.replace("test_paraview.py", "paraview_check.py")

pytestmark = pytest.mark.skipif(
    PVPYTHON is None or XVFB_RUN is None,
    reason="needs ParaView's pvpython and xvfb-run: apt-get install python3-paraview xvfb xauth "
           "(scripts/install-deps.sh installs them)")


def pvpython_under_xvfb(*args):
    """pvpython on a virtual X display of its own. `xvfb-run -a` picks the first free display
    number, and two started at once (ctest -j2) may pick the same one: ParaView then aborts with
    "bad X server connection". A number of this process's own, and another try if it was taken.
    The server runs with -noreset: an X server resets when its last client leaves, and pvpython's
    early probes connect and leave, so that its window's connection could meet the server in
    its reset (refused, or reset by the server) and abort, in most runs on a loaded machine."""
    for attempt in range(3):
        display = 200 + (os.getpid() * 7 + attempt * 101) % 700
        done = subprocess.run([XVFB_RUN, "-n", str(display), "-s", "-screen 0 1280x1024x24 -noreset", PVPYTHON, *args],
                              capture_output=True, text=True, timeout=300)
        if "bad X server connection" not in done.stderr and "Xvfb failed to start" not in done.stderr:
            return done
    return done


@pytest.fixture(scope="module")
def roof_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("paraview")
    roof = folder / "roof.yaml"
    run_cli("generate", "roof", "--units", 3, "--trusses", 2, "--out", roof)
    run_cli("run", roof, "--out", folder / "run", "--quiet", "--set", "analysis.end=0.5",
            "--set", "output.vtk=true", "--set", "output.hdf5=true")
    return folder / "run"


def test_paraview_reads_the_pvd_and_the_xdmf_as_history_csv(roof_run, tmp_path):
    columns, history = read_history(roof_run / "history.csv")
    row = len(history) // 2
    time = history[row, columns.index("t")]
    done = pvpython_under_xvfb(CHECK, str(roof_run), repr(time), str(tmp_path / "roof.png"))
    assert done.returncode == 0, f"exit {done.returncode}: " + done.stdout[-2000:] + done.stderr[-3000:]
    result = json.loads(next(line for line in done.stdout.splitlines() if line.startswith("{")))
    forces = [columns.index(c) for c in columns if c.startswith("force.")]
    nodes = sorted({c.split(".", 1)[1] for c in columns if c.startswith("x.")},
                   key=lambda n: columns.index("x." + n))
    for name in ("vtk/deploydyn.pvd", "history.xdmf"):
        seen = result[name]
        assert seen["times"] == pytest.approx(history[:, 0], abs=0, rel=0), name
        assert seen["points"] == len(nodes), name
        assert seen["cells"] == len(forces), name
        assert {"axial_force_N", "strain", "temperature_change_C"} <= set(seen["cell_arrays"]), name
        # Cell i is element i, in history.csv's order of force columns: the same doubles.
        assert seen["axial_force_N"] == list(history[row, forces]), name
    assert result["history.xdmf"]["reader"] != result["vtk/deploydyn.pvd"]["reader"]
    assert np.array_equal(result["history.xdmf"]["displacement_m"], result["vtk/deploydyn.pvd"]["displacement_m"])

    image = np.asarray(Image.open(tmp_path / "roof.png").convert("RGB")).astype(int)
    assert image.shape[:2] == (480, 640)
    background = image[0, 0]
    assert all(np.array_equal(image[y, x], background) for y, x in ((0, -1), (-1, 0), (-1, -1)))
    drawn = np.any(np.abs(image - background) > 30, axis=2)
    assert 0.002 < drawn.mean() < 0.5, f"{drawn.mean():.4f} of the picture drawn: blank or all one colour"
