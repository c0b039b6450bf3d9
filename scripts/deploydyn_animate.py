#!/usr/bin/python3
"""Animation of a deployment from a result folder: bars coloured by axial force, with a colour
bar and the time, into a GIF (Pillow) or, when ffmpeg is installed, an MP4.

    scripts/deploydyn_animate.py RESULT_DIR -o deploy.gif --model examples/paper/general.yaml
    scripts/deploydyn_animate.py results/hot -o hot.gif --model examples/paper/general.yaml \\
        --frames 60 --fps 15 --force-range 5

history.csv gives the node coordinates and bar forces at each output time; which nodes a bar
joins comes from the model file (--model; without it, RESULT_DIR/model.yaml if there is one).
A node without position columns (output.select, a large model's default) stays at its
model-file position; a member without a force column is grey. 3D models are projected: --view
xz|yz|xy|iso (iso by default) or --azim/--elev; --scale K draws the model-file shape plus K ×
the displacement, so that millimetre deflections show. Colours: blue compression, red tension,
symmetric about zero; the colour range is the largest |force| of the run unless --force-range
is given. All members are one line collection and node names are drawn up to 30 nodes, so
10⁴ members animate in seconds (bench/plot_bench.py).

The folder's status is printed on stderr; a run that did not complete (failed, interrupted,
killed, or still going) is animated as far as it got, without the incomplete last row that a
killed run may leave (histories are read by python/deploydyn/result_folder.py).
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402

# deploydyn's reader of result folders: pure Python, so that the script runs without the built
# module.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "python" / "deploydyn"))
import result_folder  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from structure_view import (MAX_LABELLED_NODES, MAX_MARKED_NODES, Structure,  # noqa: E402
                            add_view_arguments, axis_labels, force_norm, line_collection, project, segments,
                            view_angles)


def read_history(result_dir):
    """{column: array} of RESULT_DIR's history, saying the folder's status on stderr; an
    incomplete last row (a killed run's) is left out with a message."""
    status, summary = result_folder.read_status(result_dir)
    note = "" if status == "completed" else f" ({result_folder.status_note(status, summary)})"
    print(f"animate: {result_dir}: status {status}{note}", file=sys.stderr)
    history = result_folder.history_file_of(result_dir, summary)
    if not history.exists():
        raise SystemExit(f"deploydyn_animate: {history}: no such file")
    try:
        table = result_folder.read_history(history, warn=False)
    except (ValueError, OSError) as error:
        raise SystemExit(f"deploydyn_animate: {error}") from None
    if table.n_dropped_rows:
        print(f"animate: {history}: incomplete last row left out: {table.dropped_reason}",
              file=sys.stderr)
    if table.values.shape[0] == 0:
        raise SystemExit(f"deploydyn_animate: {history}: no rows to draw")
    return table.as_dict()


def check_start(structure, positions, model_file, result_dir):
    """The run must start where the model's nodes are (within a tenth of the model's size):
    a model with the same names but another shape would draw wrong bars without this."""
    size = np.ptp(structure.initial, axis=0).max() or 1.0
    distance = np.linalg.norm(positions[0] - structure.initial, axis=1)
    worst = int(np.argmax(distance))
    if distance[worst] > 0.1 * size:
        raise SystemExit(f"deploydyn_animate: node {structure.node_names[worst]} starts at "
                         f"{tuple(positions[0][worst])} in {result_dir}, but {model_file} puts it at "
                         f"{tuple(structure.initial[worst])}: is that the model of this run?")


def frame_rows(n_rows, frames, every):
    """Rows of the history to draw: every `every`-th, or `frames` spread evenly, always the last."""
    if every:
        rows = list(range(0, n_rows, every))
        if rows[-1] != n_rows - 1:
            rows.append(n_rows - 1)
        return rows
    return sorted(set(np.linspace(0, n_rows - 1, min(frames, n_rows)).round().astype(int)))


def animate(result_dir, model_file, out, frames=100, every=None, fps=20, dpi=90,
            force_range=None, title=None, view=None, azim=None, elev=None, scale=1.0):
    """Write the animation; returns the number of frames."""
    structure = Structure(model_file)
    data = read_history(result_dir)
    if not any(f"force.{m}" in data for m in structure.member_names) and \
            not any(f"x.{n}" in data for n in structure.node_names):
        raise SystemExit(f"deploydyn_animate: {result_dir}/history.csv has no column of "
                         f"{model_file}'s nodes or members: is it the model of this run?")
    t = data["t"]
    positions = structure.positions(data)                       # rows × nodes × 3
    check_start(structure, positions, model_file, result_dir)
    forces = structure.forces(data)                             # rows × members
    angles = view_angles(view, azim, elev, structure.dimension)
    rows = frame_rows(len(t), frames, every)
    page = project(structure.deformed(positions[rows], scale), *angles)   # frames × nodes × 2
    norm = force_norm(forces, force_range)

    span = np.ptp(page.reshape(-1, 2), axis=0).max() or 1.0
    low = page.reshape(-1, 2).min(axis=0) - 0.08 * span
    high = page.reshape(-1, 2).max(axis=0) + 0.08 * span
    aspect = (high[1] - low[1]) / (high[0] - low[0])    # figure shaped like the motion
    fig, ax = plt.subplots(figsize=(7.5, float(np.clip(6.0 * aspect + 1.4, 3.2, 8.0))))
    lines = line_collection(structure, norm)
    ax.add_collection(lines)
    n_nodes = len(structure.node_names)
    joints = ax.scatter([], [], s=28 if n_nodes <= 50 else 6, color="black", zorder=3) \
        if n_nodes <= MAX_MARKED_NODES else None
    if structure.supports:
        ground = project(structure.initial[structure.supports], *angles)
        ax.scatter(ground[:, 0], ground[:, 1], marker="^", s=180 if n_nodes <= 50 else 12,
                   color="dimgrey", zorder=1, label="support")
    labels = ([ax.annotate(n, (0, 0), xytext=(6, 6), textcoords="offset points", fontsize=10)
               for n in structure.node_names] if n_nodes <= MAX_LABELLED_NODES else [])
    clock = ax.text(0.02, 0.96, "", transform=ax.transAxes, fontsize=11, va="top",
                    family="monospace")
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal")
    xlabel, ylabel = axis_labels(*angles)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    fig.colorbar(lines, ax=ax, fraction=0.04, pad=0.03, label="axial force (N), tension +")
    scaled = f", displacements ×{scale:g}" if scale != 1 else ""
    ax.set_title((title or pathlib.Path(result_dir).resolve().name) + scaled, fontsize=11)
    fig.tight_layout()

    def draw(k):
        lines.set_segments(segments(structure, page[k]))
        lines.set_array(np.ma.masked_invalid(forces[rows[k]]))
        if joints is not None:
            joints.set_offsets(page[k])
        for label, xy in zip(labels, page[k]):
            label.xy = tuple(xy)
        clock.set_text(f"t = {t[rows[k]]:7.3f} s")
        return [lines, clock, *labels] + ([joints] if joints is not None else [])

    movie = animation.FuncAnimation(fig, draw, frames=range(len(rows)), blit=False)
    out = pathlib.Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    if out.suffix.lower() == ".gif":
        writer = animation.PillowWriter(fps=fps)
    elif animation.writers.is_available("ffmpeg"):
        writer = animation.FFMpegWriter(fps=fps)
    else:
        raise SystemExit(f"deploydyn_animate: {out.suffix} needs ffmpeg, which is not installed; "
                         "write a .gif instead (Pillow)")
    movie.save(out, writer=writer, dpi=dpi)
    plt.close(fig)
    return len(rows)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result_dir", metavar="RESULT_DIR")
    parser.add_argument("-o", "--out", default="deploy.gif", help=".gif (Pillow) or .mp4 (ffmpeg)")
    parser.add_argument("--model", help="the model file of the run (default RESULT_DIR/model.yaml)")
    parser.add_argument("--frames", type=int, default=100, help="frames, spread over the run")
    parser.add_argument("--every", type=int, help="every N-th output row instead of --frames")
    parser.add_argument("--fps", type=float, default=20)
    parser.add_argument("--dpi", type=int, default=90)
    parser.add_argument("--force-range", type=float, metavar="N",
                        help="colours span −N … +N newtons (default: the run's largest |force|)")
    parser.add_argument("--title")
    add_view_arguments(parser)
    args = parser.parse_args(argv)

    model = args.model or pathlib.Path(args.result_dir) / "model.yaml"
    if not pathlib.Path(model).exists():
        parser.error(f"no model file {model}: give the run's model with --model "
                     "(history.csv has no bar connectivity)")
    if args.frames < 1 or (args.every is not None and args.every < 1):
        parser.error("--frames and --every must be at least 1")
    n = animate(args.result_dir, model, args.out, frames=args.frames, every=args.every,
                fps=args.fps, dpi=args.dpi, force_range=args.force_range, title=args.title,
                view=args.view, azim=args.azim, elev=args.elev, scale=args.scale)
    print(f"animate: wrote {args.out} ({n} frames)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
