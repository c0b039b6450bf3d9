"""examples/python/sweep_dT.py, run with a coarse sweep so that it cannot rot."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR

PNG = b"\x89PNG\r\n\x1a\n"


def test_coarse_sweep_writes_the_plot_and_the_table(tmp_path):
    out = tmp_path / "sweep.png"
    done = subprocess.run(
        [sys.executable, str(SOURCE_DIR / "examples" / "python" / "sweep_dT.py"),
         "--values", "-170", "0", "130", "--end", "0.3", "--jobs", "2", "--out", str(out)],
        capture_output=True, text=True, env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    rows = [line.split() for line in done.stdout.splitlines() if line.strip().endswith("completed")]
    assert [float(row[0]) for row in rows] == [-170.0, 0.0, 130.0]
    # Total coupler strain follows αΔT = 2e-5 ΔT (µε): −3400, 0, +2600 give or take ε_m.
    for row, free in zip(rows, (-3400.0, 0.0, 2600.0)):
        assert abs(float(row[1]) - free) < 100.0, row
    assert "sweep: 3 runs in" in done.stdout
    assert out.read_bytes()[:8] == PNG
    assert out.stat().st_size > 10_000
