#!/usr/bin/python3
"""Runs the examples with two deploydyn binaries and says whether their result folders agree.

For refactors that must leave every result unchanged (issue 34): build main as it was, build
the change, then

    scripts/compare_example_results.py BEFORE/deploydyn AFTER/deploydyn [--work DIR] [--quick]

Every model example is run (`run`), every study example studied, and `modes` and `window` are
taken on the paper's parallel linkage. Each pair of folders must hold the same files with the
same bytes, except for what measures the machine rather than the structure (wall times,
thread counts). Exit 0 when all agree, 1 with the differing files listed otherwise.
"""

import argparse
import csv
import json
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# Keys whose values measure the run, not the structure: dropped before comparing JSON.
VOLATILE_KEYS = {"wall_time", "wall_time_s", "elapsed_s", "threads", "started", "finished",
                 "seconds_per_case", "cases_per_second", "host"}
# Lines of text files that carry such values (CSV tables have none; logs may).
VOLATILE_LINE = re.compile(r"wall_time|elapsed|seconds")


def jobs(quick):
    """(name, subcommand arguments) of every run to compare."""
    models, studies = [], []
    for path in sorted((ROOT / "examples").glob("*/*.yaml")):
        text = path.read_text()
        (studies if re.search(r"^model:", text, re.M) else models).append(path)
    out = [(f"run-{p.parent.name}-{p.stem}", ["run", str(p)]) for p in models]
    if not quick:
        out += [(f"study-{p.parent.name}-{p.stem}", ["study", str(p)]) for p in studies]
    parallel = str(ROOT / "examples/paper/parallel.yaml")
    out += [("modes-parallel", ["modes", parallel, "--count", "3"]),
            ("window-parallel", ["window", parallel, "--positions", "5", "--deployments", "3"])]
    return out


def strip_volatile(value):
    if isinstance(value, dict):
        return {k: strip_volatile(v) for k, v in value.items() if k not in VOLATILE_KEYS}
    if isinstance(value, list):
        return [strip_volatile(v) for v in value]
    return value


def csv_without_volatile(path):
    """The table's rows without its columns named in VOLATILE_KEYS (study.csv's wall_time)."""
    rows = list(csv.reader(path.read_text().splitlines()))
    if not rows:
        return rows
    keep = [i for i, name in enumerate(rows[0]) if name not in VOLATILE_KEYS]
    return [[row[i] for i in keep if i < len(row)] for row in rows]


def same_file(a, b):
    if a.read_bytes() == b.read_bytes():
        return True
    if a.suffix == ".json":
        try:
            return strip_volatile(json.loads(a.read_text())) == strip_volatile(
                json.loads(b.read_text()))
        except (ValueError, UnicodeDecodeError):
            return False
    if a.suffix == ".csv":
        return csv_without_volatile(a) == csv_without_volatile(b)
    if a.suffix in (".txt", ".log", ".yaml"):
        keep = lambda p: [l for l in p.read_text().splitlines() if not VOLATILE_LINE.search(l)]
        return keep(a) == keep(b)
    return False


def compare_folders(a, b):
    """Relative paths that differ between folders a and b (missing on one side included)."""
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.is_file()}
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.is_file()}
    differing = sorted(str(p) + " (only on one side)" for p in files_a ^ files_b)
    differing += sorted(str(p) for p in files_a & files_b if not same_file(a / p, b / p))
    return differing


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before", type=pathlib.Path)
    parser.add_argument("after", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/compare-results"))
    parser.add_argument("--quick", action="store_true", help="models, modes and window only")
    args = parser.parse_args()

    shutil.rmtree(args.work, ignore_errors=True)
    failures = []
    for name, command in jobs(args.quick):
        codes = []
        for side, binary in (("before", args.before), ("after", args.after)):
            out = args.work / side / name
            result = subprocess.run([str(binary.resolve()), *command, "--out", str(out)], capture_output=True, text=True)
            codes.append(result.returncode)
        differing = compare_folders(args.work / "before" / name, args.work / "after" / name)
        if codes[0] != codes[1]:
            differing.insert(0, f"exit codes {codes[0]} and {codes[1]}")
        print(f"{'same' if not differing else 'DIFFERENT'}  {name} (exit {codes[1]})")
        failures += [f"{name}: {d}" for d in differing]
    if failures:
        print("\n".join(["", "differences:"] + failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
