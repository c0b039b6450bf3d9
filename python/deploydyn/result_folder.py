"""Reading a result folder: its history (history.csv) and its status, as the folder's files and
its lock show them (docs/model-format.md, "Result folders"; src/deploydyn/runs/result_folder.hpp).

Pure Python (numpy only), without the C++ core: the package `deploydyn` re-exports what is
public here, and scripts/deploydyn_plot.py, deploydyn_animate.py and plot_paper.py load this
file directly, so that they work from the source tree without the built module.

A run owns its folder: it holds an exclusive flock(2) on FOLDER/.deploydyn.lock for its whole
life (the kernel drops it when the process dies, even on SIGKILL); its status file (summary.json,
or study.json for a study) says "running" from the start and "completed", "failed" or
"interrupted" at the end. A reader therefore tells a killed run from a live one by trying the
lock, and a history may end in a row that the killed run did not finish writing.
"""
import fcntl
import json
import os
import pathlib
import warnings

import numpy as np

LOCK_FILE_NAME = ".deploydyn.lock"
# A run's status file, then a study's: a folder has one of them.
STATUS_FILE_NAMES = ("summary.json", "study.json")
HISTORY_FILE_NAME = "history.csv"

# What folder_status returns, and what each means to whoever reads the folder.
STATUS_NOTES = {
    "completed": "the run completed",
    "failed": "the run failed; its files hold what it did before the failure",
    "interrupted": "the run was stopped early (Ctrl-C, SIGTERM or SIGHUP) and kept what it had",
    "running": "the run is still going; its files grow",
    "killed": "the run did not finish: its process died without writing a final status",
    "unknown": "no status file: not a result folder, or its run ended before writing one",
}


class IncompleteHistoryWarning(RuntimeWarning):
    """The last row of a history was incomplete (cut off when its run was killed or while it
    was being written) and was left out."""


# ---------------------------------------------------------------------------------------------
# Status


