"""A result folder never claims what its files do not show (issue 11), from Python's side:
readers accept a history whose last row a killed run cut off (left out, with a warning) and
refuse a malformed row elsewhere; a folder whose run died says "killed"; the plot and animation
scripts do the same without a traceback; results that cannot be written raise OutputError."""
import errno
import fcntl
import json
import os
import shutil
import signal
import subprocess
import sys
import time
import warnings

import numpy as np
import pytest

import deploydyn
from conftest import CLI, SOURCE_DIR

SCRIPTS = SOURCE_DIR / "scripts"
PNG = b"\x89PNG\r\n\x1a\n"
LOCK = ".deploydyn.lock"
END = 0.2  # s: 41 output rows of a one-unit roof


@pytest.fixture(scope="module")
def completed(tmp_path_factory):
    """A completed run's folder (history.csv, summary.json, model.yaml, the lock file)."""
    folder = tmp_path_factory.mktemp("completed") / "roof"
    deploydyn.roof(1, overrides={"analysis.end": END}).run(out=folder, check=True)
    return folder


@pytest.fixture
def folder(completed, tmp_path):
    """A copy of the completed run's folder, to damage."""
    copy = tmp_path / "run"
    shutil.copytree(completed, copy)
    return copy


def history_parts(folder):
    """(header line, data lines) of the folder's history, each with its newline."""
    lines = (folder / "history.csv").read_text(encoding="utf-8").splitlines(keepends=True)
    assert len(lines) > 10 and all(line.endswith("\n") for line in lines)
    return lines[0], lines[1:]


def claim_running(folder, status_file="summary.json"):
    """The status file a run writes at its start, as a killed run leaves it."""
    (folder / status_file).write_text(json.dumps(
        {"model": "roof", "status": "running", "pid": 999999, "host": "elsewhere",
         "started": "2026-01-01T00:00:00Z", "message": "running"}))


def hold_lock(folder):
    """An open file holding the folder's lock, as a live run does (another open file
    description of the same file conflicts with it, even in this process)."""
    lock = open(folder / LOCK, "a")
    fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    return lock


def lock_is_free(folder):
    with open(folder / LOCK, "a") as probe:
        try:
            fcntl.flock(probe, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
        fcntl.flock(probe, fcntl.LOCK_UN)
        return True


# ---------------------------------------------------------------------------------------------
# Incomplete and malformed histories


def cut_without_newline(last):
    return last[:-1]


def cut_mid_number(last):
    fields = last.split(",")
    return ",".join(fields[:3]) + "," + fields[3][:4]     # e.g. "0.28" of "0.2869..."


def missing_fields(last):
    return ",".join(last.split(",")[:5]) + "\n"


def unparseable_field(last):
    fields = last.split(",")
    return ",".join(fields[:-2] + ["1.5e", fields[-1]])


@pytest.mark.parametrize("damage", [cut_without_newline, cut_mid_number, missing_fields,
                                    unparseable_field])
def test_incomplete_last_row_is_left_out_with_a_warning(folder, damage):
    complete = deploydyn.read_result(folder)
    header, rows = history_parts(folder)
    (folder / "history.csv").write_text(header + "".join(rows[:-1]) + damage(rows[-1]))
    with pytest.warns(deploydyn.IncompleteHistoryWarning, match=r"history\.csv.*last row"):
        result = deploydyn.read_result(folder)
    assert issubclass(deploydyn.IncompleteHistoryWarning, RuntimeWarning)
    assert result.n_dropped_rows == 1
    assert result.values.shape == (len(rows) - 1, len(complete.columns))
    np.testing.assert_array_equal(result.values, complete.values[:-1])
    assert result.columns == complete.columns


def test_a_complete_history_gives_no_warning(folder):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = deploydyn.read_result(folder)
    assert result.n_dropped_rows == 0
    assert result.ok and result.status == "completed"


def test_only_the_header_and_a_cut_row(folder):
    header, rows = history_parts(folder)
    (folder / "history.csv").write_text(header + rows[0][:7])
    with pytest.warns(deploydyn.IncompleteHistoryWarning):
        result = deploydyn.read_result(folder)
    assert result.values.shape == (0, len(header.split(",")))
    assert result.n_dropped_rows == 1


@pytest.mark.parametrize("bad, problem", [
    ("1,2,3\n", r"3 fields, expected \d+"),
    ("0.1,abc{rest}", r"column x\.b0: 'abc' is not a number"),
])
def test_malformed_middle_row_is_an_error_naming_file_and_line(folder, bad, problem):
    header, rows = history_parts(folder)
    rest = rows[5][rows[5].index(",", rows[5].index(",") + 1):]
    rows[5] = bad.format(rest=rest)               # line 7: the header is line 1
    (folder / "history.csv").write_text(header + "".join(rows))
    with pytest.raises(ValueError, match=rf"history\.csv:7: {problem}"):
        deploydyn.read_result(folder)


def test_a_cut_header_is_an_error(folder):
    header, _ = history_parts(folder)
    (folder / "history.csv").write_text(header[:20])
    with pytest.raises(ValueError, match=r"history\.csv:1: no complete header row"):
        deploydyn.read_result(folder)


# ---------------------------------------------------------------------------------------------
# Folder status


def test_running_without_a_lock_holder_reads_killed(folder):
    claim_running(folder)
    assert deploydyn.folder_status(folder) == "killed"
    result = deploydyn.read_result(folder)
    assert result.status == "killed"
    assert not result.ok
    assert "did not finish" in result.message
    with pytest.raises(deploydyn.RunFailed):
        result.raise_for_status()
    assert lock_is_free(folder)                    # the probe let go of the lock


def test_running_with_a_lock_holder_reads_running(folder):
    claim_running(folder)
    lock = hold_lock(folder)
    try:
        assert deploydyn.folder_status(folder) == "running"
        assert deploydyn.read_result(folder).status == "running"
        assert not lock_is_free(folder)            # still ours: the probe took nothing
    finally:
        lock.close()
    assert deploydyn.folder_status(folder) == "killed"


def test_lock_held_by_another_process_until_it_dies(folder):
    claim_running(folder)
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import fcntl, sys\n"
         f"lock = open({str(folder / LOCK)!r}, 'a')\n"
         "fcntl.flock(lock, fcntl.LOCK_EX)\n"
         "print('locked', flush=True)\n"
         "sys.stdin.read()\n"],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        assert deploydyn.folder_status(folder) == "running"
    finally:
        holder.kill()
        holder.wait()
    assert deploydyn.folder_status(folder) == "killed"


