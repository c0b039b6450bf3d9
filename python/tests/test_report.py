"""`deploydyn report` in a real browser: Debian's headless Chromium (through python3-selenium and
chromium-driver, which scripts/install-deps.sh installs) opens the page from the file alone, and
the test checks that the 3D canvas draws the structure where its members are, that the time
slider changes the picture, that plots and the envelope table are there, and that no script
error is logged. A missing browser fails the test: `make test` installs it."""
import base64
import io
import json
import os
import shutil

import numpy as np
import pytest
from PIL import Image

from conftest import GENERAL, SOURCE_DIR, run_cli

selenium = pytest.importorskip("selenium", reason="python3-selenium is missing: run scripts/install-deps.sh")
from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402

CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"


@pytest.fixture(scope="module")
def browser():
    assert os.path.exists(CHROMEDRIVER), (
        "chromium-driver is not installed: run scripts/install-deps.sh (make test does)")
    options = webdriver.ChromeOptions()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-gl=angle",
                     "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1200,1600"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    # Under the sanitizer build CTest preloads ASan into python3; not into the browser.
    environment = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER, env=environment), options=options)
    yield driver
    driver.quit()


def open_report(browser, page):
    browser.get(page.as_uri())
    browser.set_script_timeout(60)
    browser.execute_async_script("""
        const done = arguments[arguments.length - 1];
        (function wait() { if (window.deploydynReport && window.deploydynReport.ready) done(); else setTimeout(wait, 50); })();
    """)


def canvas_pixels(browser):
    """The 3D canvas as an RGB array, read from its drawing buffer."""
    url = browser.execute_script("return document.getElementById('view').toDataURL('image/png')")
    image = Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGB")
    return np.asarray(image).astype(int)


def drawn(pixels):
    """Pixels that are not the white background."""
    return np.any(pixels < 235, axis=2)


