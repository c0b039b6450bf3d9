#!/usr/bin/python3
"""A light start: wall time and peak memory of short deploydyn processes, old and new binaries
interleaved (docs/performance.md, "A light start").

Every measured process is started by a small C timer built here (fork, exec, wait4; no
shell), so its wall time is fork to exit and its max RSS is the kernel's ru_maxrss of that
process alone. (Spawned from Python itself, a child's ru_maxrss starts at the interpreter's
~10 MB: Linux carries the high-water mark over from the forking process.) "bare" is a
C++ program whose main returns at once, built here with the same compiler (c++ -O2, dynamically
linked to libstdc++ like deploydyn): what any process costs on this machine.

Cases: `--version`; `run` of the paper's general four-bar (5 s at h = 1 ms, 5 000 steps, as
the paper's demo runs it) and of the same for 10 ms (10 steps: nearly all start and finish);
`check` of the four-bar; the paper's six runs as `make demo` runs them (scripts/paper_demo.py:
two `study` processes, one per linkage, one after the other).

Usage: bench/light_start_bench.py --new build/release/deploydyn [--old OLD] [--rounds 8]
       [--repetitions 5]
Prints per case the medians (wall, CPU = user + system, max RSS) over all rounds (each round's value is the median of its
repetitions), the per-round ratios new/old, and the load average at each round.
"""

import argparse
import os
import pathlib
import shutil
import statistics
import subprocess
import tempfile

TIMER = None  # built by build_helpers
ROOT = pathlib.Path(__file__).resolve().parent.parent
PAPER = ROOT / "examples" / "paper"


TIMER_SOURCE = r"""
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>
int main(int argc, char** argv) {
  (void)argc;
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  pid_t pid = fork();
  if (pid == 0) {
    int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execv(argv[1], argv + 1);
    _exit(127);
  }
  int status;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  clock_gettime(CLOCK_MONOTONIC, &end);
  printf("%.9f %ld %d %.6f\n", (end.tv_sec - start.tv_sec) + 1e-9 * (end.tv_nsec - start.tv_nsec),
         usage.ru_maxrss, WIFEXITED(status) ? WEXITSTATUS(status) : 128,
         usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec));
  return 0;
}
"""


def spawn(argv):
    """(wall s, max RSS kB, CPU s: user + system) of one process, by the C timer; output discarded."""
    line = subprocess.run([TIMER, *argv], check=True, capture_output=True, text=True).stdout.split()
    if line[2] != "0":
        raise SystemExit(f"{' '.join(argv)} exited with {line[2]}")
    return float(line[0]), int(line[1]), float(line[3])


def build_helpers(work):
    """The timer and the bare process, both built with the system's compilers."""
    global TIMER
    work = pathlib.Path(work)
    (work / "timer.c").write_text(TIMER_SOURCE)
    TIMER = str(work / "timer")
    subprocess.run(["cc", "-O2", "-o", TIMER, str(work / "timer.c")], check=True)
    (work / "bare.cpp").write_text("int main() { return 0; }\n")
    subprocess.run(["c++", "-O2", "-o", str(work / "bare"), str(work / "bare.cpp")], check=True)
    return str(work / "bare")


def cases(cli, work):
    out = pathlib.Path(work) / "out"
    four_bar = str(PAPER / "general.yaml")

    def fresh(*argv):
        def run():
            shutil.rmtree(out, ignore_errors=True)
            return spawn([cli, *argv])
        return run

    def demo():
        # scripts/paper_demo.py's run_study for both linkages, one after the other.
        wall, rss, cpu = 0.0, 0, 0.0
        for linkage in ("general", "parallel"):
            shutil.rmtree(out, ignore_errors=True)
            w, r, c = spawn([cli, "study", str(PAPER / f"{linkage}_study.yaml"), "--out", str(out), "--quiet"])
            wall, rss, cpu = wall + w, max(rss, r), cpu + c
        return wall, rss, cpu

    return {
        "--version": fresh("--version"),
        "run four-bar 5 s": fresh("run", four_bar, "--out", str(out), "--quiet"),
        "run four-bar 10 ms": fresh("run", four_bar, "--out", str(out), "--quiet", "--set", "analysis.end=0.01"),
        "check four-bar": fresh("check", four_bar),
        "demo: two studies": demo,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--new", required=True, help="the deploydyn binary measured")
    parser.add_argument("--old", help="a deploydyn binary to compare with, run interleaved")
    parser.add_argument("--rounds", type=int, default=8)
    parser.add_argument("--repetitions", type=int, default=5, help="runs per case, binary and round")
    args = parser.parse_args()
    binaries = {"new": os.path.abspath(args.new)}
    if args.old:
        binaries["old"] = os.path.abspath(args.old)
    with tempfile.TemporaryDirectory() as work:
        bare = build_helpers(work)
        suites = {name: cases(cli, os.path.join(work, name)) for name, cli in binaries.items()}
        for name in binaries:
            os.makedirs(os.path.join(work, name))
        names = list(suites["new"])
        # rounds[case][binary] = list of (wall, rss), one per round (median of the repetitions)
        rounds = {case: {b: [] for b in ("bare", *binaries)} for case in names}
        loads = []
        for _ in range(args.rounds):
            loads.append(os.getloadavg()[0])
            for case in names:
                for binary in ("bare", *binaries):
                    samples = [spawn([bare]) if binary == "bare" else suites[binary][case]()
                               for _ in range(args.repetitions)]
                    rounds[case][binary].append(tuple(statistics.median(s[k] for s in samples) for k in range(3)))
    print(f"{args.rounds} rounds × {args.repetitions} repetitions; load average (1 min) per round: "
          + " ".join(f"{load:.2f}" for load in loads))
    header = "| case | bare ms | bare CPU ms | " + " | ".join(
        f"{b} ms | {b} − bare ms | {b} CPU ms | {b} max RSS MB | {b} − bare MB" for b in binaries)
    if "old" in binaries:
        header += " | new/old per round"
    print(header + " |")
    print("|" + "---|" * (header.count("|")))
    for case in names:
        def median(binary, k):
            return statistics.median(sample[k] for sample in rounds[case][binary])
        bare_ms, bare_mb = median("bare", 0) * 1e3, median("bare", 1) / 1024
        row = f"| {case} | {bare_ms:.2f} | {median('bare', 2) * 1e3:.2f} |"
        for b in binaries:
            ms, mb = median(b, 0) * 1e3, median(b, 1) / 1024
            row += f" {ms:.2f} | {ms - bare_ms:.2f} | {median(b, 2) * 1e3:.2f} | {mb:.1f} | {mb - bare_mb:.1f} |"
        if "old" in binaries:
            ratios = [n[0] / o[0] for n, o in zip(rounds[case]["new"], rounds[case]["old"])]
            row += " " + " ".join(f"{r:.2f}" for r in ratios) + " |"
        print(row)


if __name__ == "__main__":
    main()
