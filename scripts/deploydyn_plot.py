#!/usr/bin/python3
"""Plots of deploydyn result folders: strains, forces, coordinates, driver effort over time.

One figure per quantity, PNG and SVG, several runs overlaid (colour by run, line style by
element or node), each run named by its folder or by --label:

    strain.{png,svg}       total and mechanical strain per element (µε)
    force.{png,svg}        axial force per element (N, tension positive)
    bending.{png,svg}      beams: bending moments, torsional moment (N·m) and shear forces (N)
    hinge.{png,svg}        hinges: angle (°) and the spring, damper, friction and latch/stop/stick
                           torques (N·m) that act; latch times marked
    coordinates.{png,svg}  x and y (and z) of the nodes that move (m)
    driver.{png,svg}       driver torque (N·m) or force (N)
    energy.{png,svg}       kinetic and strain energy, external work (J) — with --what energy
    structure.{png,svg}    the structure at the end (and at the time of the largest force), members
                           coloured by force over the model-file shape; 3D projected (--view,
                           --azim, --elev), displacements scaled by --scale
    displacement.{png,svg} |u| = |x − X| of the nodes that move most (m; X: model-file position)

A modal folder gets frequencies and mode_shapes (scripts/modes_figures.py), a continuation
folder path (scripts/path_figures.py) instead.

    scripts/deploydyn_plot.py results/hot results/cold --out plots
    scripts/deploydyn_plot.py results/hot results/cold --label "ΔT = +130" --label "ΔT = −170" \\
        --what strain driver --element 2 --format png
A member panel names at most 8 members in colour (4 line styles with several runs), those of
largest peak |value| of its quantity, and shades the range of the others; a coordinate panel
shows the 12 nodes that move most; notes say so (--element / --node choose others). Legends
sit beside the axes, never over the data; 10⁴ members plot in seconds (bench/plot_bench.py). Each folder's status is printed on stderr (completed, failed, interrupted, running, or killed:
the run died without finishing). Runs that did not complete are drawn as far as they got; a
history whose last row a killed run left incomplete is drawn without that row. The plotting
core is plot_columns of scripts/plot_paper.py, which draws the paper's figures; histories are
read by deploydyn's reader (python/deploydyn/result_folder.py) through it.
"""
import argparse
import csv
import pathlib
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plot_paper import MICRO, Panel, Run, plot_columns, read_folder, result_folder  # noqa: E402
from structure_view import (Structure, add_view_arguments, axis_labels, force_norm, line_collection,  # noqa: E402
                            project, segments, view_angles)
import modes_figures  # noqa: E402
import path_figures  # noqa: E402

QUANTITIES = ("strain", "force", "bending", "hinge", "coordinates", "driver", "energy", "structure",
              "displacement")
DEFAULT_QUANTITIES = ("strain", "force", "bending", "hinge", "coordinates", "driver", "structure")
MOVES_M = 1e-9  # m: a node that moves less is not shown among the coordinates
MAX_LINES = 12  # node lines per panel: beyond, those that move most
MAX_NAMED = 8  # members named in colour in a panel of one run; the rest as a shaded range
MAX_NAMED_PER_RUN = 4  # with several runs (colour tells the run, line style the member)


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


def largest(folders, names, columns_of_name, count=None):
    """The names whose columns (columns_of_name(name)) vary or reach most in any run, largest
    first (the first `count`): peak |value| for forces, range for coordinates."""
    size = {}
    for folder in folders:
        table = read_folder(pathlib.Path(folder))[2] or {}
        for name in names:
            for column, measure in columns_of_name(name):
                values = table.get(column)
                if values is not None and values.size:
                    size[name] = max(size.get(name, 0.0), float(measure(values)))
    return sorted(names, key=lambda n: -size.get(n, 0.0))[:count]


def peak(values):
    return np.max(np.abs(values))


def columns_of(names, prefix, what):
    """(column, legend label) for each name; plot_paper chooses colours and line styles."""
    return [(f"{prefix}{n}", f"{what} {n}") for n in names]


