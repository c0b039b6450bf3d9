#!/usr/bin/python3
"""Animation of a deployment from a result folder: bars coloured by axial force, with a colour
bar and the time, into a GIF (Pillow) or, when ffmpeg is installed, an MP4.

    scripts/deploydyn_animate.py RESULT_DIR -o deploy.gif --model examples/paper/general.yaml
    scripts/deploydyn_animate.py results/hot -o hot.gif --model examples/paper/general.yaml \\
        --frames 60 --fps 15 --force-range 5

history.csv gives the node coordinates and bar forces at each output time; which nodes a bar
joins comes from the model file (--model; without it, RESULT_DIR/model.yaml if there is one).
Only node and element names and the supports are read from the model, so overrides (--set)
that changed values do not matter. 3D models are drawn in their x–y projection. Colours:
blue compression, red tension, symmetric about zero; the colour range is the largest |force|
of the run unless --force-range is given.

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
import yaml  # noqa: E402
from matplotlib import animation, colors  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

# deploydyn's reader of result folders: pure Python, so that the script runs without the built
# module.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "python" / "deploydyn"))
import result_folder  # noqa: E402


def read_topology(model_file):
    """Element name → (node a, node b), the supported nodes, and node name → initial (x, y),
    from a model file.

    BaseLoader keeps every scalar as text, as the model loader reads names (so `1:` is "1").
    """
    spec = yaml.load(pathlib.Path(model_file).read_text(encoding="utf-8"), Loader=yaml.BaseLoader)
    if not isinstance(spec, dict) or not isinstance(spec.get("elements"), dict):
        raise SystemExit(f"deploydyn_animate: {model_file}: no 'elements' mapping")
    bars = {}
    for name, element in spec["elements"].items():
        nodes = element.get("nodes") if isinstance(element, dict) else None
        if not isinstance(nodes, list) or len(nodes) != 2:
            raise SystemExit(f"deploydyn_animate: {model_file}: elements.{name}.nodes: "
                             "expected two node names")
        bars[str(name)] = (str(nodes[0]), str(nodes[1]))
    supports = [str(s["node"]) for s in spec.get("supports") or [] if isinstance(s, dict)]
    positions = {}
    for name, node in (spec.get("nodes") or {}).items():
        at = node.get("at") if isinstance(node, dict) else node
        try:
            positions[str(name)] = (float(at[0]), float(at[1]))
        except (TypeError, ValueError, IndexError, KeyError):
            pass                          # the solver checked the file; this is only a check
    return bars, supports, positions


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


def check_start(data, positions, model_file, result_dir):
    """The run must start where the model's nodes are (within a tenth of the model's size):
    a model with the same names but another shape would draw wrong bars without this."""
    known = {n: xy for n, xy in positions.items() if f"x.{n}" in data and f"y.{n}" in data}
    if len(known) < 2:
        return
    model_xy = np.array(list(known.values()))
    start_xy = np.array([[data[f"x.{n}"][0], data[f"y.{n}"][0]] for n in known])
    size = np.ptp(model_xy, axis=0).max() or 1.0
    worst = int(np.argmax(np.linalg.norm(start_xy - model_xy, axis=1)))
    if np.linalg.norm(start_xy[worst] - model_xy[worst]) > 0.1 * size:
        name = list(known)[worst]
        raise SystemExit(f"deploydyn_animate: node {name} starts at {tuple(start_xy[worst])} in "
                         f"{result_dir}, but {model_file} puts it at {tuple(model_xy[worst])}: "
                         "is that the model of this run?")


def frame_rows(n_rows, frames, every):
    """Rows of the history to draw: every `every`-th, or `frames` spread evenly, always the last."""
    if every:
        rows = list(range(0, n_rows, every))
        if rows[-1] != n_rows - 1:
            rows.append(n_rows - 1)
        return rows
    return sorted(set(np.linspace(0, n_rows - 1, min(frames, n_rows)).round().astype(int)))


def animate(result_dir, model_file, out, frames=100, every=None, fps=20, dpi=90,
            force_range=None, title=None):
    """Write the animation; returns the number of frames."""
    bars, supports, positions = read_topology(model_file)
    data = read_history(result_dir)
    missing = [c for name, (a, b) in bars.items()
               for c in (f"force.{name}", f"x.{a}", f"y.{a}", f"x.{b}", f"y.{b}") if c not in data]
    if missing:
        raise SystemExit(f"deploydyn_animate: {result_dir}/history.csv has no column "
                         f"{', '.join(missing[:4])}: is {model_file} the model of this run?")
    check_start(data, positions, model_file, result_dir)
    names = list(bars)
    t = data["t"]
    forces = np.column_stack([data[f"force.{n}"] for n in names])          # rows × bars
    ends = np.stack([np.column_stack([data[f"x.{a}"], data[f"y.{a}"], data[f"x.{b}"],
                                      data[f"y.{b}"]]) for a, b in bars.values()], axis=1)
    segments = ends.reshape(len(t), len(names), 2, 2)                     # rows × bars × 2 × xy
    nodes = sorted({n for pair in bars.values() for n in pair})

    limit = force_range or float(np.max(np.abs(forces))) or 1.0
    norm = colors.Normalize(-limit, limit)
    xy = segments.reshape(-1, 2)
    span = np.ptp(xy, axis=0).max() or 1.0
    margin = 0.08 * span
    low, high = xy.min(axis=0) - margin, xy.max(axis=0) + margin
    aspect = (high[1] - low[1]) / (high[0] - low[0])    # figure shaped like the motion
    fig, ax = plt.subplots(figsize=(7.5, float(np.clip(6.0 * aspect + 1.4, 3.2, 8.0))))
    lines = LineCollection(segments[0], cmap="coolwarm", norm=norm, linewidths=5,
                           capstyle="round", zorder=2)
    lines.set_array(forces[0])
    ax.add_collection(lines)
    joints = ax.scatter([], [], s=28, color="black", zorder=3)
    ground = [n for n in supports if f"x.{n}" in data]
    ax.scatter([data[f"x.{n}"][0] for n in ground], [data[f"y.{n}"][0] for n in ground],
               marker="^", s=180, color="dimgrey", zorder=1, label="support")
    labels = {n: ax.annotate(n, (0, 0), xytext=(6, 6), textcoords="offset points", fontsize=10)
              for n in nodes}
    clock = ax.text(0.02, 0.96, "", transform=ax.transAxes, fontsize=11, va="top",
                    family="monospace")

    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(True, alpha=0.3)
    fig.colorbar(lines, ax=ax, fraction=0.04, pad=0.03, label="axial force (N), tension +")
    ax.set_title(title or pathlib.Path(result_dir).resolve().name, fontsize=11)
    fig.tight_layout()

    rows = frame_rows(len(t), frames, every)

    def draw(row):
        lines.set_segments(segments[row])
        lines.set_array(forces[row])
        positions = np.array([[data[f"x.{n}"][row], data[f"y.{n}"][row]] for n in nodes])
        joints.set_offsets(positions)
        for n, (x, y) in zip(nodes, positions):
            labels[n].xy = (x, y)
        clock.set_text(f"t = {t[row]:7.3f} s")
        return [lines, joints, clock, *labels.values()]

    movie = animation.FuncAnimation(fig, draw, frames=rows, blit=False)
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
    args = parser.parse_args(argv)

    model = args.model or pathlib.Path(args.result_dir) / "model.yaml"
    if not pathlib.Path(model).exists():
        parser.error(f"no model file {model}: give the run's model with --model "
                     "(history.csv has no bar connectivity)")
    if args.frames < 1 or (args.every is not None and args.every < 1):
        parser.error("--frames and --every must be at least 1")
    n = animate(args.result_dir, model, args.out, frames=args.frames, every=args.every,
                fps=args.fps, dpi=args.dpi, force_range=args.force_range, title=args.title)
    print(f"animate: wrote {args.out} ({n} frames)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