def test_missing_lock_file_or_status_file(folder):
    claim_running(folder)
    (folder / LOCK).unlink()
    assert deploydyn.folder_status(folder) == "killed"
    (folder / "summary.json").unlink()
    assert deploydyn.folder_status(folder) == "unknown"
    result = deploydyn.read_result(folder)           # the history still reads
    assert result.status == "unknown" and not result.ok
    assert result.summary == {}
    assert result.values.shape[0] > 10


def test_final_statuses_are_taken_as_written(folder):
    for status in ("completed", "failed", "interrupted"):
        summary = json.loads((folder / "summary.json").read_text())
        summary["status"] = status
        (folder / "summary.json").write_text(json.dumps(summary))
        assert deploydyn.folder_status(folder) == status


def test_a_study_folder_has_its_status_in_study_json(tmp_path):
    claim_running(tmp_path, "study.json")
    (tmp_path / LOCK).touch()
    assert deploydyn.folder_status(tmp_path) == "killed"
    (tmp_path / "study.json").write_text('{"status": "completed"}')
    assert deploydyn.folder_status(tmp_path) == "completed"
    assert deploydyn.folder_status(tmp_path / "nothing") == "unknown"


def test_a_killed_folder_can_be_run_into_again(folder):
    claim_running(folder)
    assert deploydyn.folder_status(folder) == "killed"
    result = deploydyn.roof(1, overrides={"analysis.end": 0.05}).run(out=folder)
    assert result.status == "completed"
    assert deploydyn.folder_status(folder) == "completed"


