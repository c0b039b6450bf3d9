#!/usr/bin/python3
"""Runs the member-check examples (examples/checks/) and prints their verdicts: does each structure
deploy, and if not, what fails first (docs/model-format.md, "Member checks and the verdict").

Usage: scripts/checks_demo.py [--cli build/release/deploydyn] [--out results/checks]
Exit status 0 when every run completed (a verdict that the structure does not deploy is a result,
not an error), 1 otherwise.
"""

import argparse
import json
import pathlib
import subprocess
import sys

from demo_verdict import print_verdicts

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "deploydyn"))
    parser.add_argument("--out", default=str(ROOT / "results" / "checks"))
    args = parser.parse_args()
    rows, ok = [], True
    for model in sorted((ROOT / "examples" / "checks").glob("*.yaml")):
        folder = pathlib.Path(args.out) / model.stem
        print(f"running deploydyn run examples/checks/{model.name} ...", file=sys.stderr)
        completed = subprocess.run([args.cli, "run", str(model), "--out", str(folder), "--quiet"],
                                   capture_output=True, text=True)
        summary_file = folder / "summary.json"
        summary = json.loads(summary_file.read_text()) if summary_file.exists() else None
        if completed.returncode != 0 or summary is None:
            ok = False
            print(f"{model.name}: did not complete: {completed.stderr.strip()}", file=sys.stderr)
        rows.append((model.stem, summary))
    print(f"\nmember checks: results in {args.out}/<example>/")
    print_verdicts(rows)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
