#!/usr/bin/python3
"""Temperatures from the environment (docs/theory.md, "Temperatures from the environment"):
a boom deploying out of eclipse, and a roof module opening at 08:00 and at 14:00 on a summer day.

Runs `deploydyn run examples/thermal/boom_out_of_eclipse.yaml` and `deploydyn study
examples/thermal/roof_summer_day_study.yaml` into results/thermal/, prints per run the members'
temperature range (K), the peak member force and driver torque and the verdict, and draws
results/thermal/thermal_temperatures.png (every member's temperature against time) and
roof_temperatures.png (the opened roof, members coloured by temperature, morning and afternoon).
Exit code 1 when a run failed.
"""
import argparse
import csv
import json
import pathlib
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
from matplotlib import cm, colors  # noqa: E402

from demo_verdict import print_verdicts  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples" / "thermal"


def read_table(file):
    """A CSV of numbers as {column: [values]}."""
    with open(file, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(rows[0])}


def read_summary(folder):
    file = folder / "summary.json"
    return json.loads(file.read_text()) if file.exists() else None


def element_nodes(model_yaml):
    """{element: (node a, node b)} from a run's model.yaml (one flow mapping a line)."""
    out = {}
    for line in model_yaml.read_text().splitlines():
        m = re.match(r"\s+(\S+): \{nodes: \[(\S+), (\S+)\]", line)
        if m:
            out[m.group(1)] = (m.group(2), m.group(3))
    return out


def run(command):
    completed = subprocess.run([str(c) for c in command], capture_output=True, text=True)
    if completed.returncode != 0:
        print(completed.stderr.strip(), file=sys.stderr)
    return completed.returncode == 0


def print_table(cases):
    header = f"{'run':18} {'T min K':>8} {'T max K':>8} {'hottest':>12} {'|N| max N':>10} {'|torque| N·m':>12}"
    print(header)
    print("-" * len(header))
    for name, folder in cases:
        s = read_summary(folder)
        if s is None or "temperatures" not in s:
            print(f"{name:18} no result")
            continue
        t = s["temperatures"]
        forces = [max(abs(q["force"]["min"]), abs(q["force"]["max"])) for q in s["elements"].values() if "force" in q]
        torque = max((d["peak"] for d in s.get("drivers", {}).values()), default=float("nan"))
        print(f"{name:18} {t['min_K']:8.2f} {t['max_K']:8.2f} {t['max_member']:>12} {max(forces):10.1f} {torque:12.1f}")


def plot_temperatures(cases, out):
    fig, axes = plt.subplots(1, len(cases), figsize=(5 * len(cases), 3.6), squeeze=False)
    for ax, (name, folder) in zip(axes[0], cases):
        table = read_table(folder / "temperatures.csv")
        minutes = [t / 60 for t in table["t"]]
        for column, values in table.items():
            if column.startswith("T."):
                ax.plot(minutes, values, lw=0.8)
        ax.set_title(name)
        ax.set_xlabel("t (min)")
        ax.set_ylabel("member temperature (K)")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "thermal_temperatures.png", dpi=120)
    plt.close(fig)


def plot_roof(cases, out):
    """The roof at its last output time, members coloured by temperature on one scale."""
    finals = []
    for name, folder in cases:
        temperatures = read_table(folder / "temperatures.csv")
        history = read_table(folder / "history.csv")
        finals.append((name, element_nodes(folder / "model.yaml"), {k[2:]: v[-1] for k, v in temperatures.items()
                                                                     if k.startswith("T.")}, history))
    low = min(min(t.values()) for _, _, t, _ in finals)
    high = max(max(t.values()) for _, _, t, _ in finals)
    norm = colors.Normalize(low, high)
    fig = plt.figure(figsize=(11, 4.6))
    for k, (name, nodes, temperature, history) in enumerate(finals):
        ax = fig.add_subplot(1, len(finals), k + 1, projection="3d")
        for element, (a, b) in nodes.items():
            if element not in temperature:
                continue
            xs = [history[f"x.{n}"][-1] for n in (a, b)]
            ys = [history[f"y.{n}"][-1] for n in (a, b)]
            zs = [history[f"z.{n}"][-1] for n in (a, b)]
            ax.plot(xs, zs, ys, color=cm.inferno(norm(temperature[element])), lw=2.5)  # y is up
        ax.set_title(f"{name}: opened, t = {history['t'][-1] / 60:.0f} min")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("z (m)")
        ax.set_zlabel("y, up (m)")
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap="inferno"), ax=fig.axes, shrink=0.7, label="temperature (K)")
    fig.savefig(out / "roof_temperatures.png", dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "thermal"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print("running deploydyn run examples/thermal/boom_out_of_eclipse.yaml ...", file=sys.stderr)
    ok = run([args.cli, "run", EXAMPLES / "boom_out_of_eclipse.yaml", "--out", out / "boom", "--quiet"])
    print("running deploydyn study examples/thermal/roof_summer_day_study.yaml ...", file=sys.stderr)
    ok = run([args.cli, "study", EXAMPLES / "roof_summer_day_study.yaml", "--out", out / "roof", "--quiet"]) and ok
    roof = [(f"roof at {hour}", out / "roof" / case) for case, hour in (("morning", "08:00"), ("afternoon", "14:00"))]
    cases = [("boom out of eclipse", out / "boom")] + roof
    print(f"\ntemperatures from the environment: results in {out}/")
    print_table(cases)
    print_verdicts([(name, read_summary(folder)) for name, folder in cases])
    if ok:
        plot_temperatures(cases, out)
        plot_roof(roof, out)
        print(f"wrote {out}/thermal_temperatures.png, roof_temperatures.png", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
