"""Figures of a modal result folder (`deploydyn modes --out`, or analysis.type: modal), for
deploydyn_plot.py:

    frequencies.{png,svg}  each mode's frequency against where the drivers stand (the first
                           driver's position, else t); an unstable equilibrium's mode (ω² < 0)
                           is drawn at −√|ω²|/2π, below the zero line, and marked
    mode_shapes.{png,svg}  the mode shapes over the equilibrium they vibrate about, for up to
                           4 driver positions (rows) and 4 modes (columns)

The table is modes.csv (runs/modes_to_folder.hpp); the shapes are the frames of its ParaView
series vtk/: frame k holds the equilibrium moved along the mode of modes.csv row k until its
largest nodal displacement component is a tenth of the shortest bar (`Points`) and the mode
itself (`velocity_m_s`, M-orthonormal), written as VTK XML binary arrays (base64, a UInt64 byte
count first). The move is that mode scaled to its largest component, the equilibrium the points
less the move.
"""
import base64
import pathlib
import xml.etree.ElementTree as ElementTree

import matplotlib.pyplot as plt
import numpy as np
import yaml
from matplotlib.collections import LineCollection

from structure_view import axis_labels, project, segments
from plot_legend import legend_beside

MAX_SHAPE_ROWS = 4     # driver positions shown in mode_shapes
MAX_SHAPE_MODES = 4    # modes shown per position


def signed_frequency_Hz(omega2):
    """f = √ω² / 2π, negative (−√|ω²| / 2π) where the equilibrium is unstable."""
    omega2 = np.asarray(omega2, dtype=float)
    return np.sign(omega2) * np.sqrt(np.abs(omega2)) / (2.0 * np.pi)


def driver_units(model_file):
    """{driver name: "m" or "rad"} of a model.yaml's drivers: `coordinate` and `length` drivers
    set a length, the others an angle (docs/model-format.md, "drivers"); {} without the file."""
    path = pathlib.Path(model_file)
    if not path.exists():
        return {}
    drivers = (yaml.safe_load(path.read_text(encoding="utf-8")) or {}).get("drivers") or {}
    return {str(name): "m" if (d or {}).get("type") in ("coordinate", "length") else "rad"
            for name, d in drivers.items()}


def position_axis(table, units=None):
    """(x values, x label, unit) of modes.csv rows: the first driver's position (its unit from
    `units`, driver_units), else the time."""
    drivers = [c for c in table if c.startswith("position.")]
    if drivers:
        name = drivers[0][len("position."):]
        unit = (units or {}).get(name, "rad or m")
        return table[drivers[0]], f"position of driver {name} ({unit})", unit
    return table["t"], "time t (s) where the drivers stand", "s"


