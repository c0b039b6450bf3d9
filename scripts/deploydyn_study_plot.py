#!/usr/bin/python3
"""Figures of a sampled study (docs/model-format.md, "Sampled studies"): how the results of the
drawn cases are distributed.

    scripts/deploydyn_study_plot.py results/roof_mc [--out DIR] [--format png svg]

writes DIR/sampling.{png,svg} (DIR defaults to the study folder) with four panels:
  - the peak axial force of the most loaded member in each drawn case (histogram), with its
    5th, 50th and 95th percentiles and the study's force limit;
  - the peak effort of each driver (histograms);
  - the final shape error from the nominal case (histogram) and its limit;
  - every member's peak force: the band from the 5th to the 95th percentile, the median, the
    largest, the nominal case's, members sorted by median.
Percentiles are statistics.csv's (linear between order statistics, as numpy.percentile).
"""
import argparse
import csv
import pathlib
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plot_legend import legend_beside  # noqa: E402


def read_rows(path):
    with open(path, encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text not in (None, "") else np.nan


def drawn_cases(study_rows, samples_rows):
    """study.csv rows of the drawn cases (samples.csv names them), in order."""
    names = {row["case"] for row in samples_rows}
    return [row for row in study_rows if row["case"] in names]


def histogram(axis, values, label, unit, limit=np.nan, percentiles=None):
    values = np.asarray([v for v in values if np.isfinite(v)])
    if values.size == 0:
        axis.text(0.5, 0.5, "no completed case", ha="center", transform=axis.transAxes)
        return
    axis.hist(values, bins=min(40, max(5, values.size // 10)), color="0.6", edgecolor="0.3", linewidth=0.4)
    for p, style in zip((5, 50, 95), (":", "-", ":")):
        value = percentiles[p] if percentiles else np.percentile(values, p)
        axis.axvline(value, color="C0", linestyle=style, label=f"p{p:02d} = {value:.4g} {unit}")
    if np.isfinite(limit):
        exceed = np.mean(values > limit)
        axis.axvline(limit, color="C3", label=f"limit {limit:.4g} {unit}: P(exceed) = {exceed:.3g}")
    axis.set_xlabel(f"{label} ({unit})")
    axis.set_ylabel("cases")
    legend_beside(axis, fontsize="x-small")


def statistics_by_key(rows):
    return {(row["quantity"], row["item"]): row for row in rows}


def percentiles_of(row):
    return {p: number(row[f"p{p:02d}"]) for p in (5, 50, 95)}


def plot(folder, out, formats):
    folder = pathlib.Path(folder)
    study_rows = read_rows(folder / "study.csv")
    samples_rows = read_rows(folder / "samples.csv")
    statistics = statistics_by_key(read_rows(folder / "statistics.csv"))
    drawn = [row for row in drawn_cases(study_rows, samples_rows) if row["status"] == "completed"]
    nominal = next((row for row in study_rows if row["case"] == "nominal"), None)

    figure, axes = plt.subplots(2, 2, figsize=(15, 8.5))
    n_failed = len(samples_rows) - len(drawn)
    figure.suptitle(f"{folder.name}: {len(samples_rows)} drawn cases, {len(drawn)} completed"
                    + (f", {n_failed} did not deploy" if n_failed else ""))

    most = statistics.get(("peak_force", "*"))
    histogram(axes[0, 0], [number(r["peak_force"]) for r in drawn], "peak |axial force| of the most loaded member",
              "N", number(most["limit"]) if most else np.nan, percentiles_of(most) if most else None)

    drivers = [c for c in study_rows[0] if c.startswith(("peak_torque.", "peak_force."))] if study_rows else []
    for column in drivers:
        values = [number(r[column]) for r in drawn]
        axes[0, 1].hist(values, bins=min(40, max(5, len(values) // 10)), histtype="step", label=column)
    axes[0, 1].set_xlabel("peak |driver effort| (N·m or N)")
    axes[0, 1].set_ylabel("cases")
    if drivers:
        legend_beside(axes[0, 1], fontsize="x-small")

    shape = statistics.get(("shape_error", "*"))
    histogram(axes[1, 0], [number(r["shape_error"]) for r in drawn], "final shape error from nominal", "m",
              number(shape["limit"]) if shape else np.nan, percentiles_of(shape) if shape else None)

    members = [row for (quantity, item), row in statistics.items()
               if quantity == "peak_force" and item != "*" and not item.startswith("driver.")]
    members.sort(key=lambda row: number(row["p50"]))
    x = np.arange(len(members))
    if members:
        axis = axes[1, 1]
        axis.fill_between(x, [number(r["p05"]) for r in members], [number(r["p95"]) for r in members],
                          color="C0", alpha=0.3, step="mid", label="p05–p95")
        axis.plot(x, [number(r["p50"]) for r in members], "C0-", drawstyle="steps-mid", label="median")
        axis.plot(x, [number(r["max"]) for r in members], "C3.", markersize=2, label="largest")
        if np.isfinite(number(members[0]["limit"])):
            axis.axhline(number(members[0]["limit"]), color="C3", linewidth=0.8, label="limit")
        axis.set_xlabel(f"members, by median peak force ({len(members)})")
        axis.set_ylabel("peak |axial force| (N)")
        if len(members) <= 30:
            axis.set_xticks(x, [r["item"] for r in members], rotation=90, fontsize="xx-small")
        legend_beside(axis, fontsize="x-small")
    if nominal and nominal["peak_force"]:
        axes[0, 0].axvline(number(nominal["peak_force"]), color="k", linestyle="--", linewidth=0.8,
                           label="nominal")
        legend_beside(axes[0, 0], fontsize="x-small")
    figure.tight_layout()
    out = pathlib.Path(out or folder)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for extension in formats:
        path = out / f"sampling.{extension}"
        figure.savefig(path, dpi=120)
        written.append(path)
    plt.close(figure)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a sampled study's folder (study.csv, samples.csv, statistics.csv)")
    parser.add_argument("--out", help="folder for the figure (default: the study folder)")
    parser.add_argument("--format", nargs="+", default=["png", "svg"], choices=["png", "svg", "pdf"])
    arguments = parser.parse_args(argv)
    for name in ("study.csv", "samples.csv", "statistics.csv"):
        if not (pathlib.Path(arguments.folder) / name).exists():
            print(f"error: {arguments.folder}/{name} is missing: not a sampled study's folder", file=sys.stderr)
            return 2
    for path in plot(arguments.folder, arguments.out, arguments.format):
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