def member_panel(folders, names, prefix, ylabel, chosen=None, scale=1.0, n_runs=1, what="element"):
    """A panel of one quantity over members: the chosen ones, else the few of largest peak
    |value| in colour and with names (as many as have a colour of their own: 10 for one run,
    4 line styles for several) and the rest as one shaded range, so that neither the legend nor
    the artists grow with the model."""
    if chosen:
        return Panel(columns_of(chosen, prefix, what), ylabel, scale)
    shown = min(len(names), MAX_NAMED if n_runs == 1 else MAX_NAMED_PER_RUN)
    ranked = largest(folders, names, lambda n: [(f"{prefix}{n}", peak)]) if len(names) > shown else names
    rest = ranked[shown:]
    note = f"the {shown} of {len(names)} of largest peak |value| (--element chooses)" if rest else ""
    return Panel(columns_of(ranked[:shown], prefix, what), ylabel, scale, note=note,
                 band=[f"{prefix}{n}" for n in rest], band_label=f"the other {len(rest)} (range)")


def nonzero(folders, prefix, names):
    """Whether any run's `prefix<name>` columns leave zero (a damper torque of hinges without
    dampers does not)."""
    for folder in folders:
        table = read_folder(pathlib.Path(folder))[2] or {}
        if any(f"{prefix}{n}" in table and np.any(table[f"{prefix}{n}"]) for n in names):
            return True
    return False


def events(folders, labels, what):
    """{run label: [(time, what)]} of the summaries' events named `what` (e.g. latched)."""
    marks = {}
    for label, folder in zip(labels, folders):
        summary = read_folder(pathlib.Path(folder))[1] or {}
        marks[label] = [(e["time_s"], what) for e in summary.get("events") or []
                        if e.get("what") == what and "time_s" in e]
    return marks


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
        _, summary = result_folder.read_status(pathlib.Path(folder))
        if summary is not None:
            name = summary.get("model") or "(unnamed model)"
            if name not in names:
                names.append(name)
    return names


def driver_names(columns, folders):
    """The drivers, as the summaries name them; without a summary, the torque columns that are
    not a beam's (a beam's torque.<name> goes with its moment.<name>)."""
    drivers, summaries = set(), False
    for folder in folders:
        summary = read_folder(pathlib.Path(folder))[1]
        if summary is not None and "drivers" in summary:
            summaries = True
            drivers |= set(summary.get("drivers") or {})
    if not summaries:
        beams = set(names_after(columns, "moment."))
        drivers = {d for d in names_after(columns, "torque.") if d not in beams}
    return drivers


