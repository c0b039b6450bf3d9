"""Studies over MPI (docs/model-format.md, "Studies over MPI"): `mpirun -n 3 deploydyn study`
writes the same case folders, byte for byte, as the study without MPI; a process killed during
a study loses only its running case, and `--resume` then runs only that case; a sampled study
draws the same cases on 1, 2 and 4 processes.

Skipped, saying why, when mpirun is missing or deploydyn was built without MPI."""
import json
import os
import pathlib
import shutil
import signal
import subprocess
import time

import pytest

from conftest import CLI, SOURCE_DIR, run_cli

MPIRUN = shutil.which("mpirun")
# mpirun refuses root unless told (CI runs as root).
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")


def built_with_mpi():
    if MPIRUN is None or not CLI.exists():
        return False
    # MPI is in a module beside the command's build, loaded under mpirun (docs/performance.md).
    return (CLI.parent / "modules" / "deploydyn_mpi.so").exists()


pytestmark = pytest.mark.skipif(
    not built_with_mpi(),
    reason="needs mpirun and deploydyn's MPI module (deploydyn_mpi.so): apt-get install openmpi-bin libopenmpi-dev "
           "(scripts/install-deps.sh), then build again")


def mpirun(n, *args, extra=(), check=True):
    done = subprocess.run([MPIRUN, "-n", str(n), "--oversubscribe", *extra, str(CLI), *map(str, args)],
                          capture_output=True, text=True, env=MPI_ENV, timeout=300)
    if check:
        assert done.returncode == 0, done.stdout + done.stderr
    return done


def case_files(folder):
    """Every file of every case folder, summary.json without its wall time."""
    files = {}
    for path in sorted(pathlib.Path(folder).glob("*/*")):
        if path.name == ".deploydyn.lock":
            continue
        if path.name == "summary.json":
            summary = json.loads(path.read_text())
            summary.pop("wall_time")
            files[str(path.relative_to(folder))] = json.dumps(summary)
        else:
            files[str(path.relative_to(folder))] = path.read_bytes()
    return files


def table_without_wall_time(folder):
    lines = (pathlib.Path(folder) / "study.csv").read_text().splitlines()
    column = lines[0].split(",").index("wall_time")
    return [",".join(f for i, f in enumerate(line.split(",")) if i != column) for line in lines]


def test_three_processes_write_the_same_case_folders_as_one(tmp_path):
    study = SOURCE_DIR / "examples" / "paper" / "general_study.yaml"
    run_cli("study", study, "--out", tmp_path / "serial", "--quiet")
    done = mpirun(3, "study", study, "--out", tmp_path / "mpi")
    serial, parallel = case_files(tmp_path / "serial"), case_files(tmp_path / "mpi")
    assert sorted(serial) == sorted(parallel)
    assert len(serial) >= 12
    for name in serial:
        assert serial[name] == parallel[name], name
    assert table_without_wall_time(tmp_path / "serial") == table_without_wall_time(tmp_path / "mpi")
    status = json.loads((tmp_path / "mpi" / "study.json").read_text())
    assert status["status"] == "completed"
    # Dynamic scheduling: the other processes ran cases too, and said so.
    processes = {case.get("process", 0) for case in status["cases"].values()}
    assert processes - {0}, status
    assert "(process " in done.stderr


