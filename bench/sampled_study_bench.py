#!/usr/bin/python3
"""Study throughput over MPI and a 1000-case Monte Carlo of a heated roof (docs/performance.md,
"Studies over MPI and sampling").

    bench/sampled_study_bench.py --cli build/release/deploydyn [--cases 40] [--repetitions 3]
        [--monte-carlo 1000] [--out /tmp/sampled_bench]

The model: `deploydyn generate roof --units 10 --trusses 2` (a redundant 3D roof of 2 trusses of
10 units, 104 bars, ΔT = +130 °C, 5 s deployment). The sampling: member length errors
N(0, 0.05 mm), a temperature field ΔT_u ∈ [110, 150] °C with a 0–20 °C gradient across the
trusses (z) and 3 °C member scatter, E and α scatter of 3 % and 5 %.

Throughput: the same study of --cases drawn cases without MPI (threads: --jobs 1, and the
default, every case at once) and with `mpirun -n 1, 2, 4` (oversubscribed beyond the cores);
medians of --repetitions wall times, cases per minute, and the serial fraction f from Amdahl's
law between 1 and 2 processes: T2/T1 = f + (1 − f)/2. Then one Monte Carlo study of
--monte-carlo cases over 2 processes: its wall time and statistics.csv's main rows.
"""
import argparse
import csv
import os
import pathlib
import shutil
import statistics
import subprocess
import time

SAMPLING = """model: roof.yaml
sampling:
  method: {method}
  cases: {cases}
  seed: 2026
  length_error: [{{elements: '*', normal: 0.05e-3}}]
  temperature: {{dT: [110, 150], gradient: {{direction: [0, 0, 1], dT: [0, 20]}}, scatter: 3}}
  material: {{E: 0.03, alpha: 0.05}}
  limits: {{force: 2000, torque: 50, shape_error: 0.002}}
"""
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def timed(command, env=None):
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    if done.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)} failed:\n{done.stderr[-2000:]}")
    return wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default="build/release/deploydyn")
    parser.add_argument("--cases", type=int, default=40)
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--monte-carlo", type=int, default=1000)
    parser.add_argument("--out", default="/tmp/sampled_bench")
    arguments = parser.parse_args()
    cli = str(pathlib.Path(arguments.cli).resolve())
    out = pathlib.Path(arguments.out)
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    subprocess.run([cli, "generate", "roof", "--units", "10", "--trusses", "2", "--out", str(out / "roof.yaml")],
                   check=True, capture_output=True)
    (out / "throughput.yaml").write_text(SAMPLING.format(method="latin_hypercube", cases=arguments.cases))
    (out / "monte_carlo.yaml").write_text(SAMPLING.format(method="monte_carlo", cases=arguments.monte_carlo))

    configurations = [("threads, --jobs 1", [cli, "study", "--jobs", "1"], None),
                      ("threads, all at once", [cli, "study", "--jobs", "0"], None)]
    if shutil.which("mpirun"):
        for n in (1, 2, 4):
            configurations.append((f"mpirun -n {n}", ["mpirun", "-n", str(n), "--oversubscribe", cli, "study"], MPI_ENV))
    print(f"| run | wall (s), median of {arguments.repetitions} | cases per minute | speed-up |")
    print("|---|---|---|---|")
    walls = {}
    for name, command, env in configurations:
        times = []
        for r in range(arguments.repetitions):
            folder = out / f"run_{len(walls)}_{r}"
            times.append(timed([*command, str(out / "throughput.yaml"), "--out", str(folder), "--quiet"], env))
            shutil.rmtree(folder)
        walls[name] = statistics.median(times)
        cases = arguments.cases + 1  # and nominal
        base = walls[configurations[0][0]]
        print(f"| {name} | {walls[name]:.2f} | {60 * cases / walls[name]:.0f} | {base / walls[name]:.2f} |")
    if "mpirun -n 2" in walls:
        ratio = walls["mpirun -n 2"] / walls["mpirun -n 1"]
        print(f"\nserial fraction (Amdahl, 1 → 2 processes): f = 2·T2/T1 − 1 = {2 * ratio - 1:.3f}")

    if arguments.monte_carlo > 0:
        command = ["mpirun", "-n", "2", "--oversubscribe", cli, "study"] if shutil.which("mpirun") else [cli, "study"]
        folder = out / "monte_carlo"
        wall = timed([*command, str(out / "monte_carlo.yaml"), "--out", str(folder), "--quiet"], MPI_ENV)
        print(f"\nMonte Carlo, {arguments.monte_carlo} cases over 2 processes: {wall:.1f} s "
              f"({60 * (arguments.monte_carlo + 1) / wall:.0f} cases per minute)\n")
        with open(folder / "statistics.csv", encoding="utf-8", newline="") as f:
            rows = list(csv.DictReader(f))
        print("| quantity | item | unit | n | mean | p05 | p50 | p95 | p99 | max | limit | P(exceed) |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for row in rows:
            if row["quantity"] == "peak_force" and row["item"] not in ("*",) and not row["item"].startswith("driver."):
                continue
            cells = [row[k] for k in ("quantity", "item", "unit", "n")]
            cells += [f"{float(row[k]):.4g}" if row[k] else "" for k in ("mean", "p05", "p50", "p95", "p99", "max", "limit", "p_exceed")]
            print("| " + " | ".join(cells) + " |")
        members = [r for r in rows if r["quantity"] == "peak_force" and r["item"] != "*" and not r["item"].startswith("driver.")]
        members.sort(key=lambda r: -float(r["p95"]))
        print("\nmembers of largest p95 peak force:")
        for row in members[:5]:
            print(f"  {row['item']}: p50 {float(row['p50']):.4g} N, p95 {float(row['p95']):.4g} N, "
                  f"P(> {row['limit']} N) = {row['p_exceed']}")


if __name__ == "__main__":
    main()
