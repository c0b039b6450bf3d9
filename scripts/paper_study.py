#!/usr/bin/python3
"""The numbers behind docs/paper-study.md: the paper's six runs and the variants of its open choices.

Regenerates the variant model files (scripts/make_tip_driven_variants.py,
scripts/make_assumption_variants.py), runs the base cases into results/paper/<linkage>/<case>/
(as `make demo` does) and every variant into results/paper/variants/<variant>/<case>/, then
prints the doc's tables in Markdown (also saved to results/paper/variants/tables.md) and draws
results/paper/driver_models.png and results/paper/assumptions_general.png.

    /usr/bin/python3 scripts/paper_study.py [--cli build/release/deploydyn]

Strains are in µε (1e-6). "peak" is the largest magnitude over 0-5 s, "mean" the time average;
"Δ vs normal" compares a case with the ΔT = 0 run of the same model at the same output times.
"""
import argparse
import json
import pathlib
import sys

import numpy as np

import make_assumption_variants
import make_tip_driven_variants
import plot_paper
from linkage_models import TABLE1
from paper_demo import CASES, ROOT, run_model

MICRO = 1e6
EXAMPLES = ROOT / "examples" / "paper"
VARIANTS = EXAMPLES / "variants"


# ---------------------------------------------------------------- running

def run_set(cli, out_root, name, model, cases=CASES, case_override="thermal.dT={dT:g}", extra=()):
    """Run `model` for each (case, ΔT) into out_root/name/case; return {case: folder or None}."""
    folders = {}
    for case, delta_t in cases:
        folder = pathlib.Path(out_root) / name / case
        overrides = [case_override.format(dT=delta_t)] if case_override else []
        result = run_model(cli, model, folder, overrides + list(extra))
        ok = result["code"] == 0
        print(f"  {name}/{case}: {'completed' if ok else 'FAILED: ' + result['error']}",
              file=sys.stderr)
        folders[case] = folder if ok else None
    return folders


def history(folder):
    """{column: array} of a run's history.csv, or None for a failed run (read as the plots
    read it: plot_paper.read_folder, which leaves out a killed run's incomplete last row)."""
    if folder is None:
        return None
    data = plot_paper.read_folder(pathlib.Path(folder))[2]
    return None if data is None else dict(data)


def add_actuator_columns(data, kind):
    """Add `actuator_torque` (N·m, about the pivot, + counter-clockwise), `actuator_radial` (N,
    the actuator's force on the tip along pivot→tip; 0 for a direction-only driver, whose force
    is normal to the bar) and `driven_force` (N, the driven bar's axial force) to a history."""
    element, pivot, tip = TABLE1[kind]["driven"]
    data["driven_force"] = data[f"force.{element}"]
    if "torque.motor" in data:
        data["actuator_torque"] = data["torque.motor"]
        data["actuator_radial"] = np.zeros_like(data["t"])
        return
    rx, ry = data[f"x.{tip}"] - data[f"x.{pivot}"], data[f"y.{tip}"] - data[f"y.{pivot}"]
    fx, fy = data["force.tip_x"], data["force.tip_y"]
    data["actuator_torque"] = rx * fy - ry * fx
    data["actuator_radial"] = (rx * fx + ry * fy) / np.hypot(rx, ry)


# ---------------------------------------------------------------- measures

def peak(values):
    """Largest magnitude."""
    return float(np.max(np.abs(values)))


def final_distance(data, reference):
    """Largest distance (m) between the final node positions of two runs."""
    return max(float(np.hypot(data[f"x.{n}"][-1] - reference[f"x.{n}"][-1],
                              data[f"y.{n}"][-1] - reference[f"y.{n}"][-1])) for n in "ABCD")


def fmt(value, digits=3):
    """A number for a Markdown table; '—' for None/NaN."""
    if value is None or (isinstance(value, float) and np.isnan(value)):
        return "—"
    return f"{value:.{digits}g}"


