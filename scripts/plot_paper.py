#!/usr/bin/python3
"""Plots of deploydyn results: any history.csv columns of one or more runs, and the paper's figures.

`plot_columns` draws chosen columns of one or more result folders, one panel per `Panel`; it
is the plotting core of scripts/deploydyn_plot.py as well.
`plot_paper_set` draws, from the six runs of scripts/paper_demo.py (results/paper/<linkage>/
<case>/), the counterparts of Cai et al. (2017) Figs. 3-5 and the driver torque:

    fig3_parallel_normal.png    element strains and nodal coordinates, parallel linkage, ΔT = 0
    fig4_general_normal.png     the same for the general linkage
    fig5a_parallel_element2.png strain of element 2 (total and mechanical), three ΔT cases
    fig5b_general_element2.png  the same for the general linkage
    torque_parallel.png         driver torque, three ΔT cases (not in the paper)
    torque_general.png

A run whose summary.json is missing or not `completed` is skipped with a message, and so is a
figure left without runs.

    /usr/bin/python3 scripts/plot_paper.py                      # the paper's set from results/paper
    /usr/bin/python3 scripts/plot_paper.py columns --run hot=results/paper/general/hot \\
        --run cold=results/paper/general/cold --column mstrain.2 --scale 1e6 \\
        --ylabel "mechanical strain (µε)" --out coupler.png
"""
import argparse
import dataclasses
import functools
import pathlib
import sys
import textwrap
from typing import Callable, Optional

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

ROOT = pathlib.Path(__file__).resolve().parent.parent
# deploydyn's reader of result folders (python/deploydyn/result_folder.py): pure Python, so that
# the scripts run without the built module.
sys.path.insert(0, str(ROOT / "python" / "deploydyn"))
import result_folder  # noqa: E402
from plot_legend import legend_beside  # noqa: E402

ALPHA = 2.0e-5                                                    # 1/°C, paper §3
CASES = (("hot", 130.0), ("normal", 0.0), ("cold", -170.0))      # paper Eq. (22)
CASE_COLOURS = {"hot": "tab:red", "normal": "black", "cold": "tab:blue"}
MICRO = 1e6                                                       # strain -> µε
LINKAGE_TITLES = {
    "parallel": "parallel four-bar linkage (ground A–D 0.357 m, posts from γ = 5°, bar 3 driven about D)",
    "general": "general four-bar linkage (assumed: ground A–D 0.8 m, crank from 60°; bar 1 driven about A)",
}
DRIVER_NOTE = "Eq. 23 ω read as angular velocity (1.46 rad), direction-only driver, ground not expanding"


@dataclasses.dataclass
class Run:
    """One result folder to plot. `derive(data)` may add computed columns to its history;
    with `incomplete_ok` a failed or interrupted run is drawn (as far as it got) instead of
    skipped."""
    label: str
    folder: pathlib.Path
    colour: Optional[str] = None
    linestyle: Optional[str] = None
    derive: Optional[Callable[[dict], None]] = None
    incomplete_ok: bool = False


@dataclasses.dataclass
class Panel:
    """One set of axes: `columns` as names or (name, legend label[, colour, line style]);
    values times `scale`.

    runs: labels of the runs to show here (default all); yscale: "linear" or "symlog" (with
    linthresh); hlines: (value, label) reference lines; note: the legend's title;
    minus: label of a run whose values (same output times) are subtracted from every run's;
    band: more column names, drawn per run as one shaded range (their min to max at each
    time) labelled band_label, so that thousands of members cost one artist;
    vlines: {run label: [(time, label)]}: events marked as dotted lines in the run's colour.
    """
    columns: list
    ylabel: str
    scale: float = 1.0
    runs: Optional[list] = None
    yscale: str = "linear"
    linthresh: float = 1.0
    hlines: list = dataclasses.field(default_factory=list)
    note: str = ""
    minus: Optional[str] = None
    band: list = dataclasses.field(default_factory=list)
    band_label: str = ""
    vlines: dict = dataclasses.field(default_factory=dict)