def test_a_study_from_python_over_mpi4py_writes_the_same_case_folders(tmp_path):
    """`mpirun -n 3 python3 script.py` calling deploydyn.run_study(..., comm=MPI.COMM_WORLD)."""
    pytest.importorskip("mpi4py", reason="needs Debian's python3-mpi4py (scripts/install-deps.sh)")
    study = SOURCE_DIR / "examples" / "paper" / "general_study.yaml"
    run_cli("study", study, "--out", tmp_path / "serial", "--quiet")
    script = tmp_path / "study.py"
    script.write_text(
        "import json, sys\n"
        "from mpi4py import MPI\n"
        "import deploydyn\n"
        "cases = deploydyn.run_study(sys.argv[1], out=sys.argv[2], comm=MPI.COMM_WORLD)\n"
        "if MPI.COMM_WORLD.Get_rank() == 0:\n"
        "    print(json.dumps([[c['name'], c['status'], c['process']] for c in cases]))\n"
        "else:\n"
        "    assert cases is None\n")
    env = dict(MPI_ENV, PYTHONPATH=os.pathsep.join(filter(None, [str(pathlib.Path(deploydyn_path())),
                                                                 os.environ.get("PYTHONPATH")])))
    done = subprocess.run([MPIRUN, "-n", "3", "--oversubscribe", "/usr/bin/python3", str(script), str(study),
                           str(tmp_path / "python")], capture_output=True, text=True, env=env, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    cases = json.loads(done.stdout.strip().splitlines()[-1])
    assert all(status == "completed" for _, status, _ in cases), cases
    assert {process for _, _, process in cases} - {0}, "the other processes ran cases too"
    serial, parallel = case_files(tmp_path / "serial"), case_files(tmp_path / "python")
    assert sorted(serial) == sorted(parallel)
    for name in serial:
        assert serial[name] == parallel[name], name
    assert table_without_wall_time(tmp_path / "serial") == table_without_wall_time(tmp_path / "python")


def test_an_error_in_process_0_from_python_ends_every_process(tmp_path):
    """The workers wait for process 0: when it raises (here: its folder is a file), mpi4py's
    Abort ends them all instead of a hang."""
    pytest.importorskip("mpi4py", reason="needs Debian's python3-mpi4py (scripts/install-deps.sh)")
    study = SOURCE_DIR / "examples" / "paper" / "general_study.yaml"
    taken = tmp_path / "a_file"
    taken.write_text("not a folder\n")
    script = tmp_path / "study.py"
    script.write_text("import sys\nfrom mpi4py import MPI\nimport deploydyn\n"
                      "deploydyn.run_study(sys.argv[1], out=sys.argv[2], comm=MPI.COMM_WORLD)\n")
    env = dict(MPI_ENV, PYTHONPATH=os.pathsep.join(filter(None, [str(deploydyn_path()),
                                                                 os.environ.get("PYTHONPATH")])))
    done = subprocess.run([MPIRUN, "-n", "2", "--oversubscribe", "/usr/bin/python3", str(script), str(study),
                           str(taken)], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode != 0, done.stdout + done.stderr
    assert "OutputError" in done.stderr, done.stderr


def deploydyn_path():
    """The folder that holds the package deploydyn this test imports."""
    import deploydyn
    return pathlib.Path(deploydyn.__file__).parent.parent


def slow_study(tmp_path):
    """Four cases of a 3D roof of 4 trusses × 40 units, about 2.5 s each."""
    roof = tmp_path / "roof.yaml"
    run_cli("generate", "roof", "--units", 40, "--trusses", 4, "--out", roof)
    study = tmp_path / "study.yaml"
    study.write_text("model: roof.yaml\ncases:\n" +
                     "".join(f"  dT{t}: {{thermal.dT: {t}, analysis.output_interval: 0.25}}\n"
                             for t in (0, 10, 20, 30)))
    return study


def running_worker_case(out, coordinator_pid):
    """(case folder, pid) of a case a worker process is running, or None."""
    for summary in pathlib.Path(out).glob("*/summary.json"):
        try:
            status = json.loads(summary.read_text())
        except (ValueError, OSError):
            continue
        if status.get("status") == "running" and status.get("pid") not in (None, coordinator_pid):
            return summary.parent, status["pid"]
    return None


def test_a_killed_process_loses_only_its_case_and_resume_runs_only_that(tmp_path):
    study, out = slow_study(tmp_path), tmp_path / "out"
    run = subprocess.Popen([MPIRUN, "-n", "3", "--oversubscribe", "--enable-recovery", str(CLI), "study",
                            str(study), "--out", str(out)],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=MPI_ENV)
    victim = None
    deadline = time.monotonic() + 60
    while victim is None and time.monotonic() < deadline:
        time.sleep(0.05)
        try:
            coordinator = json.loads((out / "study.json").read_text())["pid"]
        except (OSError, ValueError, KeyError):
            continue
        victim = running_worker_case(out, coordinator)
    assert victim is not None, "no worker process started a case"
    killed_case, pid = victim
    os.kill(pid, signal.SIGKILL)
    _, stderr = run.communicate(timeout=120)
    status = json.loads((out / "study.json").read_text())
    assert status["status"] == "failed", stderr
    # Process 0 ends the survivors (MPI cannot finalize with a dead member) and says why; with
    # --enable-recovery mpirun's own exit code stays 0, study.json tells.
    assert "died; its case is listed as failed" in stderr, stderr
    lost = status["cases"][killed_case.name]
    assert lost["status"] == "failed" and "died while running this case" in lost["message"], lost
    others = {name: case for name, case in status["cases"].items() if name != killed_case.name}
    assert all(case["status"] == "completed" for case in others.values()), status
    kept = {name: (out / name / "history.csv").stat().st_mtime_ns for name in others}

    resumed = run_cli("study", study, "--out", out, "--resume")
    status = json.loads((out / "study.json").read_text())
    assert status["status"] == "completed"
    assert status["cases"][killed_case.name].get("resumed") is None
    assert all(status["cases"][name].get("resumed") for name in others)
    assert {name: (out / name / "history.csv").stat().st_mtime_ns for name in others} == kept
    assert f"{killed_case.name}: completed" in resumed.stderr
    assert "3 by an earlier run" in resumed.stderr
    rows = {line.split(",")[0]: line for line in (out / "study.csv").read_text().splitlines()[1:]}
    assert all(",completed," in rows[name] for name in status["cases"])


def test_a_sampled_study_draws_the_same_cases_on_any_number_of_processes(tmp_path):
    roof = tmp_path / "roof.yaml"
    run_cli("generate", "roof", "--units", 2, "--trusses", 2, "--out", roof)
    text = roof.read_text().replace("  end: 5\n", "  end: 0.05\n")
    roof.write_text(text)
    study = tmp_path / "sampled.yaml"
    study.write_text("model: roof.yaml\n"
                     "sampling:\n"
                     "  cases: 6\n"
                     "  seed: 5\n"
                     "  length_error: [{elements: '*', normal: 2e-5}]\n"
                     "  temperature: {dT: [100, 160], gradient: {direction: [0, 0, 1], dT: [0, 20]}, scatter: 2}\n"
                     "  material: {E: 0.03}\n")
    run_cli("study", study, "--out", tmp_path / "n1", "--quiet")
    for n in (2, 4):
        mpirun(n, "study", study, "--out", tmp_path / f"n{n}", "--quiet")
    reference = case_files(tmp_path / "n1")
    assert len([name for name in reference if name.endswith("model.yaml")]) == 7
    for n in (2, 4):
        folder = tmp_path / f"n{n}"
        assert (folder / "samples.csv").read_bytes() == (tmp_path / "n1" / "samples.csv").read_bytes()
        assert (folder / "statistics.csv").read_bytes() == (tmp_path / "n1" / "statistics.csv").read_bytes()
        assert case_files(folder) == reference
