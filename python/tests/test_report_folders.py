"""Issue 31: `deploydyn report` on the folders of `deploydyn modes` and of a continuation, in
Debian's headless Chromium as test_report.py does: a modal folder's frequencies are modes.csv's
and its mode is animated (the picture moves through the cycle and differs between modes); a
continuation folder draws its path through every point of path.csv, marks the limit points
summary.json located, and a click on the path draws the structure at that point."""
import csv
import json

import numpy as np
import pytest

from conftest import SOURCE_DIR, run_cli, MISES
from test_report import browser, canvas_pixels, drawn, open_report, severe_messages  # noqa: F401 (fixture)

PAPER = SOURCE_DIR / "examples" / "paper"


def read_csv(file):
    with open(file) as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def modal_folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report") / "modal"
    run_cli("modes", PAPER / "parallel.yaml", "--count", 3, "--at", 0, 1, 2, "--out", folder)
    run_cli("report", folder, "--quiet")
    return folder


@pytest.fixture(scope="module")
def path_folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report") / "path"
    model = folder.parent / "mises.yaml"
    model.write_text(MISES)
    run_cli("run", model, "--quiet", "--out", folder)
    run_cli("report", folder, "--quiet")
    return folder


def test_a_modal_folder_shows_its_frequencies_and_animates_each_mode(browser, modal_folder):
    open_report(browser, modal_folder / "report.html")
    report = "window.deploydynReport"
    assert browser.execute_script(f"return {report}.kind") == "modal"
    rows = read_csv(modal_folder / "modes.csv")
    assert len(rows) == 9                                          # 3 positions × 3 modes
    shown = browser.execute_script(f"return {report}.frequencies")
    assert shown == pytest.approx([float(r["frequency"]) for r in rows], rel=1e-12)
    cells = browser.execute_script(
        "return Array.from(document.querySelectorAll('#modes-table tbody tr')).map(r => r.cells[4].textContent)")
    assert [float(c) for c in cells] == pytest.approx([float(r["frequency"]) for r in rows], rel=1e-5)
    # The mode is animated: through its cycle (phase 0: the equilibrium, a quarter: the
    # largest move, three quarters: the other way) the picture changes; half a cycle later it
    # is the equilibrium again.
    phases = browser.execute_script(f"return {report}.frameCount")
    assert phases >= 8
    pictures = []
    for k in (0, phases // 4, phases // 2, 3 * phases // 4):
        browser.execute_script(f"{report}.setFrame({k})")
        pictures.append(drawn(canvas_pixels(browser)))
    for picture in pictures:
        assert 1e-4 < picture.mean() < 0.2
    assert np.count_nonzero(pictures[0] != pictures[1]) > 50
    assert np.count_nonzero(pictures[1] != pictures[3]) > 50
    assert np.count_nonzero(pictures[0] != pictures[2]) < 0.2 * np.count_nonzero(pictures[0] != pictures[1])
    # Play advances the phase by itself.
    before = browser.execute_script(f"return {report}.framesDrawn")
    browser.find_element("id", "play").click()
    browser.execute_async_script("const done = arguments[arguments.length - 1]; setTimeout(done, 600);")
    browser.find_element("id", "play").click()
    assert browser.execute_script(f"return {report}.framesDrawn") > before + 3
    # Another row draws another mode (the second mode of the last position).
    browser.execute_script(f"{report}.setFrame({phases // 4})")
    first_mode = drawn(canvas_pixels(browser))
    assert browser.execute_script(f"return {report}.selectMode(7)") is True
    assert browser.execute_script(f"return {report}.modeRow") == 7
    assert np.count_nonzero(drawn(canvas_pixels(browser)) != first_mode) > 50
    assert "mode 2 at t = 2 s" in browser.find_element("id", "time").text
    assert severe_messages(browser) == []


def test_a_continuation_folder_draws_its_path_and_the_structure_at_a_chosen_point(browser, path_folder):
    open_report(browser, path_folder / "report.html")
    report = "window.deploydynReport"
    assert browser.execute_script(f"return {report}.kind") == "path"
    rows = read_csv(path_folder / "path.csv")
    points = np.array(browser.execute_script(f"return {report}.pathPoints"))
    assert len(points) == len(rows)
    # Drawn where the points are: a dark pixel of the path's line near each point.
    url = browser.execute_script("return document.getElementById('path-plot').toDataURL('image/png')")
    import base64
    import io
    from PIL import Image
    image = np.asarray(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGB")).astype(int)
    scale = image.shape[1] / browser.execute_script("return document.getElementById('path-plot').clientWidth")
    line = np.all(image < 200, axis=2)
    for x, y in points[::max(1, len(points) // 20)]:
        i, j = int(round(y * scale)), int(round(x * scale))
        assert line[max(i - 3, 0):i + 4, max(j - 3, 0):j + 4].any(), (x, y)
    # The snap-through: the load rises to the first limit point, falls to the second, rises again.
    load = np.array([float(r["load_N"]) for r in rows])
    y = points[:, 1]
    assert np.argmin(y) == np.argmax(load)                         # canvas y grows downwards
    # The limit points summary.json located are marked at their rows.
    events = [e for e in json.loads((path_folder / "summary.json").read_text())["events"] if e["kind"] == "limit_point"]
    marks = browser.execute_script(f"return {report}.eventMarks")
    assert sorted(m["row"] for m in marks) == [i for i, r in enumerate(rows) if r["event"]]
    assert sorted(float(rows[m["row"]]["mu"]) for m in marks if m["kind"] == "limit_point") == pytest.approx(
        sorted(e["mu"] for e in events), rel=1e-9)
    # A click on the path's first point draws the structure there (the initial shape), which
    # differs from its last (C pushed through below A–B).
    browser.execute_script(f"{report}.setFrame({report}.frameCount - 1)")
    last = drawn(canvas_pixels(browser))
    canvas = browser.find_element("id", "path-plot")
    browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)  # the whole plot in view
    from selenium.webdriver.common.action_chains import ActionChains
    size = canvas.size
    x0, y0 = points[0]
    ActionChains(browser).move_to_element_with_offset(canvas, x0 - size["width"] / 2, y0 - size["height"] / 2).click().perform()
    assert browser.execute_script(f"return {report}.pathChosenRow") == 0
    assert browser.execute_script(f"return {report}.frame") == 0
    assert np.count_nonzero(drawn(canvas_pixels(browser)) != last) > 50
    assert severe_messages(browser) == []
