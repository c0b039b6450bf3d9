"""Issue 31, item 1: the report's 3D view and time plots in Debian's headless Chromium, as
test_report.py opens them: members drawn as wide as their section (a beam wider than a cable),
support markers at the supported nodes, the axis triad, a scale bar whose drawn length is its
label's length at the current zoom, a depth cue darkening far members of a 3D model, the stress
colouring, and the events marked on the time plots at their times."""
import base64
import io
import json

import numpy as np
import pytest
import yaml
from PIL import Image

from conftest import GENERAL, SOURCE_DIR, read_history, run_cli
from test_report import browser, canvas_pixels, drawn, open_report, severe_messages  # noqa: F401 (fixture)

REPORT = "window.deploydynReport"

# A mast of steel tube (60 × 3 mm) held by two thin stays (10 mm²), heated: a beam and cables.
GUYED_BEAM = """
name: guyed beam mast
nodes: {foot: [0, 0], top: [0, 3], left: [-2, 0], right: [2, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.06, wall_thickness: 0.003}}
elements:
  mast: {type: beam, nodes: [foot, top], section: tube, material: steel}
  stay_left: {type: cable, nodes: [left, top], area: 1.0e-5, material: steel, pretension: 2000}
  stay_right: {type: cable, nodes: [right, top], area: 1.0e-5, material: steel, pretension: 2000}
supports: [{node: foot}, {node: left}, {node: right}]
thermal: {dT: {type: table, points: [[0, 0], [1, 60]]}}
analysis: {type: static, end: 1, step: 0.1}
"""

# A tetrahedron of bars on three fixed feet, heated from ΔT = 0: stress-free, so every member
# is the same grey, at the first frame.
TETRAHEDRON = """
name: tetrahedron
nodes: {A: [0, 0, 0], B: [2, 0, 0], C: [0, 2, 0], D: [0.5, 0.5, 1.5]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
elements:
  AB: {nodes: [A, B], area: 1.0e-4, material: steel}
  BC: {nodes: [B, C], area: 1.0e-4, material: steel}
  CA: {nodes: [C, A], area: 1.0e-4, material: steel}
  AD: {nodes: [A, D], area: 1.0e-4, material: steel}
  BD: {nodes: [B, D], area: 1.0e-4, material: steel}
  CD: {nodes: [C, D], area: 1.0e-4, material: steel}
supports: [{node: A}, {node: B}, {node: C}]
thermal: {dT: {type: table, points: [[0, 0], [1, 50]]}}
analysis: {type: static, end: 1, step: 0.25}
"""


def report_of(tmp_path_factory, name, model_text):
    folder = tmp_path_factory.mktemp("view") / name
    model = folder.parent / f"{name}.yaml"
    model.write_text(model_text)
    run_cli("run", model, "--out", folder, "--quiet")
    run_cli("report", folder, "--quiet")
    return folder


@pytest.fixture(scope="module")
def guyed_beam(tmp_path_factory):
    return report_of(tmp_path_factory, "guyed_beam", GUYED_BEAM)


def overlay_pixels(browser):
    """The overlay canvas (axis triad, scale bar) as an RGBA array."""
    url = browser.execute_script("return document.getElementById('view-overlay').toDataURL('image/png')")
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGBA")).astype(int)


def member_names(browser):
    return json.loads(browser.execute_script(
        "return JSON.stringify(JSON.parse(document.getElementById('deploydyn-data').textContent).members.names)"))


def width_across(mask, a, b):
    """The drawn width (px) of the segment a–b at its midpoint: drawn pixels counted along its
    normal, both ways from the midpoint, until the background."""
    a, b = np.array(a), np.array(b)
    middle, along = (a + b) / 2, (b - a) / np.linalg.norm(b - a)
    normal = np.array([-along[1], along[0]])
    count = 0
    for sign in (1, -1):
        for step in np.arange(0.0 if sign > 0 else 0.25, 30, 0.25):
            x, y = middle + sign * step * normal
            if not mask[int(round(y)), int(round(x))]:
                break
        count += step
    return count


def test_a_beam_is_drawn_wider_than_a_cable(browser, guyed_beam):
    open_report(browser, guyed_beam / "report.html")
    names = member_names(browser)
    ends = browser.execute_script(f"return {REPORT}.memberEnds()")
    mask = drawn(canvas_pixels(browser))
    beam = width_across(mask, *ends[names.index("mast")])
    cable = width_across(mask, *ends[names.index("stay_left")])
    # The tube's 60 mm against the stay's 3.6 mm: 6 px against the least, 1.5 px.
    assert beam >= 4.5, beam
    assert beam > cable + 2.5, (beam, cable)
    assert severe_messages(browser) == []


