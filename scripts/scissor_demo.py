#!/usr/bin/python3
"""Scissor structures under the paper's three temperature cases (+130, 0, −170 °C).

Runs `deploydyn study examples/scissor/<structure>_study.yaml` for the polar scissor arch and the
Hoberman ring (docs/scissor-structures.md) into results/scissor/<structure>/<case>/, prints a
table (peak member axial force, shear and bending moment, peak actuator torque, final span
against the stress-free rigid-link span scaled by the beams' free thermal stretch 1 + αΔT), and
draws results/scissor/<structure>.png: the deployed shapes and the actuator torque per case.
Exit code 1 when any case failed, after all were tried.
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "python" / "deploydyn"))
import result_folder  # noqa: E402
from demo_verdict import print_verdicts  # noqa: E402
from plot_legend import legend_beside  # noqa: E402

ALPHA = 1.2e-5  # 1/°C, steel: generators/scissor.hpp
CASES = (("hot", 130.0), ("normal", 0.0), ("cold", -170.0))
CASE_COLOURS = {"hot": "tab:red", "normal": "black", "cold": "tab:blue"}
# structure: (title, deployed span (m) the model was generated for, what the span is)
STRUCTURES = {
    "arch": ("polar scissor arch, 8 units, span 12 m", 12.0, "feet distance"),
    "ring": ("Hoberman ring, 12 angulated units, 4 m outer diameter", 4.0, "outer diameter"),
}


def run_study(cli, structure, out_root):
    """`deploydyn study` of the structure into out_root/<structure>/; one result per case."""
    folder = pathlib.Path(out_root) / structure
    command = [str(cli), "study", str(ROOT / "examples" / "scissor" / f"{structure}_study.yaml"),
               "--out", str(folder), "--quiet"]
    completed = subprocess.run(command, capture_output=True, text=True)
    results = []
    for case, delta_t in CASES:
        summary_file = folder / case / "summary.json"
        summary = json.loads(summary_file.read_text()) if summary_file.exists() else None
        ok = summary is not None and summary.get("status") == "completed"
        results.append({"structure": structure, "case": case, "dT": delta_t, "folder": folder / case,
                        "summary": summary, "ok": ok,
                        "error": "" if ok else (completed.stderr.strip() or "no summary")})
    return results


def largest(summary, key):
    """Largest |value| of quantity `key` over every element of summary.json."""
    values = [max(abs(q[key]["min"]), abs(q[key]["max"]))
              for q in summary["elements"].values() if key in q]
    return max(values) if values else float("nan")


def final_nodes(folder):
    """{node: (x, y)} of the last row of history.csv."""
    history = result_folder.read_history(folder / "history.csv", warn=False)
    row = history.values[-1]
    index = {name: i for i, name in enumerate(history.columns)}
    nodes = {}
    for name, i in index.items():
        if name.startswith("x."):
            node = name[2:]
            nodes[node] = (row[i], row[index["y." + node]])
    return nodes, history


def span(structure, nodes):
    """Arch: distance of the feet (inner ends of the first and last member); ring: 2|Q_0|."""
    if structure == "ring":
        x, y = nodes["m0b_0"]
        return 2.0 * math.hypot(x, y)
    feet = sorted((n for n in nodes if n.endswith("_0") and n.startswith("m") and "a_" in n),
                  key=lambda n: int(n[1:n.index("a")]))
    last_unit = int(feet[-1][1:feet[-1].index("a")])
    last_member = [n for n in nodes if n.startswith(f"m{last_unit}b_")]
    last = max(last_member, key=lambda n: int(n.rsplit("_", 1)[1]))
    (x0, y0), (x1, y1) = nodes["m0a_0"], nodes[last]
    return math.hypot(x1 - x0, y1 - y0)


def print_table(structure, results):
    title, deployed_span, what = STRUCTURES[structure]
    print(f"\n{title}: results in results/scissor/{structure}/<case>/")
    header = (f"{'case':7} {'ΔT °C':>6} {'|N| kN':>9} {'|V| kN':>9} {'|M| kN·m':>9} "
              f"{'torque kN·m':>11} {what + ' m':>17} {'rigid×(1+αΔT)':>16} {'Newton/step':>11}"
              f" {'wall s':>7}  status")
    print(header)
    print("-" * len(header))
    for r in results:
        s = r["summary"]
        if s is None or not s.get("elements"):
            print(f"{r['case']:7} {r['dT']:6.0f}  no result: {r['error']}")
            continue
        nodes, _ = final_nodes(r["folder"])
        expected = deployed_span * (1.0 + ALPHA * r["dT"])
        print(f"{r['case']:7} {r['dT']:6.0f} {largest(s, 'force') / 1e3:9.3f} "
              f"{largest(s, 'shear') / 1e3:9.3f} {largest(s, 'moment') / 1e3:9.3f} "
              f"{s['drivers']['motor']['peak'] / 1e3:11.4f} {span(structure, nodes):17.6f} "
              f"{expected:16.6f} {s['newton_iterations_per_step']:11.2f} {s['wall_time']:7.2f}  "
              f"{s['status']}")
    print_verdicts([(r["case"], r["summary"]) for r in results])


def plot(structure, results, out_root):
    """Deployed shapes (every beam as a line) and the actuator torque, per case."""
    figure, (shape_axes, torque_axes) = plt.subplots(1, 2, figsize=(14, 4.8))
    drawn = False
    for r in results:
        if not r["ok"]:
            print(f"note: {structure}/{r['case']} left out of the figure: {r['error']}",
                  file=sys.stderr)
            continue
        nodes, history = final_nodes(r["folder"])
        colour = CASE_COLOURS[r["case"]]
        # Members: consecutive nodes m<k><a|b>_<j>.
        members = {}
        for node, xy in nodes.items():
            if node.startswith("m") and "_" in node:
                member, j = node.rsplit("_", 1)
                members.setdefault(member, []).append((int(j), xy))
        for i, points in enumerate(members.values()):
            points.sort()
            shape_axes.plot([p[1][0] for p in points], [p[1][1] for p in points], color=colour,
                            linewidth=1.0, label=f"{r['case']} ({r['dT']:+.0f} °C)" if i == 0 else None)
        columns = history.columns
        time_column = columns.index("t")
        if "torque.motor" in columns:
            k = columns.index("torque.motor")
            torque_axes.plot([row[time_column] for row in history.values],
                             [row[k] / 1e3 for row in history.values], color=colour,
                             label=f"{r['case']} ({r['dT']:+.0f} °C)")
        drawn = True
    if not drawn:
        plt.close(figure)
        return
    shape_axes.set_aspect("equal")
    shape_axes.set_xlabel("x (m)")
    shape_axes.set_ylabel("y (m)")
    shape_axes.set_title("deployed shape")
    legend_beside(shape_axes)
    torque_axes.set_xlabel("time (s)")
    torque_axes.set_ylabel("actuator torque (kN·m)")
    torque_axes.set_title("revolute actuator at a central hinge")
    legend_beside(torque_axes)
    figure.suptitle(STRUCTURES[structure][0])
    figure.tight_layout()
    out = pathlib.Path(out_root) / f"{structure}.png"
    figure.savefig(out, dpi=120)
    plt.close(figure)
    print(f"wrote {out}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "scissor"))
    args = parser.parse_args()
    failed = False
    for structure in STRUCTURES:
        print(f"running {structure}: deploydyn study examples/scissor/{structure}_study.yaml ...",
              file=sys.stderr)
        start = time.perf_counter()
        results = run_study(args.cli, structure, args.out)
        print(f"  {time.perf_counter() - start:.1f} s", file=sys.stderr)
        print_table(structure, results)
        plot(structure, results, args.out)
        failed |= any(not r["ok"] for r in results)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