def figures(columns, folders, what, elements, nodes, labels):
    """{figure name: (panels, ncols)} for the quantities asked for that the history has."""
    # A coordinate driver's force.<name> looks like a member's; a 3D beam's torque.<name> like
    # a driver's.
    drivers = driver_names(columns, folders)
    driver_torques = [d for d in names_after(columns, "torque.") if d in drivers]
    driver_forces = [d for d in names_after(columns, "force.") if d in drivers]
    members = names_after(columns, "strain.") or [n for n in names_after(columns, "force.")
                                                  if n not in drivers]
    beams = names_after(columns, "moment.")
    hinges = names_after(columns, "hinge_angle.")
    runs = len(folders)
    axes = [a for a in "xyz" if any(c.startswith(f"{a}.") for c in columns)]
    out = {}

    def panel(names, prefix, ylabel, scale=1.0, what="element"):
        chosen = [e for e in elements if e in names] if elements else None
        return member_panel(folders, names, prefix, ylabel, chosen, scale, runs, what)
    if "strain" in what and members and any(c.startswith("strain.") for c in columns):
        out["strain"] = ([panel(members, "strain.", "total strain ε (µε)", MICRO),
                          panel(members, "mstrain.", "mechanical strain ε − αΔT (µε)", MICRO)], 1)
    if "force" in what and members:
        out["force"] = ([panel(members, "force.", "axial force (N, tension +)")], 1)
    if "bending" in what and beams:
        panels = [panel(beams, "moment.", "bending moment M_z (N·m)")]
        for prefix, ylabel in (("moment_y.", "bending moment M_y (N·m)"), ("torque.", "torsional moment (N·m)"),
                               ("shear.", "shear force V_y (N)"), ("shear_z.", "shear force V_z (N)")):
            if any(f"{prefix}{b}" in columns for b in beams):
                panels.append(panel(beams, prefix, ylabel))
        out["bending"] = (panels, 1)
    if "hinge" in what and hinges:
        latched = events(folders, labels, "latched")
        panels = [panel(hinges, "hinge_angle.", "hinge angle θ (°)", 180.0 / np.pi, "hinge")]
        for prefix, ylabel in (("spring_torque.", "spring torque (N·m)"),
                               ("damper_torque.", "damper torque (N·m)"),
                               ("friction_torque.", "friction torque (N·m)"),
                               ("lock_torque.", "latch, stop or stick torque (N·m)")):
            if nonzero(folders, prefix, hinges):
                panels.append(panel(hinges, prefix, ylabel, what="hinge"))
        for p in panels:
            p.vlines = latched
        out["hinge"] = (panels, 1)
    if "coordinates" in what and axes:
        shown = nodes or moving_nodes(folders, names_after(columns, f"{axes[0]}."), axes)
        node_note = ""
        if not nodes and len(shown) > MAX_LINES:
            node_note = f"the {MAX_LINES} of {len(shown)} moving nodes that move most (--node chooses)"
            shown = largest(folders, shown, lambda n: [(f"{a}.{n}", np.ptp) for a in axes], MAX_LINES)
        if shown:
            out["coordinates"] = ([Panel(columns_of(shown, f"{a}.", "node"), f"{a} (m)",
                                         note=node_note) for a in axes], 1)
    if "driver" in what:
        panels = []
        if driver_torques:
            panels.append(Panel(columns_of(driver_torques, "torque.", "driver"), "driver torque (N·m)"))
        if driver_forces:
            panels.append(Panel(columns_of(driver_forces, "force.", "driver"), "driver force (N)"))
        if panels:
            out["driver"] = (panels, 1)
    if "energy" in what:
        out["energy"] = ([Panel([("kinetic", "kinetic energy", None, "-"),
                                 ("strain_energy", "strain energy", None, "--"),
                                 ("external_work", "external work", None, ":")], "energy (J)")], 1)
    return out


def model_of(folder, model_file=None):
    """The Structure of a run: --model, else the folder's model.yaml; None (with a message)
    when there is neither."""
    path = pathlib.Path(model_file) if model_file else pathlib.Path(folder) / "model.yaml"
    if not path.exists():
        print(f"plot: {folder}: no model.yaml: no structure or displacement figure (--model gives it)",
              file=sys.stderr)
        return None
    return Structure(path)


def save(fig, out, name, formats):
    out.mkdir(parents=True, exist_ok=True)
    for f in formats:
        with plt.rc_context({"svg.fonttype": "none"}):
            fig.savefig(out / f"{name}.{f}", dpi=110)
        print(f"plot: wrote {out / f'{name}.{f}'}", file=sys.stderr)
    plt.close(fig)


