#!/usr/bin/python3
"""The spring-driven four-bay mast under the paper's three temperature cases (+130, 0, −170 °C).

Runs `deploydyn run examples/boom/boom.yaml --set thermal.dT=<ΔT>` (docs/boom.md) into
results/boom/<case>/, prints and writes per case a table (results/boom/<case>.md and .csv): per
hinge whether and when it latched, its final opening angle, the peak spring torque, the peak
sliding friction torque, the friction the pin can hold (μ r N), and the opening at which that
first exceeds the spring torque; the final tip position; Newton iterations per step, mode
switches and wall time. Draws results/boom/boom_angles.png (openings against time),
boom_torques.png (friction against spring torque) and boom_shapes.png (final shapes).
Exit code 1 when any case failed, after all were tried.
"""
import argparse
import csv
import json
import math
import pathlib
import re
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

MODEL = ROOT / "examples" / "boom" / "boom.yaml"
CASES = (("hot", 130.0), ("normal", 0.0), ("cold", -170.0))
CASE_COLOURS = {"hot": "tab:red", "normal": "black", "cold": "tab:blue"}
HINGES = ("hinge1", "hinge2", "hinge3", "hinge4")
BAYS = 4
LATCHED, STUCK = 1, 4
STATE_NAMES = {0: "sliding", 1: "latched", 2: "at stop", 3: "at stop", 4: "stuck", 5: "held"}
# Members drawn in the shapes: posts and links of each bay, the platforms' battens.
MEMBERS = ([(f"L{i - 1}", f"L{i}") for i in range(1, BAYS + 1)] + [(f"R{i - 1}", f"R{i}") for i in range(1, BAYS + 1)]
           + [(f"M{i - 1}", f"M{i}") for i in range(1, BAYS + 1)] + [(f"L{i}", f"R{i}") for i in range(0, BAYS + 1)])