def test_a_killed_command_line_run_reads_killed(tmp_path):
    """The real thing: `deploydyn run` owns the folder while it runs; SIGKILL leaves
    summary.json saying "running", which readers then report as "killed"."""
    assert CLI.exists(), f"no deploydyn command at {CLI}"
    roof = tmp_path / "roof.yaml"
    deploydyn.roof(2).save(roof)
    out = tmp_path / "out"
    run = subprocess.Popen([str(CLI), "run", str(roof), "--quiet", "--out", str(out), "--set",
                            "analysis.step=1e-5", "--set", "analysis.output_interval=1e-5"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            history = out / "history.csv"
            if history.exists() and history.stat().st_size > 50_000:
                break
            time.sleep(0.02)
        else:
            pytest.fail("the run wrote no history within 30 s")
        assert deploydyn.folder_status(out) == "running"
        assert run.poll() is None, "the run ended before it could be killed"
    finally:
        run.send_signal(signal.SIGKILL)
        run.wait()
    assert deploydyn.folder_status(out) == "killed"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", deploydyn.IncompleteHistoryWarning)
        result = deploydyn.read_result(out)
    assert result.status == "killed" and not result.ok
    assert result.values.shape[0] > 10
    assert np.all(np.isfinite(result.values))
    assert np.all(np.diff(result.t) > 0)


# ---------------------------------------------------------------------------------------------
# The scripts


def script(name, *args):
    return subprocess.run([sys.executable, str(SCRIPTS / name), *map(str, args)],
                          capture_output=True, text=True)


@pytest.fixture
def killed(folder):
    """A killed run's folder: status "running" with no lock holder, last row cut mid-number."""
    header, rows = history_parts(folder)
    (folder / "history.csv").write_text(header + "".join(rows[:-1]) + cut_mid_number(rows[-1]))
    claim_running(folder)
    return folder


def test_plot_draws_a_killed_run_and_says_so(killed, tmp_path):
    done = script("deploydyn_plot.py", killed, "--out", tmp_path / "plots", "--format", "png")
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    assert f"{killed}: status killed (the run did not finish" in done.stderr
    assert done.stderr.count("status killed") == 1                  # once, not per figure
    assert "incomplete last row left out" in done.stderr
    assert (tmp_path / "plots" / "strain.png").read_bytes()[:8] == PNG


def test_plot_of_a_completed_run_says_completed(completed, tmp_path):
    done = script("deploydyn_plot.py", completed, "--out", tmp_path, "--what", "strain",
                  "--format", "png")
    assert done.returncode == 0, done.stderr
    assert f"{completed}: status completed" in done.stderr


def test_plot_refuses_a_malformed_history_without_a_traceback(folder, tmp_path):
    header, rows = history_parts(folder)
    rows[3] = "1,2\n"
    (folder / "history.csv").write_text(header + "".join(rows))
    done = script("deploydyn_plot.py", folder, "--out", tmp_path)
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert "history.csv:5: 2 fields" in done.stderr


def test_animation_of_a_killed_run(killed, tmp_path):
    out = tmp_path / "a.gif"
    done = script("deploydyn_animate.py", killed, "-o", out, "--frames", "3", "--dpi", "30")
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    assert "status killed" in done.stderr and "incomplete last row left out" in done.stderr
    assert out.read_bytes()[:3] == b"GIF"


def test_animation_refuses_a_malformed_history_without_a_traceback(folder, tmp_path):
    header, rows = history_parts(folder)
    rows[3] = "1,2\n"
    (folder / "history.csv").write_text(header + "".join(rows))
    done = script("deploydyn_animate.py", folder, "-o", tmp_path / "a.gif")
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert "history.csv:5: 2 fields" in done.stderr


# ---------------------------------------------------------------------------------------------
# Results that cannot be written


def test_output_error_is_an_os_error_with_errno_and_file(tmp_path):
    assert issubclass(deploydyn.OutputError, OSError)
    assert "OutputError" in deploydyn.__all__
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    out = blocker / "results"
    with pytest.raises(deploydyn.OutputError) as error:
        deploydyn.roof(1, overrides={"analysis.end": 0.05}).run(out=out)
    assert isinstance(error.value, OSError)
    assert error.value.errno == errno.ENOTDIR
    assert error.value.strerror == os.strerror(errno.ENOTDIR)
    assert error.value.filename == str(out)
    assert str(error.value) == f"cannot create folder {out}: {os.strerror(errno.ENOTDIR)}"


def test_a_folder_in_use_is_refused(folder):
    before = (folder / "summary.json").read_bytes()
    lock = hold_lock(folder)
    try:
        with pytest.raises(deploydyn.OutputError, match="in use by another deploydyn run") as error:
            deploydyn.roof(1, overrides={"analysis.end": 0.05}).run(out=folder)
    finally:
        lock.close()
    assert error.value.errno is None
    assert (folder / "summary.json").read_bytes() == before        # the owner's files untouched


def test_a_full_disk_fails_the_run_and_keeps_whole_rows(tmp_path):
    """A file-size limit (setrlimit RLIMIT_FSIZE, SIGXFSZ ignored) stands in for a full disk:
    OutputError with EFBIG, summary.json "failed", and the history's rows whole."""
    out = tmp_path / "out"
    child = tmp_path / "limited.py"
    child.write_text(
        "import json, resource, signal, sys\n"
        "import deploydyn\n"
        "model = deploydyn.roof(1)\n"
        "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
        "resource.setrlimit(resource.RLIMIT_FSIZE, (64_000, 64_000))\n"
        "try:\n"
        f"    model.run(out={str(out)!r})\n"
        "except deploydyn.OutputError as error:\n"
        "    print(json.dumps({'errno': error.errno, 'file': error.filename,\n"
        "                      'message': str(error), 'oserror': isinstance(error, OSError)}))\n"
        "    sys.exit(3)\n")
    done = subprocess.run([sys.executable, str(child)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 3, done.stdout + done.stderr
    error = json.loads(done.stdout)
    assert error["oserror"] and error["errno"] == errno.EFBIG
    assert error["file"] == str(out / "history.csv")
    assert os.strerror(errno.EFBIG) in error["message"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")                            # no incomplete row
        result = deploydyn.read_result(out)
    assert result.status == "failed" and not result.ok
    assert 10 < result.values.shape[0] < 1001
    assert np.all(np.diff(result.t) > 0)
