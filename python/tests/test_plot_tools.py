"""scripts/deploydyn_plot.py, scripts/deploydyn_animate.py and scripts/plot_paper.py (make demo's
figures) on short runs of the paper's linkages made by the command line."""
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest
from PIL import Image

from conftest import SOURCE_DIR, run_cli

SCRIPTS = SOURCE_DIR / "scripts"
PAPER = SOURCE_DIR / "examples" / "paper"
PNG = b"\x89PNG\r\n\x1a\n"
CASES = {"hot": 130, "normal": 0, "cold": -170}
END = 0.3  # s


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """results/<linkage>/<case>/ as paper_demo.py lays them out, from 0.3 s runs."""
    root = tmp_path_factory.mktemp("results")
    for linkage in ("general", "parallel"):
        for case, dT in CASES.items():
            run_cli("run", PAPER / f"{linkage}.yaml", "--quiet", "--out", root / linkage / case,
                    "--set", f"thermal.dT={dT}", "--set", f"analysis.end={END}")
    return root


def script(name, *args, expect=0):
    done = subprocess.run([sys.executable, str(SCRIPTS / name), *map(str, args)],
                          capture_output=True, text=True)
    assert done.returncode == expect, f"{name}: {done.stdout}\n{done.stderr}"
    return done


def test_plot_overlays_cases_in_png_and_svg(results, tmp_path):
    general = results / "general"
    script("deploydyn_plot.py", general / "hot", general / "cold", "--label", "ΔT = +130 °C",
           "--label", "ΔT = −170 °C", "--out", tmp_path)
    for figure in ("strain", "force", "coordinates", "driver"):
        png = tmp_path / f"{figure}.png"
        assert png.read_bytes()[:8] == PNG, figure
        assert Image.open(png).size[0] > 500
        svg = tmp_path / f"{figure}.svg"
        root = ElementTree.parse(svg).getroot()               # well-formed XML
        assert root.tag.endswith("svg")
        text = svg.read_text(encoding="utf-8")
        assert "ΔT = +130 °C" in text and "ΔT = −170 °C" in text, figure   # the case names
    strain = (tmp_path / "strain.svg").read_text(encoding="utf-8")
    assert "µε" in strain and "element 2" in strain                        # unit and legend
    assert "N·m" in (tmp_path / "driver.svg").read_text(encoding="utf-8")
    coordinates = (tmp_path / "coordinates.svg").read_text(encoding="utf-8")
    assert "node B" in coordinates and "node A" not in coordinates         # supports left out


def test_plot_choices_and_default_names(results, tmp_path):
    general = results / "general"
    script("deploydyn_plot.py", general / "hot", general / "normal", "--what", "energy", "driver",
           "--format", "png", "--out", tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["driver.png", "energy.png"]
    done = script("deploydyn_plot.py", tmp_path / "nothing_here", "--out", tmp_path / "x",
                  expect=1)
    assert "no history.csv" in done.stderr


def test_animation_gif(results, tmp_path):
    out = tmp_path / "deploy.gif"
    done = script("deploydyn_animate.py", results / "general" / "hot", "-o", out,
                  "--model", PAPER / "general.yaml", "--frames", "12", "--dpi", "50")
    assert "12 frames" in done.stderr
    assert out.read_bytes()[:6] == b"GIF89a"
    with Image.open(out) as gif:
        assert gif.n_frames == 12
        first = gif.convert("RGB").tobytes()
        gif.seek(11)
        assert gif.convert("RGB").tobytes() != first                       # the linkage moves
    every = tmp_path / "every.gif"
    script("deploydyn_animate.py", results / "general" / "hot", "-o", every,
           "--model", PAPER / "general.yaml", "--every", "20", "--dpi", "40")
    with Image.open(every) as gif:                     # 61 rows: 0, 20, 40, 60
        assert gif.n_frames == 4


def test_animation_needs_the_model(results, tmp_path):
    """The run's own model.yaml is used by default; without it, --model is asked for."""
    script("deploydyn_animate.py", results / "general" / "hot", "-o", tmp_path / "own.gif", "--frames", "2")
    assert (tmp_path / "own.gif").read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    bare = tmp_path / "bare"
    bare.mkdir()
    for name in ("history.csv", "summary.json"):
        (bare / name).write_bytes((results / "general" / "hot" / name).read_bytes())
    done = script("deploydyn_animate.py", bare, "-o", tmp_path / "a.gif", expect=2)
    assert "--model" in done.stderr
    done = script("deploydyn_animate.py", results / "general" / "hot", "-o", tmp_path / "a.gif",
                  "--model", PAPER / "parallel.yaml", "--frames", "2", expect=1)
    assert "is that the model of this run?" in done.stderr


def test_paper_figures_still_draw(results):
    """make demo's figures: scripts/plot_paper.py on paper_demo.py's layout."""
    script("plot_paper.py", "paper", "--results", results)
    for name in ("fig3_parallel_normal", "fig4_general_normal", "fig5a_parallel_element2",
                 "fig5b_general_element2", "torque_parallel", "torque_general"):
        assert (results / f"{name}.png").read_bytes()[:8] == PNG, name
