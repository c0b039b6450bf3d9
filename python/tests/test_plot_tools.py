"""scripts/deploydyn_plot.py, scripts/deploydyn_animate.py and scripts/plot_paper.py (make demo's
figures) on short runs of the paper's linkages made by the command line."""
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest
from PIL import Image

from conftest import SOURCE_DIR, run_cli, MISES

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


# --- At scale and in 3D (scripts/structure_view.py) --------------------------------------------

sys.path.insert(0, str(SCRIPTS))
import numpy as np  # noqa: E402
import structure_view  # noqa: E402

PYRAMID = """
nodes: {A: [0, 0, 0], B: [2, 0, 0], C: [2, 2, 0], D: [0, 2, 0], E: [1, 1, 0.2]}
materials: {steel: {E: 2.0e11}}
elements:
  ae: {nodes: [A, E], area: 1.0e-4, material: steel, mass: 1}
  be: {nodes: [B, E], area: 1.0e-4, material: steel, mass: 1}
  ce: {nodes: [C, E], area: 1.0e-4, material: steel, mass: 1}
  de: {nodes: [D, E], area: 1.0e-4, material: steel, mass: 1}
  ab: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A}, {node: B}, {node: C}, {node: D}]
"""


def pyramid(tmp_path):
    model = tmp_path / "pyramid.yaml"
    model.write_text(PYRAMID)
    structure = structure_view.Structure(model)
    # A history whose apex rises from 0.2 m to 1.4 m; the base nodes have no columns (fixed).
    t = np.linspace(0, 1, 5)
    data = {"t": t, "x.E": np.ones(5), "y.E": np.ones(5), "z.E": 0.2 + 1.2 * t, "force.ae": -t}
    return structure, data


def test_a_3d_view_shows_the_apex_rising_that_the_xy_projection_hides(tmp_path):
    structure, data = pyramid(tmp_path)
    positions = structure.positions(data)
    apex = structure.node_names.index("E")
    assert np.array_equal(positions[:, 0, :], np.tile(structure.initial[0], (5, 1)))  # no columns: fixed
    side = structure_view.project(positions, *structure_view.view_angles("xz"))
    top = structure_view.project(positions, *structure_view.view_angles("xy"))
    iso = structure_view.project(positions, *structure_view.view_angles("iso"))
    assert side[-1, apex, 1] - side[0, apex, 1] == pytest.approx(1.2)     # up the page by 1.2 m
    assert np.allclose(top[-1, apex], top[0, apex])                       # seen from above: still
    assert np.linalg.norm(iso[-1, apex] - iso[0, apex]) > 0.9             # the default 3D view
    assert structure_view.axis_labels(*structure_view.view_angles("xz")) == ("x (m)", "z (m)")
    forces = structure.forces(data)
    assert np.isnan(forces[:, 1]).all() and forces[-1, 0] == -1.0         # no column: grey


def test_the_deformation_scale_multiplies_the_displacement(tmp_path):
    structure, data = pyramid(tmp_path)
    positions = structure.positions(data)
    scaled = structure.deformed(positions, 50.0)
    assert np.allclose(scaled - structure.initial, 50.0 * (positions - structure.initial))
    assert np.array_equal(structure.deformed(positions, 0.0)[-1], structure.initial)


