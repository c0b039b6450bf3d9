#!/usr/bin/python3
"""Draw a deployability window (`deploydyn window MODEL --out DIR`) as DIR/window.png.

Driver position (time, s) across, uniform ΔT (°C) up; every sample of the continuation paths
(vertical: ΔT followed at a driver position; horizontal: a quasi-static deployment at one ΔT)
coloured by the lowest stability eigenvalue (N/m, log scale: dark is near instability); each
path's first event (limit point: a jam, bifurcation: a snap, dead centre) marked, where each
deployment stops circled, and the threshold of each side drawn as a line, with its ΔT in the
legend.

    /usr/bin/python3 scripts/deploydyn_window.py DIR [--title TEXT] [--out FILE.png]
"""
import argparse
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as colors  # noqa: E402  (after choosing the backend)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plot_legend import legend_below  # noqa: E402

MARKERS = {"limit_point": ("x", "jam (limit point)"), "bifurcation": ("^", "snap (bifurcation)"),
           "singular_constraints": ("s", "dead centre")}


def draw(folder, title, out):
    folder = pathlib.Path(folder)
    try:
        summary = json.loads((folder / "window.json").read_text(encoding="utf-8"))
        samples = np.loadtxt(folder / "window.csv", delimiter=",", skiprows=1, ndmin=2, usecols=range(6))
        branches = np.loadtxt(folder / "window.csv", delimiter=",", skiprows=1, ndmin=1, usecols=6, dtype=str)
        # The stressed equilibria of jammed levels are drawn with the deployments' stops, not as samples.
        samples = samples[branches != "stressed"] if samples.size else samples
    except (OSError, ValueError) as error:
        print(f"window: {folder}: cannot read the window: {error}", file=sys.stderr)
        return 1
    fig, ax = plt.subplots(figsize=(7.5, 5.6), constrained_layout=True)
    if samples.size:
        t, dT, eigen = samples[:, 0], samples[:, 1], samples[:, 2]
        finite = np.isfinite(eigen) & (eigen > 0)
        if finite.any():
            norm = colors.LogNorm(vmin=max(eigen[finite].min(), eigen[finite].max() * 1e-6), vmax=eigen[finite].max())
            points = ax.scatter(t[finite], dT[finite], c=eigen[finite], norm=norm, s=6, cmap="viridis", lw=0)
            fig.colorbar(points, ax=ax, label="lowest stability eigenvalue (N/m)")
        if (~finite).any():
            ax.scatter(t[~finite], dT[~finite], c="crimson", s=6, lw=0, label="unstable or not computed")
    for side in ("cold", "hot"):
        data = summary[side]
        shown = set()
        for edge in data["edges"]:
            marker, label = MARKERS.get(edge["kind"], ("o", edge["kind"]))
            ax.plot(edge["t"], edge["dT"], marker, color="black", ms=7, zorder=5,
                    label=None if edge["kind"] in shown else label)
            shown.add(edge["kind"])
        threshold = data["threshold"]
        if threshold:
            ax.axhline(threshold["dT"], color="black", ls="--", lw=1,
                       label=f"{side} threshold {'μ' if summary.get('load') == 'model' else 'ΔT'} = "
                             f"{threshold['dT']:+.4g}{'' if summary.get('load') == 'model' else ' °C'} at t = {threshold['t']:g} s")
    stops = [d for d in summary.get("deployments", []) if d["stop"]]
    for i, d in enumerate(stops):
        ax.plot(d["stop"]["t"], d["dT"], "o", mfc="none", color="crimson", ms=9, zorder=6,
                label="deployment stops here" if i == 0 else None)
    stressed = [d for d in summary.get("deployments", []) if d.get("stressed") and not d["stressed"]["failure"]]
    for i, d in enumerate(stressed):
        s = d["stressed"]
        ax.annotate(f"stressed: {s['peak_axial_force']:.3g} N, {s['peak_mstrain'] * 1e6:.0f} µε", (s["t"], d["dT"]),
                    xytext=(8, -3), textcoords="offset points", fontsize=7, color="crimson")
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.set_xlabel("driver position: time t (s)")
    scaled = summary.get("load") == "model"
    ax.set_ylabel("scale μ of the model's thermal load" if scaled else "uniform temperature change ΔT (°C)")
    ax.set_title(title or f"deployability window: {folder.name}")
    legend_below(ax)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"window: {out}", file=sys.stderr)
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--title", default="")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    out = args.out or str(pathlib.Path(args.folder) / "window.png")
    return draw(args.folder, args.title, out)


if __name__ == "__main__":
    sys.exit(main())
