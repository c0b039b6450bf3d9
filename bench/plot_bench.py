#!/usr/bin/python3
"""Wall time of scripts/deploydyn_plot.py (its default figures, PNG) and
scripts/deploydyn_animate.py (a 50-frame GIF) on generated planar roofs of about 10², 10⁴ and
10⁵ members, each run for 0.2 s with output every 5 ms (41 rows) and every node's position and
every member's strains and force in history.csv (what the old scripts need). With --old SCRIPTS_DIR (the
scripts of an earlier commit: `git archive COMMIT scripts python/deploydyn | tar -x -C DIR`)
the old scripts are timed on the same folders, each stopped after --timeout seconds. Medians
of --repetitions; prints a Markdown table.

Usage: bench/plot_bench.py --cli build/release/deploydyn [--units 33 3333 33333] [--old DIR/scripts]
"""

import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

SCRIPTS = pathlib.Path(__file__).resolve().parents[1] / "scripts"


def timed(command, timeout):
    start = time.perf_counter()
    try:
        subprocess.run(command, check=True, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return float("inf")
    except subprocess.CalledProcessError as error:
        print(f"plot_bench: {' '.join(command[:2])} failed: {error.stderr.decode()[-300:]}", file=sys.stderr)
        return float("nan")
    return time.perf_counter() - start


def measure(cli, units, scripts, repetitions, timeout, work):
    model = os.path.join(work, f"roof_{units}.yaml")
    folder = os.path.join(work, f"run_{units}")
    if not os.path.exists(folder):
        subprocess.run([cli, "generate", "roof", "--units", str(units), "--out", model], check=True,
                       capture_output=True)
        # Every node and the paper's columns, as the old scripts need them (a large model's
        # default history keeps the moving nodes and the forces only).
        subprocess.run([cli, "run", model, "--out", folder, "--quiet", "--set", "analysis.end=0.2",
                        "--set", "analysis.output_interval=0.005", "--set",
                        "output.select={nodes: all, quantities: [position, strain, mstrain, force, driver, energy]}"],
                       check=True)
    plot, anim = [], []
    for k in range(repetitions):
        plot.append(timed([sys.executable, str(scripts / "deploydyn_plot.py"), folder, "--out",
                           os.path.join(work, f"plots_{k}"), "--format", "png"], timeout))
        anim.append(timed([sys.executable, str(scripts / "deploydyn_animate.py"), folder, "-o",
                           os.path.join(work, f"a_{k}.gif"), "--frames", "50", "--dpi", "60"], timeout))
        if plot[-1] == float("inf") and anim[-1] == float("inf"):
            break  # a second try would time out as well
    return statistics.median(plot), statistics.median(anim)


def cell(seconds, timeout):
    if seconds != seconds:
        return "failed"
    return f"> {timeout:.0f} (stopped)" if seconds == float("inf") else f"{seconds:.1f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", required=True)
    parser.add_argument("--units", type=int, nargs="+", default=[33, 3333, 33333])
    parser.add_argument("--old", type=pathlib.Path, help="scripts folder of an earlier commit")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=300.0)
    args = parser.parse_args()
    print("| members | plot (s) | animate, 50 frames (s) |" + (" old plot (s) | old animate (s) |" if args.old else ""))
    print("|---|---|---|" + ("---|---|" if args.old else ""))
    with tempfile.TemporaryDirectory() as work:
        for units in args.units:
            plot, anim = measure(os.path.abspath(args.cli), units, SCRIPTS, args.repetitions, args.timeout, work)
            row = f"| {3 * units + 1} | {cell(plot, args.timeout)} | {cell(anim, args.timeout)} |"
            if args.old:
                old_plot, old_anim = measure(os.path.abspath(args.cli), units, args.old, 1, args.timeout, work)
                row += f" {cell(old_plot, args.timeout)} | {cell(old_anim, args.timeout)} |"
            print(row, flush=True)


if __name__ == "__main__":
    main()