def test_ten_thousand_members_are_drawn_as_one_collection(tmp_path, monkeypatch):
    """A generated roof of 10⁴ bars: the structure figure holds two line collections (the
    model-file shape and the members) and no per-member line or label; the time-history panels
    show at most 12 lines with a note."""
    model = tmp_path / "roof.yaml"
    run_cli("generate", "roof", "--units", 3333, "--out", model)
    folder = tmp_path / "run"
    run_cli("run", model, "--out", folder, "--quiet", "--set", "analysis.end=0.02",
            "--set", "analysis.output_interval=0.01")
    import deploydyn_plot
    figures = []
    monkeypatch.setattr(deploydyn_plot.plt, "close", lambda fig=None: figures.append(fig))
    assert deploydyn_plot.main([str(folder), "--out", str(tmp_path / "plots"), "--what", "structure",
                                "force", "--format", "png"]) == 0
    from matplotlib.figure import Figure
    figures = [f for f in figures if isinstance(f, Figure)]
    from matplotlib.collections import LineCollection

    def structure_axes(figure):  # not the colour bar's
        return [ax for ax in figure.axes if ax.collections and ax.get_xlabel() == "x (m)"]
    structure_figure = [f for f in figures if structure_axes(f)][-1]
    axes = structure_axes(structure_figure)
    assert axes
    for ax in axes:
        assert len(ax.collections) == 2 and not ax.lines and len(ax.texts) == 0
        assert all(isinstance(c, LineCollection) for c in ax.collections)
        assert len(ax.collections[1].get_segments()) == 3333 * 3 + 1
    assert (tmp_path / "plots" / "force.png").exists()
    force_panel = "axial force (N, tension +)"
    force_figures = [f for f in figures if any(ax.get_ylabel() == force_panel for ax in f.axes)]
    for ax in force_figures[-1].axes:
        if ax.get_ylabel() == force_panel:
            assert len(ax.lines) == 8                      # the largest, named
            assert len(ax.collections) == 1               # the other 9992 as one shaded range
            legend = ax.get_legend()
            assert "8 of 10000" in legend.get_title().get_text().replace("\n", " ")
            assert "the other 9992 (range)" in [t.get_text() for t in legend.get_texts()]


def figure_axes(figures, ylabel):
    """The axes labelled `ylabel` in the last figure that has them."""
    from matplotlib.figure import Figure
    found = [ax for f in figures if isinstance(f, Figure) for ax in f.axes if ax.get_ylabel() == ylabel]
    assert found, ylabel
    return found[-1]


def test_hinge_and_bending_figures_with_legends_beside_the_data(tmp_path, monkeypatch):
    """Issue 31: the spring-driven mast's hinges (angle, the torques that act, latch times marked)
    and the 3D frame's beams (moments, torsion, shears) get figures of their own, and no legend
    covers the axes it explains."""
    boom, frame = tmp_path / "boom", tmp_path / "frame"
    run_cli("run", SOURCE_DIR / "examples" / "boom" / "boom.yaml", "--out", boom, "--quiet")
    run_cli("run", SOURCE_DIR / "examples" / "beams" / "frame3d.yaml", "--out", frame, "--quiet")
    import json
    import deploydyn_plot
    figures = []
    monkeypatch.setattr(deploydyn_plot.plt, "close", lambda fig=None: figures.append(fig))
    assert deploydyn_plot.main([str(boom), "--out", str(tmp_path / "b"), "--format", "png"]) == 0
    assert (tmp_path / "b" / "hinge.png").exists() and not (tmp_path / "b" / "bending.png").exists()
    angle = figure_axes(figures, "hinge angle θ (°)")
    latches = [e["time_s"] for e in json.loads((boom / "summary.json").read_text())["events"]
               if e["what"] == "latched"]
    assert len(latches) == 4
    marked = [line for line in angle.lines if line.get_linestyle() == ":"]
    assert sorted(line.get_xdata()[0] for line in marked) == pytest.approx(sorted(latches))
    curves = [line for line in angle.lines if line.get_linestyle() != ":"]
    assert len(curves) == 4 and len({line.get_color() for line in curves}) == 4
    assert max(abs(line.get_ydata()).max() for line in curves) == pytest.approx(90.0, abs=1.0)  # degrees
    figure_axes(figures, "spring torque (N·m)")
    figure_axes(figures, "latch, stop or stick torque (N·m)")

    assert deploydyn_plot.main([str(frame), "--out", str(tmp_path / "f"), "--format", "png"]) == 0
    assert (tmp_path / "f" / "bending.png").exists() and not (tmp_path / "f" / "hinge.png").exists()
    torsion = figure_axes(figures, "torsional moment (N·m)")
    assert {line.get_label() for line in torsion.lines} == {"element a1", "element a2", "element c1",
                                                             "element c2"}
    assert not (tmp_path / "f" / "driver.png").exists()   # a 3D beam's torque is not a driver's
    for figure in figures:
        if figure is None or not hasattr(figure, "canvas"):
            continue
        figure.canvas.draw()
        for ax in figure.axes:
            if ax.get_legend() is not None:
                assert ax.get_legend().get_window_extent().x0 >= ax.get_window_extent().x1 - 1