def hinge_constants(model_yaml):
    """{hinge: (μ, r)} from the run's model.yaml (one flow mapping a line, as deploydyn writes it)."""
    constants = {}
    for line in model_yaml.read_text().splitlines():
        m = re.match(r"\s*(\w+): \{type: hinge,.*\bfriction: ([0-9.eE+-]+), pin_radius: ([0-9.eE+-]+)", line)
        if m:
            constants[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return constants


def run_case(cli, case, delta_t, out_root):
    folder = pathlib.Path(out_root) / case
    command = [str(cli), "run", str(MODEL), "--out", str(folder), "--quiet", "--set", f"thermal.dT={delta_t:g}"]
    start = time.perf_counter()
    completed = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    summary_file = folder / "summary.json"
    summary = json.loads(summary_file.read_text()) if summary_file.exists() else None
    ok = completed.returncode == 0 and summary is not None and summary.get("status") == "completed"
    return {"case": case, "dT": delta_t, "folder": folder, "summary": summary, "ok": ok, "wall_s": wall,
            "error": "" if ok else (completed.stderr.strip() or "no summary")}


def analyse(result):
    """Per hinge rows and the tip position of one finished case."""
    folder, summary = result["folder"], result["summary"]
    history = result_folder.read_history(folder / "history.csv", warn=False)
    col = {name: i for i, name in enumerate(history.columns)}
    rows = history.values
    constants = hinge_constants(folder / "model.yaml")
    latch_times = {}
    for event in summary.get("events", []):
        if event["what"] == "latched":
            latch_times.setdefault(event["element"], event["time_s"])
    hinges = []
    for h in HINGES:
        mu, radius = constants[h]
        opening = [abs(r[col[f"hinge_angle.{h}"]]) for r in rows]  # θ = ∓ opening (docs/boom.md)
        spring = [abs(r[col[f"spring_torque.{h}"]]) for r in rows]
        friction = [abs(r[col[f"friction_torque.{h}"]]) for r in rows]
        capacity = [mu * radius * r[col[f"pin_force.{h}"]] for r in rows]
        state = [int(round(r[col[f"hinge_state.{h}"]])) for r in rows]
        # Where the friction the pin can hold first exceeds the spring's torque (while the spring
        # still pushes the bay open).
        exceeds = next((math.degrees(opening[k]) for k in range(len(rows)) if capacity[k] > spring[k]), None)
        latched = state[-1] == LATCHED
        latch_time = latch_times.get(h)
        if latched and latch_time is None:  # events beyond the summary's list: the history's time
            latch_time = next(rows[k][col["t"]] for k in range(len(rows)) if state[k] == LATCHED)
        hinges.append({
            "hinge": h, "latched": latched, "latch_time_s": latch_time if latched else None,
            "final_opening_deg": math.degrees(opening[-1]), "final_state": STATE_NAMES.get(state[-1], str(state[-1])),
            "peak_spring_Nm": max(spring), "peak_friction_Nm": max(friction), "peak_capacity_Nm": max(capacity),
            "final_spring_Nm": spring[-1], "final_capacity_Nm": capacity[-1],
            "friction_exceeds_spring_at_deg": exceeds, "pin_force_N": rows[-1][col[f"pin_force.{h}"]],
        })
    tip = (rows[-1][col["x.M4"]], rows[-1][col["y.M4"]])
    return {"hinges": hinges, "tip": tip, "history": history, "col": col}


def fmt(value, spec):
    return "–" if value is None else format(value, spec)


def write_tables(result, analysis, out_root):
    """results/boom/<case>.md and .csv; the markdown is printed too."""
    case, summary = result["case"], result["summary"]
    header = ["hinge", "latched", "latch time s", "final opening °", "final state", "peak spring N·m",
              "peak sliding friction N·m", "peak μrN N·m", "pin force N (end)", "μrN > spring from °"]
    lines = [f"### {case}: ΔT = {result['dT']:+.0f} °C", "",
             "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    csv_rows = []
    for h in analysis["hinges"]:
        cells = [h["hinge"], "yes" if h["latched"] else "no", fmt(h["latch_time_s"], ".3f"),
                 f"{h['final_opening_deg']:.1f}", h["final_state"], f"{h['peak_spring_Nm']:.3f}",
                 f"{h['peak_friction_Nm']:.3f}", f"{h['peak_capacity_Nm']:.3f}", f"{h['pin_force_N']:.0f}",
                 fmt(h["friction_exceeds_spring_at_deg"], ".1f")]
        lines.append("| " + " | ".join(cells) + " |")
        csv_rows.append(h)
    end = summary["end"]
    tip = analysis["tip"]
    lines += ["", f"End: {end['reason']} at {end['time_s']:.3f} s; tip (M4) at x = {tip[0]:.4f} m, "
              f"y = {tip[1]:.4f} m (deployed: 0.15, 2.0); Newton iterations per step "
              f"{summary['newton_iterations_per_step']:.2f}, mode switches {summary['mode_switches']}, "
              f"solver {summary['wall_time']:.2f} s, run {result['wall_s']:.2f} s.", ""]
    text = "\n".join(lines)
    out = pathlib.Path(out_root)
    (out / f"{case}.md").write_text(text + "\n")
    with open(out / f"{case}.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["case", "dT_C"] + list(csv_rows[0].keys()) +
                                ["tip_x_m", "tip_y_m", "end_reason", "end_time_s", "newton_per_step", "mode_switches",
                                 "wall_s"])
        writer.writeheader()
        for h in csv_rows:
            writer.writerow({"case": case, "dT_C": result["dT"], **h, "tip_x_m": tip[0], "tip_y_m": tip[1],
                             "end_reason": end["reason"], "end_time_s": end["time_s"],
                             "newton_per_step": summary["newton_iterations_per_step"],
                             "mode_switches": summary["mode_switches"], "wall_s": result["wall_s"]})
    print(text)


def plot(results, analyses, out_root):
    out = pathlib.Path(out_root)
    done = [(r, a) for r, a in zip(results, analyses) if a is not None]
    if not done:
        return
    styles = ("-", "--", "-.", ":")
    # Openings against time.
    figure, axes = plt.subplots(figsize=(10, 4.5))
    for r, a in done:
        history, col = a["history"], a["col"]
        t = [row[col["t"]] for row in history.values]
        for h, style in zip(HINGES, styles):
            axes.plot(t, [math.degrees(abs(row[col[f"hinge_angle.{h}"]])) for row in history.values],
                      color=CASE_COLOURS[r["case"]], linestyle=style, linewidth=1.2,
                      label=f"{r['case']} ({r['dT']:+.0f} °C), {h}")
    axes.axhline(90.0, color="grey", linewidth=0.8)
    axes.set_xlabel("time (s)")
    axes.set_ylabel("bay opening (°): 10 folded, 90 latched")
    axes.set_title("four-bay mast: hinge openings")
    legend_beside(axes, fontsize=7)
    figure.tight_layout()
    figure.savefig(out / "boom_angles.png", dpi=120)
    plt.close(figure)
    # Friction against spring torque along the opening, one panel per case.
    figure, panels = plt.subplots(1, len(done), figsize=(4.2 * len(done), 4.2), sharey=True, squeeze=False)
    for (r, a), axes in zip(done, panels[0]):
        history, col = a["history"], a["col"]
        constants = hinge_constants(r["folder"] / "model.yaml")
        for h, style in zip(HINGES, styles):
            mu, radius = constants[h]
            opening = [math.degrees(abs(row[col[f"hinge_angle.{h}"]])) for row in history.values]
            axes.plot(opening, [abs(row[col[f"spring_torque.{h}"]]) for row in history.values], color="tab:green",
                      linestyle=style, linewidth=1.0, label=f"spring, {h}" if h in ("hinge1", "hinge4") else None)
            axes.plot(opening, [mu * radius * row[col[f"pin_force.{h}"]] for row in history.values],
                      color="tab:purple", linestyle=style, linewidth=1.0,
                      label=f"μ r N, {h}" if h in ("hinge1", "hinge4") else None)
        axes.axvline(90.0, color="grey", linewidth=0.8)
        axes.set_xlabel("bay opening (°)")
        axes.set_title(f"{r['case']} ({r['dT']:+.0f} °C)")
    legend_beside(panels[0][-1], fontsize=7)  # the same lines in every panel
    panels[0][0].set_ylabel("torque (N·m)")
    figure.suptitle("spring torque against the friction the pin holds (μ r N)")
    figure.tight_layout()
    figure.savefig(out / "boom_torques.png", dpi=120)
    plt.close(figure)
    # Final shapes.
    figure, axes = plt.subplots(figsize=(8, 6))
    for r, a in done:
        row = a["history"].values[-1]
        col = a["col"]
        for k, (p, q) in enumerate(MEMBERS):
            axes.plot([row[col[f"x.{p}"]], row[col[f"x.{q}"]]], [row[col[f"y.{p}"]], row[col[f"y.{q}"]]],
                      color=CASE_COLOURS[r["case"]], linewidth=3.0 if r["case"] == "hot" else 1.2,
                      label=f"{r['case']} ({r['dT']:+.0f} °C) at {r['summary']['end']['time_s']:.2f} s" if k == 0 else None)
    first = done[0][1]["history"].values[0]
    col = done[0][1]["col"]
    for k, (p, q) in enumerate(MEMBERS):
        axes.plot([first[col[f"x.{p}"]], first[col[f"x.{q}"]]], [first[col[f"y.{p}"]], first[col[f"y.{q}"]]],
                  color="grey", linewidth=0.8, linestyle=":", label="folded (t = 0)" if k == 0 else None)
    axes.set_aspect("equal")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_title("final shapes")
    legend_beside(axes)
    figure.tight_layout()
    figure.savefig(out / "boom_shapes.png", dpi=120)
    plt.close(figure)
    print(f"wrote {out}/boom_angles.png, boom_torques.png, boom_shapes.png", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "boom"))
    args = parser.parse_args()
    pathlib.Path(args.out).mkdir(parents=True, exist_ok=True)
    results, analyses = [], []
    for case, delta_t in CASES:
        print(f"running {case}: deploydyn run examples/boom/boom.yaml --set thermal.dT={delta_t:g} ...",
              file=sys.stderr)
        result = run_case(args.cli, case, delta_t, args.out)
        results.append(result)
        if not result["ok"]:
            print(f"{case}: no result: {result['error']}", file=sys.stderr)
            analyses.append(None)
            continue
        analysis = analyse(result)
        analyses.append(analysis)
        write_tables(result, analysis, args.out)
    print_verdicts([(r["case"], r.get("summary")) for r in results])
    plot(results, analyses, args.out)
    return 0 if all(r["ok"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
