"""The pictures of `deploydyn report` in docs/images/ (docs/report.md, README), made by the
program itself: a generated 3D roof of 4 trusses of 8 units is run for its 5 s, reported, and
opened in Debian's headless Chromium (python3-selenium and chromium-driver, which
scripts/install-deps.sh installs), as python/tests/test_report.py opens reports. Written:

    report_roof3d.png  the summary and the 3D view at t = 4.5 s, coloured by axial force
    report_plots.png   the time histories (a driver's torque, the energies) and the envelope table

    /usr/bin/python3 scripts/report_screenshots.py [--cli build/release/deploydyn] [--out docs/images]

The PNGs are reduced to a 256-colour palette, which keeps each near 100 kB.
"""
import argparse
import io
import pathlib
import shutil
import subprocess
import sys
import tempfile

from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]
WIDTH = 1200  # px of the browser window: the pictures' width


def run(cli, *args):
    done = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"report_screenshots: deploydyn {' '.join(map(str, args))}: {done.stderr}")


def browser(height):
    options = webdriver.ChromeOptions()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-gl=angle",
                     "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--hide-scrollbars",
                     f"--window-size={WIDTH},{height}"):
        options.add_argument(argument)
    chromedriver = shutil.which("chromedriver") or "/usr/bin/chromedriver"
    return webdriver.Chrome(service=Service(chromedriver), options=options)


def open_report(driver, page):
    driver.get(page.as_uri())
    driver.set_script_timeout(60)
    driver.execute_async_script("""
        const done = arguments[arguments.length - 1];
        (function wait() { if (window.deploydynReport && window.deploydynReport.ready) done(); else setTimeout(wait, 50); })();
    """)


def save(png_bytes, out):
    """`png_bytes` as a 256-colour PNG at `out`."""
    image = Image.open(io.BytesIO(png_bytes)).convert("RGB")
    image.quantize(colors=256, method=Image.Quantize.MEDIANCUT).save(out, optimize=True)
    print(f"report_screenshots: wrote {out} ({out.stat().st_size // 1024} kB)")


def clip(driver, first, last):
    """A screenshot of the page from the top of element `first` to the bottom of `last`."""
    driver.execute_script(f"document.getElementById('{first}').scrollIntoView()")
    top = driver.execute_script(f"return document.getElementById('{first}').getBoundingClientRect().top")
    bottom = driver.execute_script(f"return document.getElementById('{last}').getBoundingClientRect().bottom")
    image = Image.open(io.BytesIO(driver.get_screenshot_as_png()))
    scale = image.width / WIDTH
    out = io.BytesIO()
    box = (0, max(0, int((top - 8) * scale)), image.width, min(image.height, int((bottom + 8) * scale)))
    image.crop(box).save(out, format="PNG")
    return out.getvalue()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=SOURCE_DIR / "build" / "release" / "deploydyn", type=pathlib.Path)
    parser.add_argument("--out", default=SOURCE_DIR / "docs" / "images", type=pathlib.Path)
    args = parser.parse_args(argv)
    # A folder of a fixed name: the summary shows it.
    scratch = pathlib.Path(tempfile.gettempdir()) / "deploydyn_report_pictures"
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir()
    model, folder = scratch / "roof3d.yaml", scratch / "roof3d"
    run(args.cli, "generate", "roof", "--units", 8, "--trusses", 4, "--out", model)
    run(args.cli, "run", model, "--out", folder, "--quiet")
    run(args.cli, "report", folder, "--quiet")
    driver = browser(2400)  # tall enough for each picture in one screenshot
    try:
        open_report(driver, folder / "report.html")
        # The frame nearest t = 4.5 s, the roof nearly upright.
        driver.execute_script("""
            const r = window.deploydynReport;
            let best = 0;
            r.times.forEach((t, k) => { if (Math.abs(t - 4.5) < Math.abs(r.times[best] - 4.5)) best = k; });
            r.colourBy('force'); r.setFrame(best);""")
        save(clip(driver, "summary-section", "view-section"), args.out / "report_roof3d.png")
        # The largest driver torque (N·m) with the energies (J): the y axis names both units.
        driver.execute_script("""
            const select = document.getElementById('plot-columns');
            const chosen = new Set(['torque.motor8', 'kinetic', 'strain_energy']);
            for (const o of select.options) o.selected = chosen.has(o.value);
            select.dispatchEvent(new Event('change'));""")
        driver.execute_script("document.getElementById('table-wrap').style.maxHeight = '260px'")
        save(clip(driver, "plot-section", "table-section"), args.out / "report_plots.png")
    finally:
        driver.quit()
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