def plot_structure(out, usable, structures, angles, scale, title, formats):
    """Per run, the structure at the end of the run and at the time of its largest |force|,
    coloured by force, over the model-file shape (thin grey)."""
    panels = []
    for label, folder, _ in usable:
        data = read_folder(pathlib.Path(folder))[2]
        if data is None or label not in structures:
            continue
        structure = structures[label]
        forces = structure.forces(data)
        finite = np.where(np.isfinite(forces), np.abs(forces), -1.0)
        at_peak = int(np.unravel_index(np.argmax(finite), finite.shape)[0]) if finite.size else 0
        rows = sorted({at_peak, len(data["t"]) - 1})
        panels += [(label, structure, data, forces, row) for row in rows]
    if not panels:
        return False
    norm = force_norm(np.concatenate([p[3].ravel() for p in panels]))
    fig, axes = plt.subplots(1, len(panels), figsize=(6.0 * len(panels), 5.0), squeeze=False)
    for ax, (label, structure, data, forces, row) in zip(axes[0], panels):
        positions = structure.positions({k: v[row:row + 1] for k, v in data.items()})[0]
        initial = project(structure.initial, *angles)
        ax.add_collection(LineCollection(segments(structure, initial), colors="lightgrey",
                                         linewidths=0.8, linestyles="--", zorder=1))
        lines = line_collection(structure, norm)
        lines.set_segments(segments(structure, project(structure.deformed(positions, scale), *angles)))
        lines.set_array(np.ma.masked_invalid(forces[row]))
        ax.add_collection(lines)
        ax.autoscale()
        ax.set_aspect("equal")
        xlabel, ylabel = axis_labels(*angles)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        scaled = f", displacements ×{scale:g}" if scale != 1 else ""
        ax.set_title(f"{label}: t = {data['t'][row]:.3g} s{scaled}", fontsize=10)
    fig.colorbar(lines, ax=axes[0].tolist(), fraction=0.03, pad=0.02, label="axial force (N), tension +")
    fig.suptitle(title, fontsize=10.5)
    save(fig, out, "structure", formats)
    return True


def plot_displacement(out, runs, structures, nodes, title, formats):
    """|x − X| over time of the chosen nodes, else the MAX_LINES that move most in any run."""
    for run in runs:
        structure = structures.get(run.label)
        if structure is None:
            continue

        def derive(data, structure=structure):
            u = np.linalg.norm(structure.positions(data) - structure.initial, axis=2)
            for i, name in enumerate(structure.node_names):
                data[f"|u|.{name}"] = u[:, i]
        run.derive = derive
    names = nodes
    note = ""
    if not names:
        first = next(iter(structures.values()))
        candidates = first.node_names
        size = {}
        for run in runs:
            data = read_folder(run.folder)[2]
            if data is None or run.label not in structures:
                continue
            u = np.linalg.norm(structures[run.label].positions(data) - structures[run.label].initial, axis=2)
            for i, name in enumerate(structures[run.label].node_names):
                size[name] = max(size.get(name, 0.0), float(u[:, i].max()))
        names = sorted(candidates, key=lambda n: -size.get(n, 0.0))[:MAX_LINES]
        names = [n for n in names if size.get(n, 0.0) > MOVES_M]
        if len(candidates) > MAX_LINES:
            note = f"the {len(names)} nodes that move most (--node chooses)"
    if not names:
        return False
    return plot_columns(out / f"displacement.{formats[0]}", runs,
                        [Panel(columns_of(names, "|u|.", "node"), "|u| = |x − X| (m)", note=note)],
                        title, also=formats[1:]) is not None


def analysis_type(folder):
    """The analysis a result folder holds (summary.json's analysis.type): "modal",
    "continuation", or a time history (anything else, also when the summary is unreadable)."""
    _, summary = result_folder.read_status(pathlib.Path(folder))
    analysis = (summary or {}).get("analysis")
    return analysis.get("type") if isinstance(analysis, dict) else None


def read_table(file):
    """A CSV table of numbers as {column: array}; text cells (path.csv's event) as strings."""
    with open(file, newline="", encoding="utf-8") as stream:
        rows = list(csv.reader(stream))
    if not rows:
        return {}
    header, body = rows[0], [r for r in rows[1:] if len(r) == len(rows[0])]
    table = {}
    for k, name in enumerate(header):
        cells = [r[k] for r in body]
        try:
            table[name] = np.array([float(c) if c else np.nan for c in cells])
        except ValueError:
            table[name] = np.array(cells)
    return table


def folder_table(folder, name):
    """(the folder's table `name` or None with a message, its summary)."""
    _, summary = result_folder.read_status(pathlib.Path(folder))
    file = pathlib.Path(folder) / name
    try:
        return read_table(file), summary
    except OSError as error:
        print(f"plot: {folder}: cannot read {name}: {error}", file=sys.stderr)
        return None, summary