@functools.lru_cache(maxsize=None)
def read_folder(folder):
    """(status, summary dict or None, {column: array} or None) of a result folder, read once
    per process by deploydyn's reader, which leaves out an incomplete last row (a killed run's).
    Says on stderr, once, the folder's status (e.g. "killed": the run did not finish) and why
    rows or the history are missing; a malformed history gives None, not a traceback."""
    status, summary = result_folder.read_status(folder)
    note = "" if status == "completed" else f" ({result_folder.status_note(status, summary)})"
    print(f"plot: {folder}: status {status}{note}", file=sys.stderr)
    history_file = result_folder.history_file_of(folder, summary)
    try:
        history = result_folder.read_history(history_file, warn=False)
    except FileNotFoundError:
        print(f"plot: {folder}: no {history_file.name}", file=sys.stderr)
        return status, summary, None
    except (ValueError, OSError) as error:
        print(f"plot: {folder}: cannot read the history: {error}", file=sys.stderr)
        return status, summary, None
    if history.n_dropped_rows:
        print(f"plot: {history_file}: incomplete last row left out: {history.dropped_reason}",
              file=sys.stderr)
    return status, summary, history.as_dict()


def load_run(run):
    """history.csv of a completed run as {column: array}, or None (with a message) otherwise;
    with run.incomplete_ok, also of a run that failed, was interrupted, was killed or is still
    going, as far as it got."""
    status, summary, data = read_folder(pathlib.Path(run.folder))
    if summary is None or data is None:
        print(f"plot: skipping {run.folder}: no result (summary.json or history.csv missing "
              "or unreadable)", file=sys.stderr)
        return None
    if status != "completed" and not run.incomplete_ok:
        print(f"plot: skipping {run.folder}: run {status}", file=sys.stderr)
        return None
    data = dict(data)  # derive adds columns to this run's copy, not to the folder's cache
    if run.derive:
        run.derive(data)
    return data


COLUMN_STYLES = ("-", "--", ":", "-.")


