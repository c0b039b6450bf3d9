#!/usr/bin/python3
"""`make bench`: runs the Google Benchmark programs in bench/ and prints the table of medians.

Sections: the paper's six runs (target < 50 ms) and the four-bar's time per step per back end;
the roofs (time per step, Newton iterations, time per Newton iteration against one numeric
refactorization (target <= 2x), KLU vs UMFPACK, assembly / residual / solve, memory per bar);
the fitted scaling exponent of the time per step in the number of bars (target <= 1.2); dense
vs KLU on small roofs; the writer's cost per value; the study speed-ups; each element type's
work per Newton iteration (bar and beam, 2D and 3D); scissor arches of 10 to 1000 units per step.
Medians over --repetitions runs (machines are noisy).
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys


def run(binary, pattern, repetitions, min_time=None):
    """Medians of the benchmarks matching `pattern`, by name (aggregate suffix removed)."""
    command = [str(binary), f"--benchmark_filter={pattern}", "--benchmark_format=json",
               f"--benchmark_repetitions={repetitions}", "--benchmark_report_aggregates_only=true"]
    if min_time is not None:
        command.append(f"--benchmark_min_time={min_time}")
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    results = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name", "median") == "median" and "error_occurred" not in b:
            results[b["run_name"]] = b
    return results


def to_us(b):
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b["time_unit"]]
    return b["real_time"] * scale


def fit_exponent(points):
    """Least-squares slope of log(time) against log(bars)."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def roof_name(units, trusses):
    return f"{units} units" if trusses == 1 else f"{trusses} x {units} (3D)"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/release/bench/deploydyn_bench")
    parser.add_argument("--repetitions", type=int, default=3)
    args = parser.parse_args()
    binary = pathlib.Path(args.binary)
    reps = args.repetitions

    print("## The paper's four-bar linkages\n")
    paper = run(binary, "BM_Paper|BM_GeneralLinkage", reps)
    six = paper["BM_PaperSixRuns/real_time"]
    print(f"six paper runs end to end (read, run, write), one after another: {to_us(six) / 1e3:.1f} ms "
          f"(target < 50 ms), {six['us_per_step']:.2f} us per step")
    studies = paper["BM_PaperStudies/real_time"]
    print(f"the same six as make demo runs them (two studies, 3 cases each, all at once): "
          f"{to_us(studies) / 1e3:.1f} ms")
    for kind, name in ((1, "dense LU"), (2, "KLU"), (3, "UMFPACK")):
        b = paper[f"BM_GeneralLinkageSolverOnly/solver:{kind}/real_time"]
        print(f"general linkage, solver only, {name:8}: {b['us_per_step']:.2f} us per step, "
              f"{b['newton_per_step']:.3f} Newton iterations per step")

    print("\n## Roofs (KLU; refactorization also with UMFPACK)\n")
    roofs = run(binary, "BM_Roof(Step|Assembly|Residual|Factor|Solve)/", reps)
    sizes = [(u, 1) for u in (10, 100, 1000, 10000)] + [(u, 10) for u in (3, 26, 263, 2630)]
    print("| roof | bars | unknowns | step us | Newton/step | per iteration us | KLU refactor us "
          "| iteration / refactor | UMFPACK refactor us | UMFPACK / KLU | assembly us | residual us "
          "| KLU solve us | heap B/bar | allocations/step |")
    print("|" + "---|" * 15)
    series = {1: [], 10: []}
    for units, trusses in sizes:
        key = f"units:{units}/trusses:{trusses}/solver:"
        step = roofs[f"BM_RoofStep/{key}2"]
        klu = roofs[f"BM_RoofFactor/{key}2"]
        umf = roofs[f"BM_RoofFactor/{key}3"]
        per_iteration = to_us(step) / step["newton_per_step"]
        series[trusses].append((step["bars"], to_us(step)))
        print(f"| {roof_name(units, trusses)} | {step['bars']:.0f} | {step['unknowns']:.0f} "
              f"| {to_us(step):.1f} | {step['newton_per_step']:.2f} | {per_iteration:.1f} "
              f"| {to_us(klu):.1f} | {per_iteration / to_us(klu):.2f} | {to_us(umf):.1f} "
              f"| {to_us(umf) / to_us(klu):.1f} | {to_us(roofs[f'BM_RoofAssembly/{key}2']):.1f} "
              f"| {to_us(roofs[f'BM_RoofResidual/{key}2']):.1f} "
              f"| {to_us(roofs[f'BM_RoofSolve/{key}2']):.1f} | {step['heap_bytes_per_bar']:.0f} "
              f"| {step['allocations_per_step']:.3f} |")

    print("\nscaling of the time per step in the number of bars (least squares, log-log; target <= 1.2):")
    planar = [p for p in series[1] if p[0] >= 100]
    print(f"  planar roofs, {planar[0][0]:.0f} to {planar[-1][0]:.0f} bars: exponent {fit_exponent(planar):.3f}")
    print(f"  3D roofs of 10 trusses, {series[10][0][0]:.0f} to {series[10][-1][0]:.0f} bars: "
          f"exponent {fit_exponent(series[10]):.3f}")

    # Peak memory of the largest roof, alone in its process (the RSS peak is per process).
    largest = run(binary, "BM_RoofStep/units:2630/trusses:10/solver:2$", 1, min_time=0.01)
    b = next(iter(largest.values()))
    print(f"\nmemory at {b['bars']:.0f} bars: peak resident {b['peak_rss_bytes_per_bar']:.0f} B/bar "
          f"(whole process), heap held by the run {b['heap_bytes_per_bar']:.0f} B/bar (target < 4 kB)")

    print("\n## Small roofs: dense LU against KLU (time per step)\n")
    small = run(binary, "BM_SmallRoofStep", reps)
    for units in (1, 3, 10, 30):
        dense = small[f"BM_SmallRoofStep/units:{units}/trusses:1/solver:1"]
        klu = small[f"BM_SmallRoofStep/units:{units}/trusses:1/solver:2"]
        print(f"  {units:2} units ({dense['unknowns']:.0f} unknowns): dense {to_us(dense):.2f} us, "
              f"KLU {to_us(klu):.2f} us, KLU/dense {to_us(klu) / to_us(dense):.2f}")

    print("\n## Output: the writer thread's work per output time (planar roof, 100 units)\n")
    output = run(binary, "BM_MakeStepRecord|BM_HistoryRow", reps)
    for name, what in (("BM_MakeStepRecord", "building the record"),
                       ("BM_HistoryRow", "formatting and writing the history.csv row")):
        b = output[name]
        print(f"  {what}: {to_us(b):.1f} us, {b['ns_per_value'] * 1e9:.1f} ns per value")

    print("\n## Load-case studies: one after another, one per core, all at once (the default)\n")
    study = run(binary, "BM_RoofStudy", reps)
    for trusses, roof in ((1, "planar roof, 100 units, 0.5 s"), (10, "3D roof, 10 x 26 units, 0.2 s")):
        for cases in (3, 4):
            key = f"BM_RoofStudy/trusses:{trusses}/cases:{cases}"
            one = to_us(study[f"{key}/jobs:1/real_time"])
            two = to_us(study[f"{key}/jobs:2/real_time"])
            every = to_us(study[f"{key}/jobs:{cases}/real_time"])
            print(f"  {roof}, {cases} cases: one after another {one / 1e3:.0f} ms; two at a time "
                  f"{two / 1e3:.0f} ms (speed-up {one / two:.2f}); all at once {every / 1e3:.0f} ms "
                  f"(speed-up {one / every:.2f})")

    print("\n## Elements: one Newton iteration's work per element (force, iteration-matrix block)\n")
    elements = run(binary, "BM_Element", reps)
    print("| element | force ns | matrix ns | sum ns | sum / bar of the same dimension |")
    print("|---|---|---|---|---|")
    for dimension in (2, 3):
        bar_sum = None
        for kind, name in ((0, "bar"), (1, "beam")):
            force = elements[f"BM_ElementForce/{kind}/{dimension}"]["per_element"] * 1e9
            matrix = elements[f"BM_ElementMatrix/{kind}/{dimension}"]["per_element"] * 1e9
            bar_sum = bar_sum or force + matrix
            print(f"| {name} {dimension}D | {force:.1f} | {matrix:.1f} | {force + matrix:.1f} | "
                  f"{(force + matrix) / bar_sum:.1f} |")

    print("\n## Scissor arches (polar units, 2 beams per arm): one generalized-α step\n")
    scissor = run(binary, "BM_ScissorStep", reps)
    for units in (10, 100, 1000):
        b = scissor[f"BM_ScissorStep/units:{units}"]
        print(f"  {units:4} units ({b['beams']:.0f} beams, {b['unknowns']:.0f} unknowns): "
              f"{to_us(b):.0f} us per step, {b['newton_per_step']:.2f} Newton iterations per step")

    print("\n## Hinges and cables: a chain falling from the horizontal, one run-loop step (mode switches included)\n")
    print("| bars | variant | us per step | vs bars alone | Newton per step | steps redone per step |")
    print("|---|---|---|---|---|---|")
    hinged = run(binary, "BM_HingedChain", reps)
    for bars in (10, 100):
        alone = hinged[f"BM_HingedChain/variant:0/bars:{bars}"]["per_step"]
        for variant in (0, 1, 2, 3):
            b = hinged.get(f"BM_HingedChain/variant:{variant}/bars:{bars}")
            if b is None:  # an error, e.g. Newton failing (the benchmark's label says which)
                print(f"| {bars} | variant {variant} | failed | | | |")
                continue
            print(f"| {bars} | {b['label']} | {b['per_step'] * 1e6:.1f} | {b['per_step'] / alone:.1f} | "
                  f"{b['newton_per_step']:.2f} | {b['switches_per_step']:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
