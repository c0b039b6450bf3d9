#!/usr/bin/python3
"""The paper's study (Cai et al. 2017): both four-bar linkages under the three temperature cases.

Runs `deploydyn study examples/paper/<linkage>_study.yaml` for each linkage (its three cases in
parallel) into results/paper/<linkage>/<case>/, with the comparison table
results/paper/<linkage>/study.csv; a failed case does not stop the others (the table says why).
Then prints a table of the peak mechanical strain of each bar and the peak driver torque, and
draws the paper's Figs. 3-5 and the driver torques into results/paper/*.png
(scripts/plot_paper.py; a failed or missing case is left out of the plots with a message).
Then the deployability window of each linkage, −200 … +200 °C, into results/paper/window/
(`deploydyn window`, drawn by scripts/deploydyn_window.py).
Exit code 1 when any case failed, after all were tried.
"""
import argparse
import csv
import json
import pathlib
import subprocess
import sys
import time

import plot_paper
from demo_verdict import print_verdicts

ROOT = pathlib.Path(__file__).resolve().parent.parent
LINKAGES = ("parallel", "general")
CASES = (("hot", 130.0), ("normal", 0.0), ("cold", -170.0))  # ΔT in °C, paper Eq. (22)
# examples/paper/<linkage>_study.yaml runs these cases; scripts/paper_study.py uses CASES.


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


def run_study(cli, linkage, out_root):
    """Run examples/paper/<linkage>_study.yaml into out_root/<linkage>/; one result per case."""
    folder = pathlib.Path(out_root) / linkage
    command = [str(cli), "study", str(ROOT / "examples" / "paper" / f"{linkage}_study.yaml"),
               "--out", str(folder), "--quiet"]
    start = time.perf_counter()
    completed = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    table = folder / "study.csv"
    if not table.exists():  # the study file itself was refused: no case ran
        return wall, [{"linkage": linkage, "case": case, "dT": delta_t, "code": completed.returncode,
                       "error": completed.stderr.strip(), "summary": None, "shape": float("nan")}
                      for case, delta_t in CASES]
    results = []
    with table.open(newline="") as rows:
        for row in csv.DictReader(rows):
            summary_file = folder / row["case"] / "summary.json"
            ok = row["status"] == "completed"
            results.append({
                "linkage": linkage, "case": row["case"], "dT": float(row["thermal.dT"]),
                "code": 0 if ok else 1, "error": "" if ok else row["message"],
                "summary": json.loads(summary_file.read_text()) if summary_file.exists() else None,
                # from the normal (ΔT = 0) case's final shape; empty unless both completed
                "shape": float(row["shape_error"]) if row["shape_error"] else float("nan")})
    return wall, results


def run_window(cli, linkage, out_root):
    """`deploydyn window` of the linkage over ΔT = −200 … +200 °C into out_root/window/<linkage>/,
    printed, and drawn by scripts/deploydyn_window.py; True when it ran whole."""
    folder = pathlib.Path(out_root) / "window" / linkage
    model = ROOT / "examples" / "paper" / f"{linkage}.yaml"
    completed = subprocess.run([str(cli), "window", str(model), "--dT", "-200:200", "--out", str(folder)],
                               capture_output=True, text=True)
    print(f"\n{completed.stdout.rstrip()}")
    if completed.stderr:
        print(completed.stderr.rstrip(), file=sys.stderr)
    drawn = subprocess.run([sys.executable, str(ROOT / "scripts" / "deploydyn_window.py"), str(folder),
                            "--title", f"deployability window: {linkage} four-bar linkage"])
    return completed.returncode == 0 and drawn.returncode == 0


def peak(extremes):
    """Largest magnitude of a summary.json {min, max} entry (NaN when absent)."""
    return max(abs(extremes["min"]), abs(extremes["max"])) if extremes else float("nan")


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
        if s is None or not s["elements"]:  # no run, or it failed before its first record
            print(f"{r['linkage']:9} {r['case']:7} {r['dT']:6.0f}  no result: {r['error']}")
            continue
        strains = " ".join(f"{peak(s['elements'][e]['mstrain']):13.4e}" for e in elements)
        torque = s["drivers"]["motor"]["peak"]
        print(f"{r['linkage']:9} {r['case']:7} {r['dT']:6.0f} {strains} {torque:13.4e} "
              f"{r['shape']:10.2e} "
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

    results, processes = [], 0.0
    for linkage in LINKAGES:
        print(f"running {linkage} linkage: deploydyn study examples/paper/{linkage}_study.yaml ...",
              file=sys.stderr)
        wall, linkage_results = run_study(args.cli, linkage, out_root)
        results += linkage_results
        processes += wall

    print(f"\nCai et al. (2017) four-bar linkages, results in {out_root}/<linkage>/<case>/")
    print("peak |mechanical strain| per bar, peak |driver torque| over 0-5 s, and how far the final")
    print("shape lies from the normal case's (largest node distance)\n")
    print_table(results)
    print()
    print_verdicts([(f"{r['linkage']}/{r['case']}", r["summary"]) for r in results])
    total = sum(r["summary"]["wall_time"] for r in results if r["summary"])
    print(f"\nwall time of the six runs: {total:.3f} s in the solver, {processes:.3f} s for the two "
          "studies (cases in parallel) with process start and result files")
    for r in results:
        if r["shape"] > 0.01:
            print(f"note: {r['linkage']}/{r['case']} ends more than 1 cm from the normal case's shape: "
                  "it changed branch (see docs/paper-study.md)")
    print(file=sys.stderr)
    plot_paper.plot_paper_set(out_root)
    windows_ok = all(run_window(args.cli, linkage, out_root) for linkage in LINKAGES)
    return 1 if any(r["code"] != 0 for r in results) or not windows_ok else 0


if __name__ == "__main__":
    sys.exit(main())
