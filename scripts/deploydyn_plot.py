#!/usr/bin/python3
"""Plots of deploydyn result folders: strains, forces, coordinates, driver effort over time.

One figure per quantity, PNG and SVG, several runs overlaid (colour by run, line style by
element or node), each run named by its folder or by --label:

    strain.{png,svg}       total and mechanical strain per element (µε)
    force.{png,svg}        axial force per element (N, tension positive)
    coordinates.{png,svg}  x and y (and z) of the nodes that move (m)
    driver.{png,svg}       driver torque (N·m) or force (N)
    energy.{png,svg}       kinetic and strain energy, external work (J) — with --what energy

    scripts/deploydyn_plot.py results/hot results/cold --out plots
    scripts/deploydyn_plot.py results/hot results/cold --label "ΔT = +130" --label "ΔT = −170" \\
        --what strain driver --element 2 --format png
Each folder's status is printed on stderr (completed, failed, interrupted, running, or killed:
the run died without finishing). Runs that did not complete are drawn as far as they got; a
history whose last row a killed run left incomplete is drawn without that row. The plotting
core is plot_columns of scripts/plot_paper.py, which draws the paper's figures; histories are
read by deploydyn's reader (python/deploydyn/result_folder.py) through it.
"""
import argparse
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plot_paper import MICRO, Panel, Run, plot_columns, read_folder  # noqa: E402

QUANTITIES = ("strain", "force", "coordinates", "driver", "energy")
DEFAULT_QUANTITIES = ("strain", "force", "coordinates", "driver")
STYLES = ("-", "--", ":", "-.")
MOVES_M = 1e-9  # m: a node that moves less is not shown among the coordinates


def read_header(folder):
    """The history's column names, or None (with a message) when the folder has no readable
    history. Prints the folder's status."""
    _, _, data = read_folder(pathlib.Path(folder))
    return list(data) if data is not None else None


def names_after(columns, prefix):
    """Names of the things `prefix.<name>` columns are about, in column order."""
    return [c[len(prefix):] for c in columns if c.startswith(prefix)]


def moving_nodes(folders, nodes, axes):
    """The nodes that move in some run by more than MOVES_M (supports and fixed nodes left out;
    a support's coordinates wander at round-off level when the solver balances it)."""
    moving = []
    tables = [read_folder(pathlib.Path(folder))[2] for folder in folders]
    for node in nodes:
        for table in tables:
            if any(f"{a}.{node}" in table and table[f"{a}.{node}"].size
                   and np.ptp(table[f"{a}.{node}"]) > MOVES_M for a in axes):
                moving.append(node)
                break
    return moving


def columns_of(names, prefix, what):
    """(column, legend label, colour, line style) for each name: line style by name."""
    return [(f"{prefix}{n}", f"{what} {n}", None, STYLES[i % len(STYLES)])
            for i, n in enumerate(names)]


def case_names(folders, labels):
    """--label values, else the folders' names (with their parent's when names repeat)."""
    if labels:
        if len(labels) != len(folders):
            raise SystemExit(f"deploydyn_plot: {len(labels)} --label for {len(folders)} folders")
        return labels
    names = [pathlib.Path(f).resolve().name for f in folders]
    if len(set(names)) < len(names):
        names = ["/".join(pathlib.Path(f).resolve().parts[-2:]) for f in folders]
    return names


def model_names(folders):
    """The model names the summaries give, in order, once each."""
    names = []
    for folder in folders:
        _, summary, _ = read_folder(pathlib.Path(folder))
        if summary is not None:
            name = summary.get("model") or "(unnamed model)"
            if name not in names:
                names.append(name)
    return names


def figures(columns, folders, what, elements, nodes):
    """{figure name: (panels, ncols)} for the quantities asked for that the history has."""
    elements = elements or names_after(columns, "strain.")
    axes = [a for a in "xyz" if any(c.startswith(f"{a}.") for c in columns)]
    out = {}
    if "strain" in what and elements:
        out["strain"] = ([Panel(columns_of(elements, "strain.", "element"),
                                "total strain ε (µε)", MICRO),
                          Panel(columns_of(elements, "mstrain.", "element"),
                                "mechanical strain ε − αΔT (µε)", MICRO)], 1)
    if "force" in what and elements:
        out["force"] = ([Panel(columns_of(elements, "force.", "element"),
                               "axial force (N, tension +)")], 1)
    if "coordinates" in what:
        shown = nodes or moving_nodes(folders, names_after(columns, f"{axes[0]}."), axes)
        if shown:
            out["coordinates"] = ([Panel(columns_of(shown, f"{a}.", "node"), f"{a} (m)")
                                   for a in axes], 1)
    if "driver" in what:
        torques = names_after(columns, "torque.")
        element_forces = set(elements) | set(names_after(columns, "strain."))
        forces = [d for d in names_after(columns, "force.") if d not in element_forces]
        panels = []
        if torques:
            panels.append(Panel(columns_of(torques, "torque.", "driver"), "driver torque (N·m)"))
        if forces:
            panels.append(Panel(columns_of(forces, "force.", "driver"), "driver force (N)"))
        if panels:
            out["driver"] = (panels, 1)
    if "energy" in what:
        out["energy"] = ([Panel([("kinetic", "kinetic energy", None, "-"),
                                 ("strain_energy", "strain energy", None, "--"),
                                 ("external_work", "external work", None, ":")], "energy (J)")], 1)
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Figures: " + ", ".join(QUANTITIES) + ". See the module docstring for more.")
    parser.add_argument("folders", nargs="+", metavar="RESULT_DIR",
                        help="result folders (history.csv, summary.json)")
    parser.add_argument("--label", action="append", metavar="NAME",
                        help="name of each run in legends, in folder order (default: folder names)")
    parser.add_argument("--out", "-o", default="plots", help="folder for the plots (default: plots)")
    parser.add_argument("--what", nargs="+", choices=QUANTITIES, default=list(DEFAULT_QUANTITIES),
                        help="figures to draw (default: strain force coordinates driver)")
    parser.add_argument("--element", action="append", help="only these elements (repeatable)")
    parser.add_argument("--node", action="append", help="only these nodes (default: those that move)")
    parser.add_argument("--format", nargs="+", default=["png", "svg"], choices=["png", "svg", "pdf"],
                        help="file formats (default: png svg)")
    parser.add_argument("--title", help="figure title (default: the model names and runs)")
    args = parser.parse_args(argv)

    labels = case_names(args.folders, args.label)
    headers = [read_header(f) for f in args.folders]
    usable = [(label, f, h) for label, f, h in zip(labels, args.folders, headers) if h]
    if not usable:
        print("plot: no result to draw", file=sys.stderr)
        return 1
    runs = [Run(label, pathlib.Path(folder), incomplete_ok=True) for label, folder, _ in usable]
    columns = usable[0][2]
    title = args.title or f"{' / '.join(model_names(args.folders))}: {', '.join(labels)}"

    out = pathlib.Path(args.out)
    written = []
    for name, (panels, ncols) in figures(columns, [u[1] for u in usable], args.what,
                                         args.element, args.node).items():
        done = plot_columns(out / f"{name}.{args.format[0]}", runs, panels, title, ncols=ncols,
                            also=args.format[1:])
        if done:
            written.append(name)
    if not written:
        print("plot: nothing drawn (no matching columns)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
