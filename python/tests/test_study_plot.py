"""A sampled study's statistics against numpy, and its figure (scripts/deploydyn_study_plot.py).

statistics.csv's row for the most loaded member must equal numpy's mean, standard deviation and
percentiles of study.csv's peak_force over the drawn cases that completed; the figure is drawn
and not blank."""
import csv
import subprocess

import numpy as np
import pytest
from PIL import Image

from conftest import SOURCE_DIR, run_cli

SCRIPT = SOURCE_DIR / "scripts" / "deploydyn_study_plot.py"


@pytest.fixture(scope="module")
def sampled_study(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sampled")
    roof = folder / "roof.yaml"
    run_cli("generate", "roof", "--units", 2, "--trusses", 2, "--out", roof)
    roof.write_text(roof.read_text().replace("  end: 5\n", "  end: 0.05\n"))
    study = folder / "study.yaml"
    study.write_text("model: roof.yaml\n"
                     "sampling:\n"
                     "  method: monte_carlo\n"
                     "  cases: 40\n"
                     "  seed: 2\n"
                     "  length_error: [{elements: '*', normal: 3e-5}]\n"
                     "  temperature: {dT: [100, 160], scatter: 5}\n"
                     "  limits: {force: 300, shape_error: 1e-4}\n")
    run_cli("study", study, "--out", folder / "out", "--quiet")
    return folder / "out"


def rows(path):
    with open(path, encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def test_statistics_equal_numpys(sampled_study):
    drawn = {row["case"] for row in rows(sampled_study / "samples.csv")}
    assert len(drawn) == 40
    peaks = np.array([float(r["peak_force"]) for r in rows(sampled_study / "study.csv")
                      if r["case"] in drawn and r["status"] == "completed"])
    assert peaks.size >= 30
    row = next(r for r in rows(sampled_study / "statistics.csv") if r["quantity"] == "peak_force" and r["item"] == "*")
    assert int(row["n"]) == peaks.size
    assert float(row["mean"]) == pytest.approx(peaks.mean(), rel=1e-13)
    assert float(row["std"]) == pytest.approx(peaks.std(ddof=1), rel=1e-12)
    for p in (5, 50, 95, 99):
        assert float(row[f"p{p:02d}"]) == pytest.approx(np.percentile(peaks, p), rel=1e-13), p
    assert float(row["p_exceed"]) == pytest.approx(np.mean(peaks > 300.0), abs=1e-15)
    assert 0.0 < float(row["p_exceed"]) < 1.0, "the limit should split the sample, else the check is empty"


def test_figure_is_drawn(sampled_study, tmp_path):
    done = subprocess.run(["/usr/bin/python3", str(SCRIPT), str(sampled_study), "--out", str(tmp_path),
                           "--format", "png"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    image = np.asarray(Image.open(tmp_path / "sampling.png").convert("L"))
    assert image.shape[0] > 500
    assert (image < 250).mean() > 0.02, "the figure is blank"


def test_not_a_sampled_study_is_refused(tmp_path):
    done = subprocess.run(["/usr/bin/python3", str(SCRIPT), str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 2
    assert "not a sampled study" in done.stderr


def test_no_legend_covers_a_histogram(sampled_study, tmp_path, monkeypatch):
    """Issue 31: the four panels' legends sit beside their axes, over none of them."""
    import sys
    sys.path.insert(0, str(SCRIPT.parent))
    import deploydyn_study_plot
    from plot_legend import legends_over_axes
    figures = []
    monkeypatch.setattr(deploydyn_study_plot.plt, "close", lambda fig=None: figures.append(fig))
    deploydyn_study_plot.plot(sampled_study, tmp_path, ["png"])
    drawn = [f for f in figures if f is not None and hasattr(f, "axes") and len(f.axes) == 4]
    assert len(drawn) == 1
    assert sum(ax.get_legend() is not None for ax in drawn[0].axes) >= 3
    assert legends_over_axes(drawn[0]) == []