def test_modal_folders_draw_frequencies_and_mode_shapes(tmp_path, monkeypatch):
    """Issue 31: a modal folder drew its folded model twice as 't = 0' and 't = 20 s'. Now its
    frequencies against the driver's position and its mode shapes, read from the VTK frames:
    the stress-free linkage's equilibrium at t = 0 is its model-file shape, and each shape moves
    its largest node by a tenth of the shortest bar (runs/modes_to_folder.hpp)."""
    folder = tmp_path / "modal"
    run_cli("modes", PAPER / "parallel.yaml", "--count", 3, "--at", 0, 1, 2, "--out", folder)
    import deploydyn_plot
    import modes_figures
    figures = []
    monkeypatch.setattr(deploydyn_plot.plt, "close", lambda fig=None: figures.append(fig))
    assert deploydyn_plot.main([str(folder), "--out", str(tmp_path / "plots"), "--format", "png"]) == 0
    assert sorted(p.name for p in (tmp_path / "plots").iterdir()) == ["frequencies.png", "mode_shapes.png"]
    table = deploydyn_plot.read_table(folder / "modes.csv")
    ax = figure_axes(figures, "frequency f (Hz); < 0: −√|ω²|/2π")
    drawn = sorted(y for line in ax.lines if line.get_label().startswith("mode") for y in line.get_ydata())
    assert drawn == pytest.approx(sorted(table["frequency"]))
    shapes = [f for f in figures if f is not None and len([a for a in f.axes if a.get_visible()]) == 9]
    assert shapes                                                   # 3 positions × 3 modes
    structure = structure_view.Structure(folder / "model.yaml")
    frames = modes_figures.mode_frames(folder, structure)
    assert len(frames) == 9
    assert frames[0][0] == pytest.approx(structure.initial, abs=1e-9)
    for k in range(3):                         # one equilibrium per position, whatever the mode
        for mode in (1, 2):
            assert frames[3 * k + mode][0] == pytest.approx(frames[3 * k][0], abs=1e-9)
    lengths = [np.linalg.norm(frames[3 * k][0][structure.members[:, 0]] - frames[3 * k][0][structure.members[:, 1]],
                              axis=1) for k in range(3)]
    assert lengths[2] == pytest.approx(lengths[0], rel=1e-6)   # rigid bars: the linkage moved, not stretched
    assert not np.allclose(frames[6][0], frames[0][0])


def test_continuation_folders_draw_their_path_and_events(tmp_path, monkeypatch):
    """Issue 31: a continuation folder printed "no result to draw" and exited 0. Now its path
    (μ against the displacement), its lowest eigenvalues and the limit points summary.json
    located, at their μ."""
    model = tmp_path / "mises.yaml"
    model.write_text(MISES)
    folder = tmp_path / "path"
    run_cli("run", model, "--quiet", "--out", folder)
    import json
    import deploydyn_plot
    figures = []
    monkeypatch.setattr(deploydyn_plot.plt, "close", lambda fig=None: figures.append(fig))
    assert deploydyn_plot.main([str(folder), "--out", str(tmp_path / "plots"), "--format", "png"]) == 0
    assert (tmp_path / "plots" / "path.png").exists()
    events = json.loads((folder / "summary.json").read_text())["events"]
    limit_points = sorted(e["mu"] for e in events if e["kind"] == "limit_point")
    assert len(limit_points) == 2
    ax = figure_axes(figures, "load factor μ (1)")
    marked = sorted(line.get_ydata()[0] for line in ax.lines if line.get_linestyle() == ":")
    assert marked == pytest.approx(limit_points)
    path = [line for line in ax.lines if line.get_label() == "path"][0]
    assert max(path.get_ydata()) == pytest.approx(1.1)              # to the end of the range
    eigen = figure_axes(figures, "lowest eigenvalues (N/m); < 0: unstable")
    assert min(min(line.get_ydata()) for line in eigen.lines if line.get_label() == "λ1") < 0


