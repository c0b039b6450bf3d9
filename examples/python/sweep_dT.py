#!/usr/bin/python3
"""ΔT sweep of the general four-bar linkage: peak coupler strain and peak driver torque vs ΔT.

Runs examples/paper/general.yaml at ΔT = −170, −160, ..., +130 °C through the Python bindings
(in memory, nothing written but the plot), prints a table and draws into one PNG:
  - the peak total and mechanical strain of the coupler, element 2 (signed: the value of
    largest magnitude over the run, µε);
  - the peak driver torque (largest magnitude, N·m).
It reports how long the sweep took. Runs go in parallel threads (the bindings release the GIL).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/sweep_dT.py --out sweep_dT.png
    ... --values -170 0 130 --end 0.5      # a quick, coarse sweep
"""
import argparse
import concurrent.futures
import os
import pathlib
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
import numpy as np  # noqa: E402

import deploydyn  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
COUPLER = "2"
MICRO = 1e6  # strain → µε


def peaks(model, dT):
    """Run `model` at ΔT = dT; return the coupler's peak strains and the peak torque."""
    result = model.with_overrides({"thermal.dT": dT}).run()
    driver = next(iter(model.drivers))
    return {"dT": dT, "status": result.status, "message": result.message,
            "strain": result.extreme(f"strain.{COUPLER}"),
            "mstrain": result.extreme(f"mstrain.{COUPLER}"),
            "torque": abs(result.extreme(f"torque.{driver}")),
            "wall": result.summary["wall_time"]}


def plot(rows, out, title):
    """Peak strains and torque against ΔT, three panels; failed runs are left out."""
    done = [r for r in rows if r["status"] == "completed"]
    dT = np.array([r["dT"] for r in done])
    fig, (total, mechanical, torque) = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    # Two panels for the strains: the total follows αΔT (thousands of µε), the mechanical
    # part (what stresses the bar) is a hundred times smaller.
    for ax, key, style, colour, label in (
            (total, "strain", "o-", "C0", "total strain ε"),
            (mechanical, "mstrain", "s-", "C3", "mechanical strain ε − αΔT")):
        ax.plot(dT, [r[key] * MICRO for r in done], style, color=colour, label=label)
        ax.set_ylabel(f"element {COUPLER}: {key.replace('mstrain', 'ε_m').replace('strain', 'ε')}"
                      " peak (µε)")
        ax.legend(title=f"element {COUPLER} (coupler), value of largest magnitude",
                  fontsize=9, title_fontsize=8)
        ax.grid(True, alpha=0.3)
    total.axhline(0, color="grey", linewidth=0.8)
    torque.plot(dT, [r["torque"] for r in done], "o-", color="C2", label="peak |driver torque|")
    torque.set_ylabel("driver torque peak (N·m)")
    torque.set_xlabel("temperature change ΔT (°C)")
    torque.legend(fontsize=9)
    torque.grid(True, alpha=0.3)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    pathlib.Path(out).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=str(ROOT / "examples" / "paper" / "general.yaml"))
    parser.add_argument("--values", type=float, nargs="+", metavar="DT",
                        help="ΔT values (°C); default −170 to +130 in steps of 10")
    parser.add_argument("--end", type=float, help="end time (s); default the model's")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="runs at once (threads; default: the number of CPUs)")
    parser.add_argument("--out", default="sweep_dT.png", help="the PNG to write")
    args = parser.parse_args()

    values = args.values if args.values else [float(v) for v in range(-170, 131, 10)]
    overrides = {"analysis.end": args.end} if args.end else {}
    model = deploydyn.load(args.model, overrides=overrides)

    start = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        rows = list(pool.map(lambda dT: peaks(model, dT), values))
    wall = time.perf_counter() - start

    print(f"{model.name}, {len(values)} runs of 0-{model.analysis['end']:g} s")
    print(f"{'ΔT °C':>7} {'ε peak µε':>11} {'ε_m peak µε':>12} {'|torque| N·m':>13} "
          f"{'solver s':>9}  status")
    for r in rows:
        print(f"{r['dT']:7.0f} {r['strain'] * MICRO:11.2f} {r['mstrain'] * MICRO:12.3f} "
              f"{r['torque']:13.5f} {r['wall']:9.3f}  {r['status']}")
    plot(rows, args.out, f"{model.name}: peaks over 0–{model.analysis['end']:g} s against ΔT "
                         f"({len(values)} runs)")
    print(f"sweep: {len(values)} runs in {wall:.2f} s wall time with {args.jobs} thread(s) "
          f"({sum(r['wall'] for r in rows):.2f} s in the solver); plot in {args.out}")
    failed = [r for r in rows if r["status"] != "completed"]
    for r in failed:
        print(f"ΔT = {r['dT']:+g} °C: {r['message']}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
