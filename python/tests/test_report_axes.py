"""Issue 31, item 1: every axis of every plot in the report names a unit, and its ticks are round
numbers — k·step with step ∈ {1, 2, 5}·10ⁿ — that span the data. Read from the page in Debian's
headless Chromium (test_report.py's browser), the units checked against the history columns'
families as docs/model-format.md gives them, the data range against history.csv and path.csv."""
import csv
import math

import numpy as np
import pytest

from conftest import GENERAL, MISES, read_history, run_cli
from test_report import browser, open_report, severe_messages  # noqa: F401 (fixture)
from test_report_view import GUYED_BEAM

REPORT = "window.deploydynReport"

# The SI unit of a history.csv column, by family (docs/model-format.md, "select"; the elements'
# quantity tables), written here apart from the program's.
UNIT_OF_PREFIX = {
    "force": "N", "shear": "N", "shear_z": "N", "pin_force": "N",
    "torque": "N·m", "moment": "N·m", "moment_y": "N·m", "hinge_torque": "N·m", "spring_torque": "N·m",
    "damper_torque": "N·m", "friction_torque": "N·m", "lock_torque": "N·m",
    "strain": "1", "mstrain": "1", "slack": "1", "hinge_state": "1",
    "stress": "Pa", "rest": "m", "length": "m", "ux": "m", "uy": "m", "uz": "m",
    "hinge_angle": "rad", "dissipated": "J",
}
ENERGIES = {"kinetic", "strain_energy", "external_work", "dissipated"}


def expected_unit(column):
    if column in ENERGIES:
        return "J"
    if column.startswith("reaction."):
        return "N·m" if column.rsplit(".", 1)[1].startswith("r") else "N"
    return UNIT_OF_PREFIX[column.split(".", 1)[0]]


def assert_round_ticks(axis, lo, hi, covers):
    """Ticks k·step, step ∈ {1, 2, 5}·10ⁿ, evenly spaced, printed as the round numbers they are;
    `covers`: the first and last ticks bound [lo, hi]; else they lie inside it, less than a step
    from its ends."""
    step, ticks, labels = axis["step"], axis["ticks"], axis["labels"]
    assert step > 0
    mantissa = step / 10 ** math.floor(math.log10(step) + 1e-12)
    assert min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-9, f"step {step} is not 1, 2 or 5 × 10ⁿ"
    assert 3 <= len(ticks) <= 12, ticks
    for tick, label in zip(ticks, labels):
        k = tick / step
        assert abs(k - round(k)) < 1e-9, f"tick {tick} is not a multiple of {step}"
        assert abs(float(label) - tick) <= 1e-9 * max(abs(tick), step), (label, tick)
        # A round number prints with no more digits than its step needs (not 7457.52).
        assert len(label.replace("-", "").replace(".", "").strip("0")) <= 4 or "e" in label, label
    assert np.allclose(np.diff(ticks), step, rtol=1e-9, atol=0)
    span = 1e-9 * max(abs(lo), abs(hi), step)
    if covers:
        assert ticks[0] <= lo + span and ticks[-1] >= hi - span, (ticks, lo, hi)
    else:
        assert lo - span <= ticks[0] < lo + step and hi - step < ticks[-1] <= hi + span, (ticks, lo, hi)


def assert_names_its_unit(axis, unit):
    assert axis["unit"] == unit, (axis["label"], unit)
    assert axis["label"].endswith(f"({unit})"), axis["label"]


def choose(browser, columns):
    browser.execute_script(f"""
        const chosen = new Set(arguments[0]), select = document.getElementById('plot-columns');
        for (const o of select.options) o.selected = chosen.has(o.value);
        select.dispatchEvent(new Event('change'));""", columns)
    return browser.execute_script(f"return {REPORT}.plotAxes.plot")


def run_report(tmp_path, model, *settings):
    folder = tmp_path / "run"
    run_cli("run", model, "--out", folder, "--quiet", *settings)
    run_cli("report", folder, "--quiet")
    return folder


@pytest.mark.parametrize("case", ["linkage", "guyed_beam"])
def test_every_time_plot_column_has_its_unit_and_round_ticks(browser, tmp_path, case):
    if case == "linkage":  # bars, a driver, reactions, energies
        folder = run_report(tmp_path, GENERAL, "--set", "analysis.end=1.5", "--set", "thermal.dT=130")
    else:  # a beam and cables: moments, shear, slack
        model = tmp_path / "guyed.yaml"
        model.write_text(GUYED_BEAM)
        folder = run_report(tmp_path, model)
    open_report(browser, folder / "report.html")
    offered = browser.execute_script(
        "return Array.from(document.getElementById('plot-columns').options).map(o => o.value)")
    columns, values = read_history(folder / "history.csv")
    t = values[:, 0]
    families = {}
    for name in offered:
        families.setdefault(name.split(".", 1)[0], []).append(name)
    assert len(families) >= 4, families.keys()
    # Each family alone (one unit), then all together (their units listed).
    for chosen in [*families.values(), offered]:
        axes = choose(browser, chosen)
        units = list(dict.fromkeys(expected_unit(name) for name in chosen))
        assert_names_its_unit(axes["y"], ", ".join(units))
        assert_names_its_unit(axes["x"], "s")
        data = values[:, [columns.index(name) for name in chosen]]
        lo, hi = data.min(), data.max()
        if hi == lo:
            lo, hi = lo - 1, hi + 1
        assert_round_ticks(axes["y"], lo, hi, covers=True)
        assert_round_ticks(axes["x"], t[0], t[-1], covers=False)
    # The legend and the column list say each column's unit.
    texts = browser.execute_script(
        "return Array.from(document.getElementById('plot-columns').options).map(o => o.textContent)")
    assert texts == [f"{name} ({expected_unit(name)})" for name in offered]
    # A zoom to an odd range keeps round ticks inside it.
    browser.execute_script(f"{REPORT}.zoom(0.1234, 0.9876)")
    assert_round_ticks(browser.execute_script(f"return {REPORT}.plotAxes.plot")["x"], 0.1234, 0.9876, covers=False)
    assert severe_messages(browser) == []


def test_the_path_plots_have_units_and_round_ticks(browser, tmp_path):
    model = tmp_path / "mises.yaml"
    model.write_text(MISES)
    folder = run_report(tmp_path, model)
    open_report(browser, folder / "report.html")
    axes = browser.execute_script(f"return {REPORT}.plotAxes")
    with open(folder / "path.csv") as f:
        rows = list(csv.DictReader(f))
    load = np.array([float(r["load_N"]) for r in rows])
    eigen = np.array([[float(r[c]) for c in r if c.startswith("eigenvalue")] for r in rows])
    path, eigen_plot = axes["path-plot"], axes["eigen-plot"]
    assert_names_its_unit(path["x"], "m")
    assert_names_its_unit(path["y"], "N")
    assert_names_its_unit(eigen_plot["x"], "N")
    assert_names_its_unit(eigen_plot["y"], "N/m")
    assert_round_ticks(path["y"], load.min(), load.max(), covers=True)
    assert_round_ticks(eigen_plot["x"], load.min(), load.max(), covers=True)
    assert_round_ticks(eigen_plot["y"], min(eigen.min(), 0.0), max(eigen.max(), 0.0), covers=True)
    assert severe_messages(browser) == []