def test_supports_are_marked_at_their_nodes_with_a_legend(browser, guyed_beam):
    open_report(browser, guyed_beam / "report.html")
    pixels = canvas_pixels(browser)
    markers = browser.execute_script(f"return {REPORT}.markers()")
    supports = [m for m in markers if m["kind"] == "fixed"]
    assert len(supports) == 3
    for marker in supports:
        x, y = marker["at"]
        i, j = int(round(y)), int(round(x))
        patch = pixels[i - 2:i + 3, j - 2:j + 3].reshape(-1, 3)
        green = (patch[:, 1] > patch[:, 0] + 60) & (patch[:, 1] > patch[:, 2] + 40)
        assert green.sum() >= 10, f"no support marker at node {marker['node']} ({x:.0f}, {y:.0f}): {patch}"
    # ... and not at the free node (top): the marker is the support's, not the members'.
    top = [m for m in markers if m["kind"] == "node"][0]
    x, y = top["at"]
    patch = pixels[int(round(y)) - 2:int(round(y)) + 3, int(round(x)) - 2:int(round(x)) + 3].reshape(-1, 3)
    assert not np.any((patch[:, 1] > patch[:, 0] + 60) & (patch[:, 1] > patch[:, 2] + 40))
    legend = browser.find_element("id", "marker-legend").text
    assert "fixed support" in legend and "node" in legend


def test_the_axis_triad_and_a_scale_bar_that_follows_the_zoom(browser, tmp_path_factory):
    folder = report_of(tmp_path_factory, "tetrahedron", TETRAHEDRON)
    open_report(browser, folder / "report.html")
    axes = browser.execute_script(f"return {REPORT}.axes")
    assert [a["name"] for a in axes] == ["x", "y", "z"]
    pixels = overlay_pixels(browser)
    for axis, channel in zip(axes, (0, 1, 2)):  # x red, y green, z blue strokes to the tips
        x, y = axis["tip"]
        patch = pixels[int(y) - 3:int(y) + 4, int(x) - 3:int(x) + 4].reshape(-1, 4)
        others = [c for c in (0, 1, 2) if c != channel]
        strong = (patch[:, 3] > 128) & (patch[:, channel] > patch[:, others[0]] + 40) & (patch[:, channel] > patch[:, others[1]] + 40)
        assert strong.any(), (axis, patch)

    def check_scale_bar():
        bar = browser.execute_script(f"return {REPORT}.scaleBar")
        length = bar["length_m"]
        mantissa = length / 10 ** np.floor(np.log10(length) + 1e-9)
        assert min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-6, length  # a round length
        # The bar as drawn: the opaque pixels of its row.
        row = pixels_now = overlay_pixels(browser)
        row = pixels_now[int(round(bar["y"])), :, 3] > 128
        columns = np.nonzero(row)[0]
        drawn_px = columns.max() - columns.min()
        # Its label's length at the view's centre, as the camera projects it: from the orbit
        # target, `length` metres along the camera's right direction.
        expected = browser.execute_script(f"""
            const r = {REPORT}, c = r.camera, target = r.controls.target.clone();
            const right = new THREE.Vector3().setFromMatrixColumn(c.matrixWorld, 0);
            const a = target.clone().project(c), b = target.clone().addScaledVector(right, {length}).project(c);
            return (b.x - a.x) / 2 * document.getElementById('view').clientWidth;""")
        assert abs(drawn_px - expected) < 4, (drawn_px, expected, length)
        return length, drawn_px

    before = check_scale_bar()
    # Zoom in 4×: the bar follows (another round length, or the same one drawn longer).
    browser.execute_script(f"""
        const r = {REPORT}, c = r.camera, t = r.controls.target;
        c.position.sub(t).multiplyScalar(0.25).add(t); r.controls.update(); r.render();""")
    after = check_scale_bar()
    assert after[0] < before[0] or after[1] > before[1] + 20, (before, after)


