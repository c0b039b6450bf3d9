#!/usr/bin/python3
"""How much peaks taken at output times only (what summary.json and study.csv held before
envelopes were tracked at every step) under-report the true peaks, on generated roofs.

For each roof it runs `deploydyn run` with the roof's own output interval (5 ms up to 1000
bars, 50 ms above), then compares, per member, the largest |force| among history.csv's rows (the
old, sampled peak) with envelopes.csv's (every step), and the same for the driver torque. It
also reports history.csv's size and column count (the output selection's default) and the
VTK size of one frame. Prints a Markdown table; numbers are single runs (peaks do not vary
between runs; the sizes neither).

Usage: bench/sampled_peaks.py --cli build/release/deploydyn [--units 100 1000 10000]
"""

import argparse
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np


def read_history(path):
    with open(path) as f:
        header = f.readline().rstrip("\n").split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return header, data


def envelope_peaks(path):
    peaks = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["quantity"] in ("axial_force_N", "torque_Nm"):
                peaks[row["item"]] = max(abs(float(row["min"])), abs(float(row["max"])))
    return peaks


def measure(cli, units, trusses, end, work):
    model = os.path.join(work, f"roof_{units}x{trusses}.yaml")
    subprocess.run([cli, "generate", "roof", "--units", str(units), "--trusses", str(trusses), "--out", model],
                   check=True)
    out = os.path.join(work, f"run_{units}x{trusses}")
    subprocess.run([cli, "run", model, "--out", out, "--quiet", "--set", f"analysis.end={end}",
                    "--set", "output.vtk=true"], check=True)
    header, data = read_history(os.path.join(out, "history.csv"))
    peaks = envelope_peaks(os.path.join(out, "envelopes.csv"))
    errors = []
    torque_error = None
    for c, name in enumerate(header):
        if name.startswith("force.") or name.startswith("torque."):
            item = name.split(".", 1)[1]
            true_peak = peaks.get(item)
            if not true_peak:
                continue
            sampled = np.max(np.abs(data[:, c]))
            error = (true_peak - sampled) / true_peak
            if name.startswith("torque."):
                torque_error = error
            else:
                errors.append(error)
    errors = np.array(errors)
    # The member of highest peak: what a designer sizes for.
    chords = {k: v for k, v in peaks.items() if not k.startswith("motor")}
    top = max(chords, key=chords.get)
    top_c = header.index("force." + top)
    top_error = (chords[top] - np.max(np.abs(data[:, top_c]))) / chords[top]
    vtk_dir = os.path.join(out, "vtk")
    frames = [f for f in os.listdir(vtk_dir) if f.endswith(".vtu")]
    return {
        "units": units, "trusses": trusses, "rows": data.shape[0], "columns": len(header),
        "history_MB": os.path.getsize(os.path.join(out, "history.csv")) / 1e6,
        "vtk_frame_MB": os.path.getsize(os.path.join(vtk_dir, frames[0])) / 1e6,
        "median_error": float(np.median(errors)), "max_error": float(np.max(errors)),
        "top_member": top, "top_error": float(top_error), "torque_error": torque_error,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", required=True)
    parser.add_argument("--units", type=int, nargs="+", default=[100, 1000])
    parser.add_argument("--end", type=float, default=1.0, help="simulated time (s) of each run")
    args = parser.parse_args()
    print("| units | history rows | columns | history.csv (MB) | one VTK frame (MB) | sampled peak under-reports, median over members | worst member | highest-force member | driver torque |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for units in args.units:
            r = measure(args.cli, units, 1, args.end, work)
            print(f"| {r['units']} | {r['rows']} | {r['columns']} | {r['history_MB']:.2f} | {r['vtk_frame_MB']:.3f} | "
                  f"{100 * r['median_error']:.2f} % | {100 * r['max_error']:.1f} % | {r['top_member']}: "
                  f"{100 * r['top_error']:.2f} % | {100 * (r['torque_error'] or 0):.2f} % |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