def _read_status_file(file):
    """The status file's JSON object, or None when it is missing, unreadable or is not a JSON
    object."""
    try:
        content = json.loads(pathlib.Path(file).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return content if isinstance(content, dict) else None


def _status_file(folder, status_file):
    if status_file is not None:
        return pathlib.Path(status_file)
    for name in STATUS_FILE_NAMES:
        if (folder / name).exists():
            return folder / name
    return folder / STATUS_FILE_NAMES[0]


def read_status(folder, status_file=None):
    """(status, the status file's content as a dict or None) of a result folder: the status
    as folder_status gives it, and what the status file said (its message, pid, files...)."""
    status, content, _ = _status_and_content(folder, status_file)
    return status, content


def _status_and_content(folder, status_file=None):
    """(status, the status file's content or None, the status file) of a result folder."""
    folder = pathlib.Path(folder)
    file = _status_file(folder, status_file)
    content = _read_status_file(file)
    claimed = content.get("status") if content is not None else None
    if claimed not in (None, "running") and isinstance(claimed, str):
        return claimed, content, file
    # "running" (or no status yet): alive only if a process holds the lock. Whoever owns the
    # folder cannot change the status file while this reader holds the lock, so it is read
    # again under the lock: a run that ended between the two reads is not called killed.
    try:
        fd = os.open(folder / LOCK_FILE_NAME, os.O_RDONLY | os.O_CLOEXEC)
    except FileNotFoundError:
        return ("killed" if claimed == "running" else "unknown"), content, file
    except OSError:
        return ("running" if claimed == "running" else "unknown"), content, file  # cannot tell
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return "running", content, file                     # a live process owns it
        except OSError:
            return ("running" if claimed == "running" else "unknown"), content, file
        content = _read_status_file(file)
        claimed = content.get("status") if content is not None else None
        fcntl.flock(fd, fcntl.LOCK_UN)  # at once: a run starting into the folder waits for it
    finally:
        os.close(fd)
    if claimed == "running":
        return "killed", content, file
    if isinstance(claimed, str):
        return claimed, content, file
    return "unknown", content, file


def folder_status(folder, status_file=None):
    """The status of a result folder (a run's or a study's), as a string:

    "completed", "failed", "interrupted"  what the run's status file (summary.json, or
                                          study.json for a study) says at its end;
    "running"   the status file says "running" and a process holds the folder's lock
                (.deploydyn.lock): the run is alive;
    "killed"    the status file says "running" but no process holds the lock (or the lock
                file is gone): the run died without finishing (SIGKILL, a crash, a power cut);
                its history holds the rows written before, maybe the last one cut off;
    "unknown"   no status file (or not a JSON object with a status) and no process holding
                the lock: not a result folder, a run of a deploydyn older than result-folder
                locks, or a run that died before it wrote its first status. Not "killed":
                nothing says a run was there. (With the lock held, "running": a run starting.)

    When the lock cannot be tried (no permission to read it, or a file system without
    flock), a "running" status is taken as it is. The lock is held for an instant only (runs
    retry theirs briefly). `status_file` names the status file when the model gave it another
    name (output.summary_file); by default summary.json, else study.json.
    """
    return _status_and_content(folder, status_file)[0]


def status_note(status, content=None):
    """One line on what `status` means for the folder's files, with the status file's own
    message when it has one (e.g. why a run failed)."""
    note = STATUS_NOTES.get(status, f"status {status!r}")
    message = content.get("message") if isinstance(content, dict) else None
    if status in ("failed", "interrupted") and isinstance(message, str) and message:
        note = f"{note}: {message}"
    return note


# ---------------------------------------------------------------------------------------------
# History


class History:
    """A history.csv as read: `columns` (names), `values` (rows × columns float array),
    `n_dropped_rows` (0, or 1 when an incomplete last row was left out) and `dropped_reason`
    (why, or None)."""

    def __init__(self, columns, values, n_dropped_rows=0, dropped_reason=None):
        self.columns = columns
        self.values = values
        self.n_dropped_rows = n_dropped_rows
        self.dropped_reason = dropped_reason

    def as_dict(self):
        """{column: 1-D array}, in column order."""
        return {name: self.values[:, i].copy() for i, name in enumerate(self.columns)}


def _row_problem(fields, columns):
    """Why a row's fields are not one number per column, or None when they are."""
    if len(fields) != len(columns):
        return (f"{len(fields)} field{'' if len(fields) == 1 else 's'}, expected {len(columns)} "
                "(one per column)")
    for field, column in zip(fields, columns):
        try:
            float(field)
        except ValueError:
            return f"column {column}: {field.strip()!r} is not a number"
    return None


def read_history(file, warn=True, status=None, _stacklevel=2):
    """A history.csv (a header row, then one row of numbers per output time) as a History.

    A run killed while writing may leave its last row incomplete: without its newline, with
    fewer fields than columns, or with a field cut mid-number. Such a last row is left out
    (History.n_dropped_rows = 1) with an IncompleteHistoryWarning (none with warn=False:
    History.dropped_reason says why). Any other malformed row raises ValueError naming the
    file and line ("results/x/history.csv:17: 5 fields, expected 12 (one per column)"), and so
    does a file without a complete header row. `status`, when given, is added to the warning.
    A missing file raises FileNotFoundError.
    """
    file = pathlib.Path(file)
    fast = _read_whole_history(file)
    if fast is not None:
        return fast
    # Numbers are ASCII; names were checked by the loader. Undecodable bytes (a damaged file)
    # then fail as fields that are not numbers, with their line.
    text = file.read_bytes().decode("utf-8", errors="surrogateescape")
    lines = text.split("\n")  # lines[i] is line i + 1; lines[-1] follows the last newline
    del text
    if len(lines) < 2 or not lines[0].strip():
        raise ValueError(f"{file}:1: no complete header row"
                         + (" (the file is empty)" if lines == [""] else ""))
    columns = lines[0].rstrip("\r").split(",")
    end = len(lines) - 1                  # lines[1:end]: the rows that end in a newline
    reason = None
    if lines[-1].strip():
        reason = f"line {len(lines)} is cut off (no newline at its end)"
    else:
        last = next((i for i in range(end - 1, 0, -1) if lines[i].strip()), None)
        if last is not None:
            fields = lines[last].split(",")
            problem = _row_problem(fields, columns)
            if problem is not None and len(fields) <= len(columns):
                reason = f"line {last + 1}: {problem}"
                end = last
    values = _parse_rows(file, lines, end, columns)
    if reason is not None and warn:
        where = f" (the folder's status: {status})" if status else ""
        warnings.warn(f"{file}: incomplete last row left out{where}: {reason}",
                      IncompleteHistoryWarning, stacklevel=_stacklevel)
    return History(columns, values, 1 if reason else 0, reason)


# Bytes read at a time from the end of a history to find its last row.
_TAIL_CHUNK_BYTES = 1 << 16


def _read_whole_history(file):
    """The common case fast (numpy reads the file itself): a history whose header and last row
    are complete. None when it is not so, or when numpy cannot read it: read_history then reads
    it line by line and says which row is wrong."""
    with open(file, "rb") as f:
        header = f.readline()
        size = f.seek(0, os.SEEK_END)
        if not header.endswith(b"\n") or size == len(header):
            return None
        # The last row: after the last newline but one; chunks from the end until it is whole.
        start = size
        while True:
            start = max(len(header), start - _TAIL_CHUNK_BYTES)
            f.seek(start)
            tail = f.read(size - start)
            if tail.rfind(b"\n", 0, len(tail) - 1) >= 0 or start == len(header):
                break
    if not tail.endswith(b"\n"):
        return None
    last = tail[tail.rfind(b"\n", 0, len(tail) - 1) + 1:-1].decode("utf-8", "surrogateescape")
    columns = header.decode("utf-8", "surrogateescape").rstrip("\r\n").split(",")
    if not last.strip() or _row_problem(last.split(","), columns) is not None:
        return None
    try:
        values = np.loadtxt(file, delimiter=",", comments=None, skiprows=1, ndmin=2, dtype=float)
    except ValueError:
        return None
    return History(columns, values) if values.shape[1] == len(columns) else None


def _parse_rows(file, lines, end, columns):
    """lines[1:end] as a (rows × columns) array; ValueError naming the first bad row's line."""
    rows = lines[1:end]
    if not any(line.strip() for line in rows):
        return np.empty((0, len(columns)))
    try:
        values = np.loadtxt(rows, delimiter=",", comments=None, ndmin=2, dtype=float)
        if values.shape[1] == len(columns):
            return values
    except ValueError:
        pass
    rows = [(number, line) for number, line in enumerate(rows, start=2) if line.strip()]
    for number, line in rows:
        problem = _row_problem(line.split(","), columns)
        if problem is not None:
            raise ValueError(f"{file}:{number}: {problem}")
    # Blank lines, or a spelling of a number that Python reads and numpy does not.
    return np.array([[float(f) for f in line.split(",")] for _, line in rows], dtype=float)


def history_file_of(folder, content=None):
    """The history file of a run's folder: the one its status file lists (a modal analysis's
    table, modes.csv, in its place), else history.csv."""
    files = content.get("files") if isinstance(content, dict) else None
    name = (files.get("history") or files.get("modes")) if isinstance(files, dict) else None
    if isinstance(name, str) and name and "/" not in name and name not in (".", ".."):
        return pathlib.Path(folder) / name
    return pathlib.Path(folder) / HISTORY_FILE_NAME

