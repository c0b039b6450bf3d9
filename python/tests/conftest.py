"""Shared fixtures of the Python tests; run by CTest (python/CMakeLists.txt), which sets
PYTHONPATH to the built package, DEPLOYDYN_CLI to the command and DEPLOYDYN_SOURCE_DIR.
By hand, from the source tree:

    PYTHONPATH=build/release/python DEPLOYDYN_CLI=build/release/deploydyn \\
        /usr/bin/python3 -m pytest -q python/tests
"""
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("DEPLOYDYN_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("DEPLOYDYN_CLI", SOURCE_DIR / "build" / "release" / "deploydyn"))
GENERAL = SOURCE_DIR / "examples" / "paper" / "general.yaml"
# A von Mises truss loaded by continuation through its snap-through: the path, its two limit
# points and statics in closed form (the continuation tests, the plot and report of its folder).
MISES = """
name: von Mises truss
nodes: {A: [-1, 0], B: [1, 0], C: [0, 0.1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  1: {nodes: [A, C], area: 1.0e-4, material: steel, mass: 1}
  2: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A}, {node: B}]
loads: [{node: C, force: [0, -1.0e+4]}]
analysis: {type: continuation, parameter: load, end: 1.1, eigenvalues: 2}
"""


def pytest_sessionfinish(session, exitstatus):
    """No test collected (pytest's exit code 5) is a failure, not a pass or a skip."""
    if exitstatus == pytest.ExitCode.NO_TESTS_COLLECTED:
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def general_model():
    return GENERAL


def run_cli(*args, check=True):
    """The deploydyn command with `args`; returns the CompletedProcess."""
    assert CLI.exists(), f"no deploydyn command at {CLI}: build first or set DEPLOYDYN_CLI"
    done = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    if check:
        assert done.returncode == 0, done.stderr
    return done


def read_history(path):
    """(columns, values) of a history.csv."""
    with open(path, encoding="utf-8") as f:
        columns = f.readline().strip().split(",")
    return columns, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)