def test_the_depth_cue_darkens_far_members_of_a_3d_model(browser, tmp_path_factory):
    folder = report_of(tmp_path_factory, "tetrahedron_depth", TETRAHEDRON)
    open_report(browser, folder / "report.html")
    browser.execute_script(f"{REPORT}.setFrame(0)")  # stress-free: every member the same grey
    assert browser.execute_script(f"return {REPORT}.depthCue") > 0
    depths = browser.execute_script(f"return {REPORT}.memberDepths()")
    midpoints = browser.execute_script(f"return {REPORT}.memberMidpoints()")
    pixels = canvas_pixels(browser)

    def shade(m):
        x, y = midpoints[m]
        patch = pixels[int(round(y)) - 1:int(round(y)) + 2, int(round(x)) - 1:int(round(x)) + 2].reshape(-1, 3)
        return patch.sum(axis=1).min()  # the line's own colour, not an anti-aliased edge

    near, far = int(np.argmin(depths)), int(np.argmax(depths))
    assert shade(far) < shade(near) - 60, (shade(near), shade(far))
    # A 2D model keeps its flat view.
    flat = report_of(tmp_path_factory, "guyed_flat", GUYED_BEAM)
    open_report(browser, flat / "report.html")
    assert browser.execute_script(f"return {REPORT}.depthCue") == 0
    assert [a["name"] for a in browser.execute_script(f"return {REPORT}.axes")] == ["x", "y"]


def test_stress_colours_the_most_stressed_member_at_its_peak(browser, tmp_path):
    folder = tmp_path / "run"
    run_cli("run", GENERAL, "--out", folder, "--quiet", "--set", "analysis.end=1.5", "--set", "thermal.dT=130")
    run_cli("report", folder, "--quiet")
    open_report(browser, folder / "report.html")
    assert "stress" in browser.execute_script(f"return {REPORT}.colourings")
    # The largest |N/A| over the frames, from history.csv and the areas of model.yaml.
    elements = {str(name): e for name, e in yaml.safe_load((folder / "model.yaml").read_text())["elements"].items()}
    columns, values = read_history(folder / "history.csv")
    names = member_names(browser)
    rows = browser.execute_script(f"return {REPORT}.frameRows")
    stress = np.array([[values[r, columns.index(f"force.{n}")] / float(elements[n]["area"]) for n in names]
                       for r in rows])
    frame, member = np.unravel_index(np.argmax(np.abs(stress)), stress.shape)
    browser.execute_script(f"{REPORT}.colourBy('stress'); {REPORT}.setFrame({frame})")
    assert "(Pa)" in browser.find_element("id", "legend-title").text
    x, y = browser.execute_script(f"return {REPORT}.memberMidpoints()")[member]
    pixels = canvas_pixels(browser)
    patch = pixels[int(round(y)) - 2:int(round(y)) + 3, int(round(x)) - 2:int(round(x)) + 3].reshape(-1, 3)
    colour = patch[np.argmin(patch.sum(axis=1))]
    assert abs(int(colour[0]) - int(colour[2])) > 60, f"member {names[member]} is not red or blue at its peak: {colour}"
    assert severe_messages(browser) == []


def test_events_are_marked_on_the_time_plot_at_their_times(browser, tmp_path):
    """The heated bay's link buckles: the verdict's first failure is a red line on the plot at its
    time, and the summary lists it with that time."""
    folder = tmp_path / "bay"
    run_cli("run", SOURCE_DIR / "examples" / "checks" / "heated_bay.yaml", "--out", folder, "--quiet")
    run_cli("report", folder, "--quiet")
    open_report(browser, folder / "report.html")
    failure = json.loads((folder / "summary.json").read_text())["verdict"]["first_failure"]
    lines = browser.execute_script(f"return {REPORT}.eventLines")
    marked = [line for line in lines if line["kind"] == "failure"]
    assert len(marked) == 1
    # At the failure's time on the plot's axis (its pixel read back through the plot's mapping).
    t_at = browser.execute_script(f"return {REPORT}.toTime({marked[0]['x']})")
    plot_range = browser.execute_script(f"return {REPORT}.plotRange")
    assert abs(t_at - failure["time_s"]) < 1e-9 * max(1.0, abs(plot_range[1]))
    # ... and drawn there: a red column of pixels on the plot canvas.
    url = browser.execute_script("return document.getElementById('plot').toDataURL('image/png')")
    plot = np.asarray(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGBA")).astype(int)
    dpr = browser.execute_script("return window.devicePixelRatio || 1")
    column = plot[:, int(round(marked[0]["x"] * dpr)) - 1:int(round(marked[0]["x"] * dpr)) + 2]
    red = (column[..., 3] > 128) & (column[..., 0] > column[..., 1] + 60) & (column[..., 0] > column[..., 2] + 60)
    assert red.any(axis=1).sum() > 0.5 * plot.shape[0], "no red line at the failure's time"
    summary = browser.find_element("id", "summary").text
    assert "first failure" in summary and f"t = " in summary
    assert severe_messages(browser) == []