def blocks(mask, size=4):
    """Whether anything is drawn in each size × size block of pixels."""
    h, w = (mask.shape[0] // size) * size, (mask.shape[1] // size) * size
    return mask[:h, :w].reshape(h // size, size, w // size, size).any(axis=(1, 3))


def severe_messages(browser):
    return [entry for entry in browser.get_log("browser") if entry["level"] == "SEVERE"]


@pytest.fixture(scope="module")
def linkage_report(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report") / "run"
    run_cli("run", GENERAL, "--out", folder, "--quiet", "--set", "analysis.end=1.5", "--set", "thermal.dT=130")
    run_cli("report", folder, "--quiet")
    return folder


def test_the_page_draws_the_linkage_and_the_slider_moves_it(browser, linkage_report):
    page = linkage_report / "report.html"
    assert page.stat().st_size > 500_000  # three.js is in the file: no network at view time
    assert "<script src=" not in page.read_text(encoding="utf-8")
    open_report(browser, page)
    frames = browser.execute_script("return window.deploydynReport.frameCount")
    assert frames > 10

    browser.execute_script("window.deploydynReport.setFrame(0)")
    first = canvas_pixels(browser)
    browser.execute_script(f"window.deploydynReport.setFrame({frames - 1})")
    last = canvas_pixels(browser)
    # The members are drawn: a line's worth of pixels, not a blank canvas and not a filled one.
    for pixels in (first, last):
        share = drawn(pixels).mean()
        assert 1e-4 < share < 0.2, share
    # The crank turned by 1.5 rad/s·1.5 s: the picture changed where the members are.
    assert np.count_nonzero(drawn(first) != drawn(last)) > 100
    # And the members are drawn where they are: a drawn pixel within 2 px of each member's
    # midpoint, as the page's camera projects it.
    midpoints = browser.execute_script("return window.deploydynReport.memberMidpoints()")
    assert len(midpoints) == 3
    for x, y in midpoints:
        i, j = int(round(y)), int(round(x))
        assert drawn(last)[max(i - 2, 0):i + 3, max(j - 2, 0):j + 3].any(), (x, y)
    # ... and not where no member is: the canvas's corners are background.
    assert not drawn(last)[:20, :20].any() and not drawn(last)[-20:, -20:].any()

    # Members are coloured by force: at the time of the largest force (envelopes.csv) the most
    # loaded bar is red (tension) or blue (compression), not grey.
    import csv
    with open(linkage_report / "envelopes.csv") as f:
        forces = [r for r in csv.DictReader(f) if r["quantity"] == "axial_force_N"]
    peak = max(forces, key=lambda r: max(abs(float(r["min"])), abs(float(r["max"]))))
    t_peak = float(peak["t_max_s"] if abs(float(peak["max"])) >= abs(float(peak["min"])) else peak["t_min_s"])
    times = browser.execute_script("return window.deploydynReport.times")
    browser.execute_script(f"window.deploydynReport.setFrame({int(np.argmin(np.abs(np.array(times) - t_peak)))})")
    at_peak = canvas_pixels(browser)
    colours = at_peak[drawn(at_peak)]
    assert np.any(np.abs(colours[:, 0] - colours[:, 2]) > 60), "no red or blue member"

    # The deformation scale: 0 draws the model-file shape whatever the frame.
    # (Only the colours differ then, and with them the anti-aliased edges: a few pixels.)
    # Compared on 4×4-pixel blocks, which an edge's shade does not move between.
    browser.execute_script("window.deploydynReport.setScale(0)")
    browser.execute_script(f"window.deploydynReport.setFrame({frames - 1})")
    undeformed = blocks(drawn(canvas_pixels(browser)))
    browser.execute_script("window.deploydynReport.setFrame(0)")
    changed = np.count_nonzero(blocks(drawn(canvas_pixels(browser))) != undeformed)
    assert changed < 0.05 * np.count_nonzero(blocks(drawn(first)) != blocks(drawn(last))), changed
    browser.execute_script("window.deploydynReport.setScale(1)")

    assert severe_messages(browser) == []


def test_members_with_capacities_are_coloured_by_utilization(browser, tmp_path):
    """The heated bay (examples/checks) buckles its link: at the last frame, coloured by
    utilization, the link is red (over capacity); coloured by force, blue (compression)."""
    folder = tmp_path / "bay"
    run_cli("run", SOURCE_DIR / "examples" / "checks" / "heated_bay.yaml", "--out", folder, "--quiet")
    run_cli("report", folder, "--quiet")
    open_report(browser, folder / "report.html")
    report = "window.deploydynReport"
    frames = browser.execute_script(f"return {report}.frameCount")
    assert browser.execute_script("return document.getElementById('colour-by-label').hidden") is False
    # Utilization first, then force; then stress and the history's other element quantities.
    assert browser.execute_script(f"return {report}.colourings")[:3] == ["utilization", "force", "stress"]
    names = json.loads(browser.execute_script(
        "return JSON.stringify(JSON.parse(document.getElementById('deploydyn-data').textContent).members.names)"))
    link = names.index("link")

    def colour_at_link():
        browser.execute_script(f"{report}.setFrame({frames - 1})")
        x, y = browser.execute_script(f"return {report}.memberMidpoints()")[link]
        pixels = canvas_pixels(browser)
        i, j = int(round(y)), int(round(x))
        patch = pixels[max(i - 2, 0):i + 3, max(j - 2, 0):j + 3].reshape(-1, 3)
        return patch[np.argmin(patch.sum(axis=1))]  # the most saturated pixel: the line, not its edge

    red = colour_at_link()  # a 1-pixel line blends with the white: a hue, not a value
    assert red[0] > red[1] + 60 and abs(int(red[1]) - int(red[2])) < 20, f"not red (over capacity, not orange): {red}"
    assert "utilization" in browser.find_element("id", "legend-title").text
    browser.execute_script(f"{report}.colourBy('force')")
    blue = colour_at_link()
    assert blue[2] > blue[0] + 40, f"not blue (compression): {blue}"
    assert "axial force" in browser.find_element("id", "legend-title").text
    assert severe_messages(browser) == []


def test_the_page_has_the_plots_and_the_envelope_table(browser, linkage_report):
    open_report(browser, linkage_report / "report.html")
    assert browser.execute_script("return window.deploydynReport.plotted") == ["torque.motor"]
    options = browser.execute_script(
        "return Array.from(document.getElementById('plot-columns').options).map(o => o.value)")
    assert {"kinetic", "force.1", "reaction.A.x"} <= set(options)
    assert not any(name.startswith(("x.", "y.")) for name in options)  # positions: the 3D view
    # Zooming in time redraws on the chosen range.
    browser.execute_script("window.deploydynReport.zoom(0.5, 1.0)")
    assert browser.execute_script("return window.deploydynReport.plotRange") == [0.5, 1.0]

    rows = (linkage_report / "envelopes.csv").read_text().strip().splitlines()[1:]
    assert browser.execute_script("return window.deploydynReport.tableRows") == len(rows)
    first_cells = browser.execute_script(
        "return Array.from(document.querySelectorAll('#table tbody tr')).map(r => r.cells[0].textContent + '/' + r.cells[2].textContent)")
    assert {f"{r.split(',')[0]}/{r.split(',')[2]}" for r in rows} == set(first_cells)
    summary = json.loads((linkage_report / "summary.json").read_text())
    assert summary["model"] in browser.find_element("id", "title").text
    assert severe_messages(browser) == []


def test_a_folder_without_results_is_a_clear_error(tmp_path):
    done = run_cli("report", tmp_path, check=False)
    assert done.returncode == 2
    assert "summary.json" in done.stderr and str(tmp_path) in done.stderr
    assert not (tmp_path / "report.html").exists()


PER_AXIS_COLUMN = """
name: column, K per axis
nodes: {A: [0, 0, 0], M: [0.5, 0, 0], B: [1, 0, 0]}
materials: {steel: {E: 2.1e11, density: 7850, yield_strength: 3.55e8}}
elements:
  c1: {type: beam, nodes: [A, M], area: 1.0e-4, inertia_y: 4.0e-8, inertia_z: 1.0e-8, torsion: 1.0e-8, material: steel, orientation: [0, 1, 0]}
  c2: {type: beam, nodes: [M, B], area: 1.0e-4, inertia_y: 4.0e-8, inertia_z: 1.0e-8, torsion: 1.0e-8, material: steel, orientation: [0, 1, 0]}
members:
  column: {elements: [c1, c2], buckling_length_factor: [0.5, 2]}
supports: [{node: A, fix: [x, y, z], axis: [0, 1, 0]}, {node: B, fix: [y, z], axis: [0, 1, 0]}]
loads:
  - {node: B, force: [-1000, 0, 0]}
analysis: {type: static, end: 1, step: 0.5}
"""


def test_the_verdict_lists_checks_and_members_with_their_buckling_length_factors(browser, tmp_path):
    """The report's verdict section: the outcome, each check's largest utilization, and the
    members by utilization with the K each was checked with, K_y and K_z where a 3D beam
    member's differ; a failing run (the heated bay) is marked as failing."""
    model = tmp_path / "column.yaml"
    model.write_text(PER_AXIS_COLUMN)
    folder = tmp_path / "column"
    run_cli("run", model, "--out", folder, "--quiet")
    run_cli("report", folder, "--quiet")
    verdict = json.loads((folder / "summary.json").read_text())["verdict"]
    open_report(browser, folder / "report.html")
    assert browser.find_element("id", "verdict-section").is_displayed()
    outcome = browser.find_element("id", "verdict-outcome")
    assert outcome.text.startswith("deploys: ") and "fails" not in outcome.get_attribute("class")
    checks = browser.execute_script(
        "return Array.from(document.querySelectorAll('#verdict-checks tbody tr')).map(r => r.cells[0].textContent)")
    assert checks == list(verdict["checks"])
    member, kind, governing, utilization, _, factor = browser.execute_script(
        "return window.deploydynReport.verdictMembers")[0]
    assert (member, kind, governing) == ("column", "beam", "buckling")
    assert utilization == verdict["members"]["column"]["utilization"]
    # N = 1 kN against π² E I_z / (K_z L)² with K_z = 2: the weak axis at its given K governs.
    assert utilization == pytest.approx(1000 / (np.pi ** 2 * 2.1e11 * 1e-8 / 4), rel=1e-3)
    assert factor == "K_y = 0.5, K_z = 2 (given)"
    assert severe_messages(browser) == []

    bay = tmp_path / "bay"
    run_cli("run", SOURCE_DIR / "examples" / "checks" / "heated_bay.yaml", "--out", bay, "--quiet")
    run_cli("report", bay, "--quiet")
    open_report(browser, bay / "report.html")
    outcome = browser.find_element("id", "verdict-outcome")
    assert outcome.text.startswith("does not deploy: ") and "fails" in outcome.get_attribute("class")
    over = browser.execute_script("return document.querySelectorAll('#verdict-members td.over').length")
    assert over >= 1
    assert severe_messages(browser) == []