def table(header, rows):
    """Markdown table text."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# ---------------------------------------------------------------- the doc's tables

def finding_tables(base):
    """Element 2, then all elements: total and mechanical strain per case, and Δ vs normal."""
    rows2, rows_all = [], []
    for kind in TABLE1:
        normal = base[kind]["normal"]
        for case, delta_t in CASES:
            d = base[kind][case]
            if d is None or normal is None:
                rows2.append([kind, case, f"{delta_t:+g}"] + ["failed"] * 8)
                continue
            de, dm = d["strain.2"] - normal["strain.2"], d["mstrain.2"] - normal["mstrain.2"]
            rows2.append([kind, case, f"{delta_t:+g}", fmt(2e-5 * delta_t * MICRO, 4),
                          fmt(np.mean(d["strain.2"]) * MICRO, 5), fmt(peak(d["strain.2"]) * MICRO, 5),
                          fmt(np.mean(d["mstrain.2"]) * MICRO), fmt(peak(d["mstrain.2"]) * MICRO),
                          fmt(np.mean(de) * MICRO, 5), fmt(peak(dm) * MICRO), fmt(np.mean(dm) * MICRO)])
            row = [kind, case, f"{delta_t:+g}"]
            for e in "123":
                ratio = peak(d[f"mstrain.{e}"]) / peak(normal[f"mstrain.{e}"])
                change = f"×{ratio:.3g}" if ratio > 10 else f"{(ratio - 1) * 100:+.1f} %"
                row.append(f"{fmt(peak(d[f'mstrain.{e}']) * MICRO)} ({change})")
            row.append(fmt(max(peak(d[f"mstrain.{e}"] - normal[f"mstrain.{e}"]) for e in "123") * MICRO))
            row.append(fmt(peak(d["torque.motor"])))
            row.append(fmt(final_distance(d, normal) * 1e3))
            rows_all.append(row)
    t2 = table(["linkage", "case", "ΔT °C", "αΔT", "mean ε", "peak \\|ε\\|", "mean ε_m",
                "peak \\|ε_m\\|", "mean Δε", "peak \\|Δε_m\\|", "mean Δε_m"], rows2)
    t_all = table(["linkage", "case", "ΔT °C", "peak \\|ε_m\\| el. 1 (vs normal)", "el. 2", "el. 3",
                   "peak \\|Δε_m\\| any el.", "peak \\|torque\\| N·m", "final shape Δ mm"], rows_all)
    return ("### Element 2 (µε; Δ = this case − normal, same times)\n\n" + t2 +
            "\n\n### All elements (peak |ε_m| in µε, change of the peak against normal)\n\n" + t_all)


def driver_table(base, tip):
    """Direction-only against tip-position driver: strains, forces, actuator effort."""
    rows = []
    for kind in TABLE1:
        element = TABLE1[kind]["driven"][0]
        for case, delta_t in CASES:
            for model, runs in (("direction", base), ("tip position", tip)):
                d = runs[kind][case]
                if d is None:
                    rows.append([kind, case, model] + ["failed"] * 7)
                    continue
                rows.append([kind, case, model] +
                            [fmt(peak(d[f"mstrain.{e}"]) * MICRO) for e in "123"] +
                            [fmt(float(np.mean(d["driven_force"])), 4),
                             fmt(peak(d["force.2"])), fmt(peak(d["actuator_torque"])),
                             fmt(peak(d["actuator_radial"]))])
    return table(["linkage", "case", "driver", "peak \\|ε_m\\| el. 1 µε", "el. 2", "el. 3",
                  "driven bar: mean N (N)", "peak \\|N\\| el. 2 (N)", "peak \\|torque\\| N·m",
                  "peak \\|radial actuator force\\| N"], rows)


def variant_table(label, sets, note_column=None):
    """Rows per (variant, case): peak |ε_m| per element, element-2 mean ε_m, peak torque,
    and the element-2 difference against the same variant's normal case. note_column:
    (header, function(history, case) -> text) for one more column."""
    rows = []
    for name, runs in sets.items():
        normal = runs.get("normal")
        for case, d in runs.items():
            if d is None:
                rows.append([name, case] + ["failed"] * 7)
                continue
            diff = peak(d["mstrain.2"] - normal["mstrain.2"]) * MICRO if normal is not None else None
            row = [name, case] + [fmt(peak(d[f"mstrain.{e}"]) * MICRO) for e in "123"]
            row += [fmt(float(np.mean(d["mstrain.2"])) * MICRO), fmt(diff),
                    fmt(peak(d["torque.motor"])) if "torque.motor" in d else "—"]
            if note_column:
                row.append(note_column[1](d, case))
            rows.append(row)
    header = [label, "case", "peak \\|ε_m\\| el. 1 µε", "el. 2", "el. 3", "mean ε_m el. 2",
              "peak \\|Δε_m\\| el. 2 vs normal", "peak \\|torque\\| N·m"]
    return table(header + ([note_column[0]] if note_column else []), rows)


def rotation(d, kind):
    """Turn of the driven bar at the end of the run, and the largest turn (degrees)."""
    _, pivot, tip = TABLE1[kind]["driven"]
    angle = np.unwrap(np.arctan2(d[f"y.{tip}"] - d[f"y.{pivot}"], d[f"x.{tip}"] - d[f"x.{pivot}"]))
    turn = np.degrees(angle - angle[0])
    return f"{turn[-1]:.1f} (max {turn.max():.1f})"


# ---------------------------------------------------------------- figures

def driver_models_figure(results, out_png):
    """results/paper/driver_models.png: direction-only (solid) vs tip-position (dashed) driver.

    One column per linkage; rows: the driven bar's axial force, element 2's mechanical strain,
    the actuator torque. The parallel linkage's cold case (jammed with either driver, forces
    10⁴ times larger) is left to the table so that the other curves stay readable."""
    runs, panels = [], {}
    for kind in TABLE1:
        for model, folder, style in (("direction", results / kind, "-"),
                                     ("tip", results / "variants" / f"{kind}_tip", "--")):
            for case, delta_t in CASES:
                runs.append(plot_paper.Run(f"{kind}: {case}, {model}", folder / case,
                                           colour=plot_paper.CASE_COLOURS[case], linestyle=style,
                                           derive=lambda data, k=kind: add_actuator_columns(data, k)))
        shown = [r.label for r in runs if r.label.startswith(kind)
                 and not (kind == "parallel" and ": cold" in r.label)]
        note = "cold case: jammed, see the table" if kind == "parallel" else None
        element = TABLE1[kind]["driven"][0]
        panels[kind] = [
            plot_paper.Panel([("driven_force", "")], f"{kind}: axial force, driven bar {element} (N)",
                             runs=shown, note=note),
            plot_paper.Panel([("mstrain.2", "")], f"{kind}: ε_m of element 2 (µε)",
                             plot_paper.MICRO, runs=shown, note=note),
            plot_paper.Panel([("actuator_torque", "")], f"{kind}: actuator torque (N·m)",
                             runs=shown, note=note)]
    ordered = [p for row in zip(panels["parallel"], panels["general"]) for p in row]
    return plot_paper.plot_columns(
        out_png, runs, ordered,
        "Driver models side by side: direction-only driver (solid) leaves the driven bar free to "
        "stretch; prescribed tip position (dashed) holds it at its reference length, so it carries "
        "−EA·α·ΔT and the actuator pushes or pulls along it.\nLeft: parallel linkage (bar 3 driven "
        "about D). Right: general linkage (assumed ground 0.8 m, crank from 60°; bar 1 driven about "
        "A). Hot red, normal black, cold blue.", ncols=2)


def assumptions_figure(results, out_png):
    """results/paper/assumptions_general.png: ground length (left) and ω reading (right),
    general linkage at ΔT = 0."""
    variants = results / "variants"
    grounds = [plot_paper.Run(f"ground {g:g} m", variants / f"general_ground_{g:g}" / "normal",
                              colour=c)
               for g, c in zip(make_assumption_variants.GROUND_LENGTHS,
                               ("tab:green", "black", "tab:purple"))]
    readings = [plot_paper.Run("ω as angular velocity (1.46 rad)", results / "general" / "normal",
                               colour="black"),
                plot_paper.Run("ω as angle (0.365 rad and back)",
                               variants / "general_angle" / "normal", colour="tab:orange")]
    ground_labels, reading_labels = [r.label for r in grounds], [r.label for r in readings]
    panels = [
        plot_paper.Panel(["mstrain.2"], "element 2: mechanical strain (µε)", plot_paper.MICRO,
                         runs=ground_labels, note="crank from 60°, Eq. 23 as ω"),
        plot_paper.Panel(["mstrain.2"], "element 2: mechanical strain (µε)", plot_paper.MICRO,
                         runs=reading_labels, note="ground 0.8 m, crank from 60°"),
        plot_paper.Panel(["torque.motor"], "driver torque (N·m)", runs=ground_labels),
        plot_paper.Panel(["torque.motor"], "driver torque (N·m)", runs=reading_labels)]
    return plot_paper.plot_columns(
        out_png, grounds + readings, panels,
        "General four-bar linkage, ΔT = 0: two choices the paper leaves open. Left: ground A–D "
        "0.7 / 0.8 / 0.9 m (C by circle intersection, Table-1 bar lengths). Right: Eq. 23 read as "
        "an angular velocity (project) or as the angle itself.", ncols=2)


# ---------------------------------------------------------------- main

def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "paper"))
    args = parser.parse_args()
    results = pathlib.Path(args.out)
    make_tip_driven_variants.main()
    make_assumption_variants.main()

    def load(folders, kind=None):
        """Histories of a run set, with actuator columns when `kind` is given."""
        out = {case: history(f) for case, f in folders.items()}
        for d in out.values():
            if d is not None and kind:
                add_actuator_columns(d, kind)
        return out

    print("running ...", file=sys.stderr)
    base, tip, angle, expands, heated = {}, {}, {}, {}, {}
    for kind in TABLE1:
        base[kind] = load(run_set(args.cli, results, kind, EXAMPLES / f"{kind}.yaml"), kind)
        tip[kind] = load(run_set(args.cli, results / "variants", f"{kind}_tip",
                                 VARIANTS / f"{kind}_tip.yaml"), kind)
        angle[kind] = load(run_set(args.cli, results / "variants", f"{kind}_angle",
                                   EXAMPLES / f"{kind}.yaml", extra=["drivers.motor.reading=angle"]))
        expands[kind] = {"normal": base[kind]["normal"]}
        for case, _ in make_assumption_variants.EXPANSION_CASES:
            expands[kind].update(load(run_set(
                args.cli, results / "variants", f"{kind}_ground_expands",
                VARIANTS / f"{kind}_ground_expands_{case}.yaml",
                cases=[c for c in CASES if c[0] == case], case_override=None)))
        heated[kind] = load(run_set(args.cli, results / "variants", f"{kind}_heated_at_start",
                                    VARIANTS / f"{kind}_heated_at_start.yaml",
                                    case_override="functions.heat.v1={dT:g}"))
    grounds = {f"{g:g} m": load(run_set(args.cli, results / "variants", f"general_ground_{g:g}",
                                        VARIANTS / f"general_ground_{g:g}.yaml"))
               for g in make_assumption_variants.GROUND_LENGTHS}
    cranks = {f"{a:g}°": load(run_set(args.cli, results / "variants", f"general_crank_{a:g}",
                                      VARIANTS / f"general_crank_{a:g}.yaml"))
              for a in make_assumption_variants.CRANK_ANGLES}
    fine = {"parallel, h = 0.25 ms": load(run_set(
        args.cli, results / "variants", "parallel_step_0.25ms", EXAMPLES / "parallel.yaml",
        extra=["analysis.step=2.5e-4"]))}

    sections = [
        "## Temperature effect, direction-only driver (the project's model)\n\n" + finding_tables(base),
        "## Driver models\n\n" + driver_table(base, tip),
        "## Ground length, general linkage\n\n" + variant_table("ground A–D", grounds),
        "## Initial crank angle, general linkage\n\n" + variant_table("crank", cranks),
        "## ω read as an angle (--set drivers.motor.reading=angle)\n\n" +
        "\n\n".join(variant_table(f"{kind}, angle", {kind: angle[kind]},
                                  ("turn of driven bar, end (max) °", lambda d, case, k=kind: rotation(d, k)))
                    for kind in TABLE1),
        "## Ground expanding with the bars\n\n" + "\n\n".join(
            variant_table(f"{kind}", {f"{kind}, ground expands": expands[kind]},
                          ("final shape Δ vs normal mm",
                           lambda d, case, k=kind: fmt(final_distance(d, base[k]["normal"]) * 1e3)))
            for kind in TABLE1),
        "## Heated at the start instead of starting in thermal equilibrium\n\n" + "\n\n".join(
            variant_table(f"{kind}", {f"{kind}, heated at start": heated[kind]},
                          ("final shape Δ vs normal mm",
                           lambda d, case, k=kind: fmt(final_distance(d, base[k]["normal"]) * 1e3)))
            for kind in TABLE1),
        "## Step check, parallel linkage\n\n" + variant_table(
            "run", fine, ("final shape Δ vs same case at h = 1 ms, mm",
                          lambda d, case: fmt(final_distance(d, base["parallel"][case]) * 1e3))),
    ]
    text = "\n\n".join(sections) + "\n"
    print(text)
    (results / "variants").mkdir(parents=True, exist_ok=True)
    (results / "variants" / "tables.md").write_text(text)
    driver_models_figure(results, results / "driver_models.png")
    assumptions_figure(results, results / "assumptions_general.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