def plot_modal(out, usable, args, title):
    """frequencies and mode_shapes (scripts/modes_figures.py) of modal folders."""
    tables = [(label, folder_table(folder, "modes.csv")[0]) for label, folder in usable]
    tables = [(label, t) for label, t in tables if t and "omega2" in t and len(t["omega2"])]
    written = []
    if not tables:
        return written
    units = modes_figures.driver_units(args.model or pathlib.Path(usable[0][1]) / "model.yaml")
    fig, ax = plt.subplots(figsize=(11.0, 5.0))
    modes_figures.plot_frequencies(ax, tables, units)
    fig.suptitle(title, fontsize=10.5)
    fig.tight_layout()
    save(fig, out, "frequencies", args.format)
    written.append("frequencies")
    label, folder = usable[0]
    structure = model_of(folder, args.model)
    table = dict(tables)[label] if label in dict(tables) else None
    if structure is not None and table is not None:
        angles = view_angles(args.view, args.azim, args.elev, structure.dimension)
        fig = modes_figures.plot_mode_shapes(structure, table, modes_figures.mode_frames(folder, structure), angles,
                                                units)
        if fig is not None:
            fig.suptitle(f"{title}: mode shapes of {label}", fontsize=10.5)
            fig.tight_layout()
            save(fig, out, "mode_shapes", args.format)
            written.append("mode_shapes")
    return written


def plot_continuation(out, usable, args, title):
    """path (scripts/path_figures.py) of continuation folders."""
    runs = [(label, *folder_table(folder, "path.csv")) for label, folder in usable]
    fig = plt.figure(figsize=(11.0, 9.0))
    if not path_figures.plot_path(fig, runs):
        plt.close(fig)
        return []
    fig.suptitle(title, fontsize=10.5)
    fig.tight_layout()
    save(fig, out, "path", args.format)
    return ["path"]


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
    add_view_arguments(parser, "structure: ")
    parser.add_argument("--model", help="the runs' model file, for structure and displacement "
                        "(default: each folder's model.yaml)")
    args = parser.parse_args(argv)

    labels = case_names(args.folders, args.label)
    title = args.title or f"{' / '.join(model_names(args.folders))}: {', '.join(labels)}"
    out = pathlib.Path(args.out)
    kinds = [analysis_type(f) for f in args.folders]
    written = []
    for kind, draw in (("modal", plot_modal), ("continuation", plot_continuation)):
        chosen = [(label, f) for label, f, k in zip(labels, args.folders, kinds) if k == kind]
        if chosen:
            written += draw(out, chosen, args, title)
    histories = [(label, f) for label, f, k in zip(labels, args.folders, kinds)
                 if k not in ("modal", "continuation")]
    if not histories:
        return 0 if written else no_result()
    headers = [read_header(f) for _, f in histories]
    usable = [(label, f, h) for (label, f), h in zip(histories, headers) if h]
    if not usable:
        return 0 if written else no_result()
    runs = [Run(label, pathlib.Path(folder), incomplete_ok=True) for label, folder, _ in usable]
    columns = usable[0][2]
    for name, (panels, ncols) in figures(columns, [u[1] for u in usable], args.what,
                                         args.element, args.node, [u[0] for u in usable]).items():
        done = plot_columns(out / f"{name}.{args.format[0]}", runs, panels, title, ncols=ncols,
                            also=args.format[1:])
        if done:
            written.append(name)
    structures = {label: model_of(folder, args.model) for label, folder, _ in usable}
    structures = {label: s for label, s in structures.items() if s is not None}
    if "displacement" in args.what and structures:
        if plot_displacement(out, runs, structures, args.node, title, args.format):
            written.append("displacement")
    if "structure" in args.what and structures:
        angles = view_angles(args.view, args.azim, args.elev, next(iter(structures.values())).dimension)
        if plot_structure(out, usable, structures, angles, args.scale, title, args.format):
            written.append("structure")
    if not written:
        print("plot: nothing drawn (no matching columns)", file=sys.stderr)
        return 1
    return 0


def no_result():
    print("plot: no result to draw", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
