#!/usr/bin/python3
"""The paper's study (Cai et al. 2017): both four-bar linkages under the three temperature cases.

Runs `deploydyn run` for every (linkage, case) into results/paper/<linkage>/<case>/, keeps going
when a case fails (saying why), then prints a table of the peak mechanical strain of each bar
and the peak driver torque, and draws the paper's Figs. 3-5 and the driver torques into
results/paper/*.png (scripts/plot_paper.py; a failed or missing case is left out of the plots
with a message). Exit code 1 when any case failed, after all were tried.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import time

import plot_paper

ROOT = pathlib.Path(__file__).resolve().parent.parent
LINKAGES = ("parallel", "general")
CASES = (("hot", 130.0), ("normal", 0.0), ("cold", -170.0))  # ΔT in °C, paper Eq. (22)


def run_model(cli, model, folder, overrides=()):
    """Run `deploydyn run model --out folder --set ...`; return exit code, stderr, summary, wall."""
    command = [str(cli), "run", str(model), "--out", str(folder), "--quiet"]
    for override in overrides:
        command += ["--set", override]
    start = time.perf_counter()
    completed = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    summary_file = folder / "summary.json"
    summary = json.loads(summary_file.read_text()) if summary_file.exists() else None
    error = completed.stderr.strip() if completed.returncode != 0 else ""
    return {"code": completed.returncode, "error": error, "summary": summary, "wall": wall}


def run_case(cli, linkage, case, delta_t, out_root):
    """Run examples/paper/<linkage>.yaml at ΔT = delta_t into out_root/<linkage>/<case>/."""
    result = run_model(cli, ROOT / "examples" / "paper" / f"{linkage}.yaml",
                       pathlib.Path(out_root) / linkage / case, [f"thermal.dT={delta_t:g}"])
    return {"linkage": linkage, "case": case, "dT": delta_t, **result}


def peak(extremes):
    """Largest magnitude of a summary.json {min, max} entry (NaN when absent)."""
    return max(abs(extremes["min"]), abs(extremes["max"])) if extremes else float("nan")


def shape_change(result, results):
    """Largest distance (m) of a final node position from the normal (ΔT = 0) case's."""
    normal = next((r for r in results if r["linkage"] == result["linkage"] and r["dT"] == 0.0), None)
    if normal is None or normal["summary"] is None:
        return float("nan")
    mine = result["summary"]["final_positions"]
    theirs = normal["summary"]["final_positions"]
    return max(sum((a - b) ** 2 for a, b in zip(mine[n], theirs[n])) ** 0.5 for n in mine)


def print_table(results):
    """The six runs' peak mechanical strains, torque, shape change, steps and wall time."""
    elements = ("1", "2", "3")
    header = (f"{'linkage':9} {'case':7} {'ΔT °C':>6} "
              + " ".join(f"{'|ε_m| bar ' + e:>13}" for e in elements)
              + f" {'|torque| N·m':>13} {'shape Δ m':>10} {'steps':>6} {'Newton/step':>11}"
              + f" {'wall s':>7}  status")
    print(header)
    print("-" * len(header))
    for r in results:
        s = r["summary"]
        if s is None:
            print(f"{r['linkage']:9} {r['case']:7} {r['dT']:6.0f}  no result: {r['error']}")
            continue
        strains = " ".join(f"{peak(s['elements'][e]['mstrain']):13.4e}" for e in elements)
        torque = s["drivers"]["motor"]["peak"]
        print(f"{r['linkage']:9} {r['case']:7} {r['dT']:6.0f} {strains} {torque:13.4e} "
              f"{shape_change(r, results):10.2e} "
              f"{s['steps']:6d} {s['newton_iterations_per_step']:11.2f} {s['wall_time']:7.3f}  "
              f"{s['status']}")
    for r in results:
        if r["code"] != 0:
            print(f"\n{r['linkage']}/{r['case']} did not complete:\n  {r['error']}")


def main():
    """Run the six cases, print the table, draw the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "paper"))
    args = parser.parse_args()
    out_root = pathlib.Path(args.out)

    results = []
    for linkage in LINKAGES:
        for case, delta_t in CASES:
            print(f"running {linkage} linkage, {case} (ΔT = {delta_t:+g} °C) ...", file=sys.stderr)
            results.append(run_case(args.cli, linkage, case, delta_t, out_root))

    print(f"\nCai et al. (2017) four-bar linkages, results in {out_root}/<linkage>/<case>/")
    print("peak |mechanical strain| per bar, peak |driver torque| over 0-5 s, and how far the final")
    print("shape lies from the normal case's (largest node distance)\n")
    print_table(results)
    total = sum(r["summary"]["wall_time"] for r in results if r["summary"])
    processes = sum(r["wall"] for r in results)
    print(f"\nwall time of the six runs: {total:.3f} s in the solver, {processes:.3f} s with process "
          "start and result files")
    for r in results:
        if r["summary"] and shape_change(r, results) > 0.01:
            print(f"note: {r['linkage']}/{r['case']} ends more than 1 cm from the normal case's shape: "
                  "it changed branch (see docs/paper-study.md)")
    print(file=sys.stderr)
    plot_paper.plot_paper_set(out_root)
    return 1 if any(r["code"] != 0 for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