def has_unit(label):
    """Whether an axis label names its unit, as "(N·m)" or "(µε)" does."""
    return "(" in label and label.rstrip().endswith(")") or "(" in label and ")" in label.split("(", 1)[1]


def test_every_axis_of_every_figure_names_its_unit(tmp_path, monkeypatch):
    """Issue 31: units on every axis, in the figures of a time history (bars, drivers, energies),
    a hinged boom, a 3D frame of beams (its structure in the iso view too), a modal folder and a
    continuation folder. An axis sharing its x with a labelled one counts as labelled (stacked
    panels label the bottom one)."""
    folders = {"linkage": tmp_path / "linkage", "boom": tmp_path / "boom", "frame": tmp_path / "frame",
               "modal": tmp_path / "modal", "path": tmp_path / "path"}
    run_cli("run", PAPER / "general.yaml", "--out", folders["linkage"], "--quiet", "--set", f"analysis.end={END}")
    run_cli("run", SOURCE_DIR / "examples" / "boom" / "boom.yaml", "--out", folders["boom"], "--quiet")
    run_cli("run", SOURCE_DIR / "examples" / "beams" / "frame3d.yaml", "--out", folders["frame"], "--quiet")
    run_cli("modes", PAPER / "parallel.yaml", "--count", 2, "--at", 0, 1, "--out", folders["modal"])
    (tmp_path / "mises.yaml").write_text(MISES)
    run_cli("run", tmp_path / "mises.yaml", "--quiet", "--out", folders["path"])
    import deploydyn_plot
    from matplotlib.figure import Figure
    close = deploydyn_plot.plt.close
    for name, folder in folders.items():
        for view in ([["--view", "iso"], []] if name == "frame" else [[]]):
            figures = []
            monkeypatch.setattr(deploydyn_plot.plt, "close", lambda fig=None: figures.append(fig))
            assert deploydyn_plot.main([str(folder), "--out", str(tmp_path / f"plots_{name}"), "--format", "png",
                                        *view]) == 0
            for figure in [f for f in figures if isinstance(f, Figure)]:
                drawn = [ax for ax in figure.axes if ax.get_visible() and (ax.lines or ax.collections or ax.images)]
                for ax in drawn:
                    title = figure._suptitle.get_text() if figure._suptitle else ""
                    where = f"{name} {view}: figure {title!r}, axes {ax.get_title()!r}"
                    if not len(ax.get_xticks()) and not len(ax.get_yticks()):
                        continue  # a picture without a scale (the mode shapes' grid)
                    colour_bar = ax.get_label() == "<colorbar>"
                    if colour_bar:
                        label = ax.get_ylabel() or ax.get_xlabel()
                        assert has_unit(label), f"{where}: colour bar {label!r}"
                        continue
                    y = ax.get_ylabel()
                    if figure._supylabel is not None and not has_unit(y):
                        y = figure._supylabel.get_text()
                    assert has_unit(y), f"{where}: y label {y!r}"
                    x_labels = [other.get_xlabel() for other in figure.axes
                                if other is ax or ax.get_shared_x_axes().joined(ax, other)]
                    if figure._supxlabel is not None:
                        x_labels.append(figure._supxlabel.get_text())
                    assert any(has_unit(x) for x in x_labels), f"{where}: x labels {x_labels!r}"
            close("all")