def _column_look(j, n_runs):
    """Colour and line style of a panel's j-th column: with one run, ten colours before a
    style repeats; with several, colour tells the run and style the column."""
    if n_runs == 1:
        return f"C{j % 10}", COLUMN_STYLES[(j // 10) % len(COLUMN_STYLES)]
    return None, COLUMN_STYLES[j % len(COLUMN_STYLES)]


def _draw_band(ax, panel, values_of, colour):
    """The range of the panel's band columns in one run as one shaded area."""
    columns = [values_of(name) for name in panel.band]
    columns = [c for c in columns if c is not None]
    if not columns:
        return
    stacked = np.vstack(columns) * panel.scale
    ax.fill_between(values_of("t"), stacked.min(axis=0), stacked.max(axis=0), color=colour or "grey",
                    alpha=0.25, linewidth=0, label=panel.band_label or f"{len(columns)} more (range)")


def _draw_panel(ax, panel, runs, data):
    """Draw one panel: colour by column for one run, else by run (line style by column). The
    legend goes beside the axes, never over the data."""
    shown = [r for r in runs if panel.runs is None or r.label in panel.runs]
    columns = [(c if isinstance(c, tuple) else (c, c)) + (None, None) for c in panel.columns]
    marked = set()
    for i, run in enumerate(shown):
        table = data[run.label]
        if panel.minus and panel.minus not in data:
            print(f"plot: no run {panel.minus} to subtract; panel left out", file=sys.stderr)
            return

        def values_of(name, table=table):
            if name not in table:
                return None
            if panel.minus and name != "t":
                return table[name] - data[panel.minus][name]
            return table[name]
        run_colour = run.colour or f"C{i}"
        for j, (name, label, colour, style, *_) in enumerate(columns):
            values = values_of(name)
            if values is None:
                print(f"plot: {run.folder} has no column {name}", file=sys.stderr)
                continue
            default_colour, default_style = _column_look(j, len(shown))
            if len(shown) == 1:
                colour = colour or default_colour
                style = style or run.linestyle or default_style
                text = label
            else:
                colour = run_colour
                style = run.linestyle or default_style
                text = run.label if len(columns) == 1 else f"{run.label}: {label}"
            ax.plot(table["t"], values * panel.scale, color=colour, linestyle=style, linewidth=1.6, label=text)
        if panel.band:
            _draw_band(ax, panel, values_of, "grey" if len(shown) == 1 else run_colour)
        for time, label in panel.vlines.get(run.label, []):
            ax.axvline(time, color="dimgrey" if len(shown) == 1 else run_colour, linestyle=":", linewidth=1.0,
                       label=None if label in marked else label)
            marked.add(label)
    for value, label in panel.hlines:
        ax.axhline(value, color="grey", linestyle=":", linewidth=1.0)
        below = value > 0        # keep the label off the curve that settles on the line
        ax.annotate(label, (1.0, value), xycoords=("axes fraction", "data"),
                    xytext=(-4, -4 if below else 4), textcoords="offset points", ha="right",
                    va="top" if below else "bottom", fontsize=8, color="dimgrey")
    if panel.yscale == "symlog":
        ax.set_yscale("symlog", linthresh=panel.linthresh)
    ax.set_ylabel(panel.ylabel)
    ax.grid(True, alpha=0.3)
    legend_beside(ax, title=textwrap.fill(panel.note, 32) if panel.note else None, title_fontsize=8)


def plot_columns(out_png, runs, panels, title, ncols=1, xlabel="time t (s)", also=()):
    """Plot history columns of `runs` (list of Run) in `panels` (list of Panel) into out_png.

    Panels are laid out in `ncols` columns; `also` lists more formats to write beside it, e.g.
    ("svg",) (text stays text in SVG). Runs that cannot be loaded are skipped with a message;
    returns the path of out_png, or None when no run could be loaded.
    """
    data = {run.label: load_run(run) for run in runs}
    runs = [run for run in runs if data[run.label] is not None]
    if not runs:
        print(f"plot: no result for {pathlib.Path(out_png).name}, not drawn", file=sys.stderr)
        return None
    nrows = -(-len(panels) // ncols)
    width = 11.0 if ncols == 1 else 9.0 * ncols  # room for the legends beside the axes
    fig, axes = plt.subplots(nrows, ncols, figsize=(width, 3.0 * nrows + 1.0),
                             sharex=True, squeeze=False)
    for ax, panel in zip(axes.flat, panels):
        _draw_panel(ax, panel, runs, data)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel(xlabel)
    fig.suptitle("\n".join(textwrap.fill(line, int(12 * width)) for line in title.splitlines()),
                 fontsize=10.5)
    fig.tight_layout()
    pathlib.Path(out_png).parent.mkdir(parents=True, exist_ok=True)
    for out in [pathlib.Path(out_png)] + [pathlib.Path(out_png).with_suffix(f".{f}") for f in also]:
        with plt.rc_context({"svg.fonttype": "none"}):
            fig.savefig(out, dpi=110)
        print(f"plot: wrote {out}", file=sys.stderr)
    plt.close(fig)
    return pathlib.Path(out_png)


def case_runs(results, linkage, cases=CASES):
    """The three temperature cases of a linkage as Runs, coloured hot red, normal black, cold blue."""
    return [Run(f"{case} (ΔT = {dT:+g} °C)", pathlib.Path(results) / linkage / case,
                colour=CASE_COLOURS[case]) for case, dT in cases]


def thermal_lines(cases=CASES):
    """Reference lines at the free thermal strain αΔT (µε) of each case."""
    return [(ALPHA * dT * MICRO, f"αΔT = {ALPHA * dT * MICRO:+.0f} µε") for _, dT in cases if dT]


def plot_paper_set(results):
    """Draw the paper's Figs. 3-5 and the driver torques from results/<linkage>/<case>/."""
    results = pathlib.Path(results)
    strains = [(f"strain.{e}", f"element {e}", f"C{i}", style)
               for i, (e, style) in enumerate(zip("123", ("-", "--", ":")))]
    coordinates = [("x.B", "x of B", "C0", "-"), ("y.B", "y of B", "C0", "--"),
                   ("x.C", "x of C", "C3", "-"), ("y.C", "y of C", "C3", "--")]
    written = []
    for linkage, fig in (("parallel", "fig3"), ("general", "fig4")):
        normal = [Run("normal", results / linkage / "normal")]
        panels = [Panel(strains, "total strain ε (µε)", MICRO),
                  Panel(coordinates, "nodal coordinate (m)",
                        note="y of B = y of C (a parallelogram)" if linkage == "parallel" else "")]
        if linkage == "general":       # bars 1 and 3 are 60-150 times stiffer than the coupler
            panels.insert(1, Panel(strains[0::2], "total strain ε (µε)", MICRO,
                                   note="elements 1 and 3 only (zoom)"))
        written.append(plot_columns(
            results / f"{fig}_{linkage}_normal.png", normal, panels,
            f"Fig. {fig[-1]} counterpart: {LINKAGE_TITLES[linkage]}\nΔT = 0; {DRIVER_NOTE}"))

    for linkage, fig in (("parallel", "fig5a"), ("general", "fig5b")):
        runs = case_runs(results, linkage)
        panels = [Panel(["strain.2"], "element 2: total strain ε (µε)", MICRO,
                        hlines=thermal_lines()),
                  Panel(["mstrain.2"], "element 2: mechanical strain ε − αΔT (µε)", MICRO)]
        torque = [Panel(["torque.motor"], "driver torque (N·m)")]
        hot, normal, cold = (r.label for r in runs)
        if linkage == "general":       # the three cases overlap: show what ΔT changes
            panels.append(Panel(["mstrain.2"], "element 2: ε_m − ε_m(normal) (µε)", MICRO,
                                runs=[hot, cold], minus=normal,
                                note="difference from the normal case"))
        if linkage == "parallel":      # the jammed cold case is 10⁴ times larger: zoom on the others
            warm = [r.label for r in runs if not r.label.startswith("cold")]
            panels.append(Panel(["mstrain.2"], "element 2: mechanical strain (µε)", MICRO,
                                runs=warm, note="hot and normal only (zoom)"))
            torque.append(Panel(["torque.motor"], "driver torque (N·m)", runs=warm,
                                note="hot and normal only (zoom)"))
        written.append(plot_columns(
            results / f"{fig}_{linkage}_element2.png", runs, panels,
            f"Fig. {fig[-2:]} counterpart: element 2 (B–C), {LINKAGE_TITLES[linkage]}\n{DRIVER_NOTE}"))
        written.append(plot_columns(
            results / f"torque_{linkage}.png", runs, torque,
            f"Driver torque (not in the paper): {LINKAGE_TITLES[linkage]}\n{DRIVER_NOTE}"))
    return [w for w in written if w]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command")
    paper = sub.add_parser("paper", help="the paper's figures (default)")
    paper.add_argument("--results", default=str(ROOT / "results" / "paper"))
    columns = sub.add_parser("columns", help="chosen columns of chosen runs, one panel")
    columns.add_argument("--run", action="append", required=True, metavar="LABEL=FOLDER")
    columns.add_argument("--column", action="append", required=True)
    columns.add_argument("--scale", type=float, default=1.0)
    columns.add_argument("--ylabel", default="value")
    columns.add_argument("--title", default="")
    columns.add_argument("--out", required=True)
    args = parser.parse_args()
    if args.command == "columns":
        runs = [Run(*spec.split("=", 1)) for spec in args.run]
        for run in runs:
            run.folder = pathlib.Path(run.folder)
        done = plot_columns(args.out, runs, [Panel(args.column, args.ylabel, args.scale)], args.title)
        return 0 if done else 1
    plot_paper_set(getattr(args, "results", ROOT / "results" / "paper"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
