"""The numbers the documents quote are the program's: each quoted value is read from the
document's own sentence and compared with a fresh run, so that a slip like the README's "82 Hz"
(the linkage at ΔT = 0, quoted for the cold one) cannot recur."""
import json
import re

import numpy as np
import pytest

from conftest import SOURCE_DIR, read_history, run_cli

README = (SOURCE_DIR / "README.md").read_text(encoding="utf-8")
TUTORIAL = (SOURCE_DIR / "docs" / "tutorial.md").read_text(encoding="utf-8")


def quoted(text, pattern):
    """The numbers `pattern`'s groups capture in `text` (whitespace in the text may be a line
    break)."""
    found = re.search(pattern.replace(" ", r"\s+"), text)
    assert found, f"the document no longer says: {pattern}"
    return [float(g) for g in found.groups()]


def modes_table(output):
    """{(t, mode): (ω², f or None)} of `deploydyn modes`' table."""
    rows = {}
    for line in output.splitlines():
        cells = line.split()
        if len(cells) >= 4 and re.fullmatch(r"[\d.e+-]+", cells[0]) and cells[1].isdigit():
            rows[float(cells[0]), int(cells[1])] = (float(cells[2]), None if cells[3] == "nan" else float(cells[3]))
    return rows


def test_readme_cold_parallel_linkage_frequencies():
    start_Hz, later_Hz = quoted(README, r"The cold parallel linkage, for instance, drops from ([\d.]+) Hz "
                                        r"at 5° \(t = 0\) to ([\d.]+) Hz at t = 0.5 s and is unstable")
    table = modes_table(run_cli("modes", SOURCE_DIR / "examples" / "paper" / "parallel.yaml", "--count", 1,
                                "--at", 0, 0.5, 1, "--set", "thermal.dT=-170").stdout)
    assert table[0.0, 1][1] == pytest.approx(start_Hz, abs=0.05)
    assert table[0.5, 1][1] == pytest.approx(later_Hz, abs=0.05)
    assert table[1.0, 1][0] < 0                                  # unstable at t = 1 s


def test_tutorial_sampling_line():
    frequency_Hz, rows = quoted(TUTORIAL, r"`sampling    lowest natural frequency at the start ([\d.]+) Hz: "
                                          r"([\d.]+) history rows per period`")
    output = run_cli("check", SOURCE_DIR / "examples" / "tutorial" / "bascule.yaml").stdout
    assert f"lowest natural frequency at the start {frequency_Hz:g} Hz: {rows:g} history rows per period" in output
    alias_Hz, = quoted(TUTORIAL, r"a slow wave of about ([\d.]+) Hz")
    assert abs(50.0 - frequency_Hz) == pytest.approx(alias_Hz, abs=0.5)   # 20 ms rows: 50 Hz sampling


def test_tutorial_drive_ringing_and_peaks(tmp_path):
    """Section 8: the motor torque's ringing and peak with the smooth step and the cycloidal
    ramp, measured as the tutorial's Python block does."""
    quotes = {
        "smooth_step": quoted(TUTORIAL, r"`smooth_step  ringing ±([\d.]+) N·m, peak torque ([\d.]+) N·m`"),
        "cycloidal": quoted(TUTORIAL, r"`cycloidal    ringing ±([\d.]+) N·m, peak torque ([\d.]+) N·m`"),
    }
    profiles = {"smooth_step": [],
                "cycloidal": ["--set", "drivers.motor.profile={type: cycloidal, t0: 0, v0: 0, t1: 6, "
                                       "v1: 1.0471975511965976}"]}
    for run, extra in profiles.items():
        out = tmp_path / run
        run_cli("run", SOURCE_DIR / "examples" / "tutorial" / "bascule.yaml", "--out", out, "--quiet",
                "--set", "analysis.output_interval=0.002", *extra)
        columns, values = read_history(out / "history.csv")
        t = values[:, columns.index("t")]
        torque = values[:, columns.index("torque.motor")]
        first = t <= 1.0
        trend = np.polyval(np.polyfit(t[first], torque[first], 3), t[first])
        ringing = np.abs(torque[first] - trend).max()
        peak = json.loads((out / "summary.json").read_text(encoding="utf-8"))["drivers"]["motor"]["peak"]
        assert ringing == pytest.approx(quotes[run][0], abs=0.5), run
        assert peak == pytest.approx(quotes[run][1], abs=0.5), run


def test_readme_stressed_branch_of_the_cold_parallel_linkage(tmp_path):
    strain, torque = quoted(README, r"−170 °C is pulled straight with (\d+) µε and ([\d.]+) N·m")
    run_cli("window", SOURCE_DIR / "examples" / "paper" / "parallel.yaml", "--dT", "-170:0", "--positions", "1",
            "--deployments", "1", "--out", tmp_path)
    stressed = json.loads((tmp_path / "window.json").read_text(encoding="utf-8"))["deployments"][0]["stressed"]
    assert stressed["peak_mstrain"] * 1e6 == pytest.approx(strain, abs=0.5)
    assert abs(stressed["driver_effort"]) == pytest.approx(torque, abs=0.05)