def plot_frequencies(ax, runs, units=None):
    """runs: [(label, modes.csv as {column: array})]; units: driver_units. One line per run and
    mode."""
    styles = ("-", "--", ":", "-.")
    unstable_marked = False
    for i, (label, table) in enumerate(runs):
        x, xlabel, _ = position_axis(table, units)
        f = signed_frequency_Hz(table["omega2"])
        modes = table["mode"].astype(int)
        for j, mode in enumerate(sorted(set(modes))):
            rows = modes == mode
            colour = f"C{j % 10}" if len(runs) == 1 else f"C{i % 10}"
            name = f"mode {mode}" if len(runs) == 1 else f"{label}: mode {mode}"
            ax.plot(x[rows], f[rows], color=colour, linestyle=styles[0 if len(runs) == 1 else j % 4],
                    marker="o", markersize=3, linewidth=1.4, label=name)
        unstable = f < 0
        if unstable.any():
            ax.plot(x[unstable], f[unstable], "x", color="tab:red", markersize=8,
                    label=None if unstable_marked else "unstable (ω² < 0)")
            unstable_marked = True
    ax.axhline(0.0, color="grey", linewidth=0.8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("frequency f (Hz); < 0: −√|ω²|/2π")
    ax.grid(True, alpha=0.3)
    legend_beside(ax)


def vtu_array(piece, name):
    """A Float64 array of a VTK XML piece (binary: base64 of a UInt64 byte count, then the
    data) as n × components."""
    for array in piece.iter("DataArray"):
        if array.get("Name") == name:
            raw = base64.b64decode("".join(array.text.split()))
            n_bytes = int(np.frombuffer(raw[:8], dtype="<u8")[0])
            values = np.frombuffer(raw[8:8 + n_bytes], dtype="<f8")
            return values.reshape(-1, int(array.get("NumberOfComponents", "1")))
    raise ValueError(f"no array {name}")


def mode_frames(folder, structure):
    """{frame number: (equilibrium positions, the move along the mode)} from vtk/, each n × 3.
    The move is the mode scaled to a tenth of the shortest member of the model file at its
    largest component: exact where the mode has only nodal positions (bars, cables); a beam's
    mode may peak in a frame coordinate, and then the equilibrium drawn is off by a fraction of
    the move."""
    members = structure.members
    lengths = np.linalg.norm(structure.initial[members[:, 0]] - structure.initial[members[:, 1]], axis=1)
    shortest = lengths[lengths > 0].min() if (lengths > 0).any() else 1.0
    frames = {}
    for file in sorted((pathlib.Path(folder) / "vtk").glob("frame_*.vtu")):
        piece = ElementTree.parse(file).getroot().find("UnstructuredGrid/Piece")
        moved = vtu_array(piece, "Points")
        mode = vtu_array(piece, "velocity_m_s")
        largest = np.abs(mode).max()
        move = mode * (0.1 * shortest / largest) if largest > 0 else np.zeros_like(mode)
        frames[int(file.stem.split("_")[-1])] = (moved - move, move)
    return frames


def chosen_rows(values, count):
    """Up to `count` of the distinct `values`, evenly spread, first and last included."""
    distinct = sorted(set(values.tolist()))
    if len(distinct) <= count:
        return distinct
    return [distinct[round(k * (len(distinct) - 1) / (count - 1))] for k in range(count)]


def plot_mode_shapes(structure, table, frames, angles, units=None):
    """A figure of mode shapes: rows the driver positions, columns the modes, all panels at one
    scale. None when the folder has no frames to draw."""
    times = chosen_rows(table["t"], MAX_SHAPE_ROWS)
    modes = sorted(set(table["mode"].astype(int).tolist()))[:MAX_SHAPE_MODES]
    cells = {}
    for t in times:
        for mode in modes:
            rows = np.flatnonzero((table["t"] == t) & (table["mode"].astype(int) == mode))
            if rows.size and int(table["frame"][rows[0]]) in frames:
                equilibrium, move = frames[int(table["frame"][rows[0]])]
                cells[t, mode] = (rows[0], project(equilibrium, *angles), project(equilibrium + move, *angles))
    if not cells:
        return None
    points = np.vstack([np.vstack(c[1:]) for c in cells.values()])
    low, high = points.min(axis=0), points.max(axis=0)
    pad = 0.05 * max(high - low)
    low, high = low - pad, high + pad
    width = 3.2
    height = max(0.8, width * (high[1] - low[1]) / max(high[0] - low[0], 1e-12))
    fig, axes = plt.subplots(len(times), len(modes), squeeze=False,
                             figsize=(width * len(modes) + 1.2, (height + 0.6) * len(times) + 1.2))
    x, _, unit = position_axis(table, units)
    for r, t in enumerate(times):
        for c, mode in enumerate(modes):
            ax = axes[r][c]
            if (t, mode) not in cells:
                ax.set_visible(False)
                continue
            row, equilibrium, moved = cells[t, mode]
            ax.add_collection(LineCollection(segments(structure, equilibrium), colors="lightgrey",
                                             linewidths=1.0, linestyles="--"))
            ax.add_collection(LineCollection(segments(structure, moved), colors="C0", linewidths=1.8))
            ax.set_xlim(low[0], high[0])
            ax.set_ylim(low[1], high[1])
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            f = signed_frequency_Hz(table["omega2"][row])
            ax.set_title(f"mode {mode}: {f:.4g} Hz" + (" (unstable)" if f < 0 else ""), fontsize=9)
            if c == 0:
                ax.set_ylabel(f"t = {t:g} s\nposition {x[row]:.4g} {unit}", fontsize=9)
    xlabel, ylabel = axis_labels(*angles)
    fig.supxlabel(f"projection: {xlabel} across, {ylabel} up, one scale; grey: equilibrium; blue: mode "
                  "(largest move a tenth of the shortest bar)", fontsize=9)
    return fig
