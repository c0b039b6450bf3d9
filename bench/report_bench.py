#!/usr/bin/python3
"""`deploydyn report` at scale (runs of 0.5 s written every 10 ms: 51 rows): the time to write
the page and its size, and in headless
Chromium (software WebGL: SwiftShader, so a lower bound of what a desktop GPU does) the time to
open it and the time to draw one animation frame, on generated planar roofs of about 10², 10⁴
and 10⁵ members. Medians of --repetitions; prints a Markdown table. With --baseline OTHER_CLI
the page of the same run is also written by that build (an older viewer) and measured alike,
one row each: the frame time before and after a change of the viewer.

Usage: bench/report_bench.py --cli build/release/deploydyn [--units 33 3333 33333]
                             [--baseline /path/to/older/deploydyn]
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-gl=angle",
                     "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1200,1600"):
        options.add_argument(argument)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def measure(cli, units, repetitions, work, driver, baseline=None):
    model = os.path.join(work, f"roof_{units}.yaml")
    subprocess.run([cli, "generate", "roof", "--units", str(units), "--out", model], check=True,
                   capture_output=True)
    out = os.path.join(work, f"run_{units}")
    subprocess.run([cli, "run", model, "--out", out, "--quiet", "--set", "analysis.end=0.5",
                    "--set", "analysis.output_interval=0.01"], check=True)
    rows = []
    for label, page_cli in ([("baseline", baseline)] if baseline else []) + [("this build", cli)]:
        page = os.path.join(out, "report.html")
        rows.append(measure_page(page_cli, out, page, repetitions, driver) | {"units": units, "build": label})
    return rows


def measure_page(cli, out, page, repetitions, driver):
    writes = []
    for _ in range(repetitions):
        start = time.perf_counter()
        subprocess.run([cli, "report", out, "--quiet"], check=True)
        writes.append(time.perf_counter() - start)
    opens, frames = [], []
    for _ in range(repetitions):
        start = time.perf_counter()
        driver.get("file://" + page)
        driver.set_script_timeout(600)
        driver.execute_async_script("""
            const done = arguments[arguments.length - 1];
            (function wait() { if (window.deploydynReport && window.deploydynReport.ready) done(); else setTimeout(wait, 20); })();
        """)
        opens.append(time.perf_counter() - start)
        # Frame k → k + 1, drawn and finished (gl.finish through readPixels of one pixel).
        frames.append(driver.execute_script("""
            const r = window.deploydynReport, n = Math.min(r.frameCount, 21);
            const gl = document.getElementById('view').getContext('webgl');
            const pixel = new Uint8Array(4);
            const start = performance.now();
            for (let k = 0; k < n; ++k) { r.setFrame(k); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); }
            return (performance.now() - start) / n;
        """))
    members = driver.execute_script("return JSON.parse(document.getElementById('deploydyn-data').textContent).members.names.length")
    n_frames = driver.execute_script("return window.deploydynReport.frameCount")
    return {"members": members, "frames": n_frames, "write_s": statistics.median(writes),
            "size_MB": os.path.getsize(page) / 1e6, "open_s": statistics.median(opens),
            "frame_ms": statistics.median(frames)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", required=True)
    parser.add_argument("--units", type=int, nargs="+", default=[33, 3333, 33333])
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--baseline", help="another build's deploydyn: its page of the same run measured too")
    args = parser.parse_args()
    print("| members | build | frames | write the page (s) | page (MB) | open in Chromium (s) | one frame (ms) |")
    print("|---|---|---|---|---|---|---|")
    driver = browser()
    try:
        with tempfile.TemporaryDirectory() as work:
            for units in args.units:
                baseline = os.path.abspath(args.baseline) if args.baseline else None
                for r in measure(os.path.abspath(args.cli), units, args.repetitions, work, driver, baseline):
                    print(f"| {r['members']} | {r['build']} | {r['frames']} | {r['write_s']:.2f} | {r['size_MB']:.1f} | "
                          f"{r['open_s']:.1f} | {r['frame_ms']:.1f} |", flush=True)
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
