"""Results: Result (a run's history and summary), reading result folders (read_result,
read_envelopes, folder_status), and RunFailed."""
import errno
import json
import math
import pathlib

import numpy as np

from deploydyn import _arguments as checked
from deploydyn import _core
from deploydyn import result_folder


class RunFailed(RuntimeError):
    """A run that did not complete, raised only on request (run(check=True),
    Result.raise_for_status()). `result` holds what was computed up to the failure."""

    def __init__(self, result):
        super().__init__(result.message)
        self.result = result


class Result:
    """The outcome of a run.

    columns: history.csv's column names; values: the history, one row per output time, as a
    2-D float array; history: {column: 1-D array}; summary: summary.json as a dict ({} when the
    folder has none); status: "completed", "failed" or "interrupted", and for a folder read
    with read_result also "running", "killed" or "unknown" (see folder_status), as it was when
    read; folder: the result folder, or None; n_dropped_rows: 1 when the history's incomplete
    last row was left out, else 0; temperatures: the members' temperatures of a run with an
    `environment` (below).
    """

    def __init__(self, columns, values, summary, folder=None, status=None, n_dropped_rows=0,
                 temperatures=None):
        self.columns = list(columns)
        self.values = np.asarray(values, dtype=float).reshape(-1, len(self.columns))
        self.history = {name: self.values[:, i].copy() for i, name in enumerate(self.columns)}
        self.summary = summary
        self.folder = pathlib.Path(folder) if folder is not None else None
        self.n_dropped_rows = n_dropped_rows
        self._status = status
        self._temperatures = temperatures

    @property
    def temperatures(self):
        """The members' temperatures that an `environment` gave the run, as temperatures.csv
        holds them (docs/model-format.md, "environment"): {column: 1-D array}, a row per output
        time (the history's), columns "t" (s), "T.<member>" (K) per bar, beam and cable, with
        shadows "shade.<member>" (the shadowed fraction), with section gradients
        "dT_section.<beam>" (K); summary["temperatures"] has the extremes and the heat balance.
        The same from memory and from a folder; {} for a run without an environment."""
        if self._temperatures is None:
            self._temperatures = {}
            file = self.folder / "temperatures.csv" if self.folder is not None else None
            if file is not None and file.exists():
                self._temperatures = result_folder.read_history(file, warn=False).as_dict()
        return self._temperatures

    @property
    def status(self):
        """"completed", "failed" or "interrupted"; for a folder read with read_result also
        "running", "killed" or "unknown" (folder_status), as it was when read."""
        return self._status if self._status is not None else self.summary.get("status")

    @property
    def message(self):
        """summary.json's message; for a killed, running or unknown folder, what that means."""
        if self.status in ("killed", "running", "unknown"):
            return result_folder.status_note(self.status)
        return self.summary.get("message", "")

    @property
    def ok(self):
        """True when the run completed."""
        return self.status == "completed"

    @property
    def failure(self):
        """Where and why it failed (summary.json's "failure"), or None."""
        return self.summary.get("failure")

    @property
    def t(self):
        """The output times (s): the history's column t."""
        return self.history["t"]

    def __getitem__(self, column):
        try:
            return self.history[column]
        except KeyError:
            raise KeyError(f"no column {column!r}; columns are {', '.join(self.columns)}") from None

    def extreme(self, column):
        """The value of `column` with the largest magnitude (signed); NaN with no rows."""
        values = self[column]
        return float(values[np.argmax(np.abs(values))]) if values.size else math.nan

    @property
    def envelopes(self):
        """envelopes.csv of the result folder (extremes over every step, not only the output
        rows) as {(item, quantity): {"kind", "unit", "min", "t_min_s", "max", "t_max_s"}}, e.g.
        result.envelopes[("crank", "axial_force_N")]["max"]; {} for a run kept in memory or a
        folder without the file."""
        if self.folder is None:
            return {}
        return read_envelopes(self.folder / "envelopes.csv")

    def raise_for_status(self):
        """Raise RunFailed unless the run completed."""
        if not self.ok:
            raise RunFailed(self)
        return self

    def __repr__(self):
        return (f"<deploydyn.Result {self.status}: {self.values.shape[0]} rows × "
                f"{len(self.columns)} columns{f' in {self.folder}' if self.folder else ''}>")


def read_envelopes(file):
    """envelopes.csv as {(item, quantity): {"kind", "unit", "min", "t_min_s", "max", "t_max_s"}};
    {} when the file does not exist. The numbers are floats."""
    import csv
    file = checked.path("read_envelopes", "file", file)
    try:
        with open(file, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    except FileNotFoundError:
        return {}
    out = {}
    for row in rows:
        out[(row["item"], row["quantity"])] = {
            "kind": row["kind"], "unit": row["unit"],
            **{key: float(row[key]) for key in ("min", "t_min_s", "max", "t_max_s")}}
    return out


def read_result(folder, history_file=None, summary_file=None):
    """A Result from a result folder written by `deploydyn run` or Model.run(out=...), also
    while its run is going or after it was killed.

    Result.status is the folder's status (folder_status): "killed" for a run that died without
    finishing, "running" for a live one, "unknown" without summary.json. An incomplete last
    row of the history (cut off by the kill, or not yet written whole) is left out with an
    IncompleteHistoryWarning (Result.n_dropped_rows = 1); any other malformed row raises
    ValueError naming the file and line. history_file: default the history file that
    summary.json lists, else FOLDER/history.csv; summary_file: default FOLDER/summary.json.
    A missing history file raises FileNotFoundError.
    """
    folder = checked.path("read_result", "folder", folder)
    if history_file is not None:
        history_file = checked.path("read_result", "history_file", history_file)
    if summary_file is not None:
        summary_file = checked.path("read_result", "summary_file", summary_file)
    return read_result_folder(folder, history_file, summary_file, stacklevel=3)


def read_result_folder(folder, history_file, summary_file, stacklevel):
    """read_result with its arguments already checked (history_file, summary_file: None for
    the defaults); `stacklevel` points an IncompleteHistoryWarning at the user's call."""
    folder = pathlib.Path(folder)
    summary_file = pathlib.Path(summary_file or folder / "summary.json")
    status, _ = result_folder.read_status(folder, summary_file)
    try:
        summary = json.loads(summary_file.read_text(encoding="utf-8"))
    except FileNotFoundError:
        summary = {}
    except ValueError as error:
        raise ValueError(f"{summary_file}: not a JSON summary ({error})") from None
    if not isinstance(summary, dict):
        raise ValueError(f"{summary_file}: not a JSON summary (a {type(summary).__name__}, "
                         "not an object)")
    history_file = pathlib.Path(history_file or result_folder.history_file_of(folder, summary))
    try:
        history = result_folder.read_history(history_file, status=status,
                                              _stacklevel=stacklevel + 1)
    except FileNotFoundError:
        raise FileNotFoundError(
            errno.ENOENT, f"no history file (the folder's status: {status})",
            str(history_file)) from None
    except ValueError as error:
        if status == "completed":
            raise
        raise ValueError(f"{error} (the folder's status: {status})") from None
    return Result(history.columns, history.values, summary, folder=folder, status=status,
                  n_dropped_rows=history.n_dropped_rows)


def folder_status(folder, status_file=None):
    """The status of a result folder (a run's or a study's): "completed", "failed",
    "interrupted", "running" (a live run owns it), "killed" (its summary.json says "running"
    but no process holds its lock: the run died) or "unknown" (no status file). Details in
    deploydyn.result_folder.folder_status."""
    folder = checked.path("folder_status", "folder", folder)
    if status_file is not None:
        status_file = checked.path("folder_status", "status_file", status_file)
    return result_folder.folder_status(folder, status_file)


def report(folder, out=None, frames=200):
    """Writes the result folder `folder` (of a run, a study's case, modes or a continuation) as
    one self-contained HTML page, as `deploydyn report` does (docs/report.md): the summary,
    zoomable time histories, the envelope table and the deployment in 3D. out: the HTML file
    (default FOLDER/report.html), replaced only once the page is complete; frames: the most
    animation frames (1 to 100 000), spread evenly over the history. Returns the file's path.
    A folder the page cannot be made from raises ValueError naming the file and what is wrong;
    a page that cannot be written raises OutputError."""
    where = "report"
    folder = checked.path(where, "folder", folder)
    out = pathlib.Path(folder) / "report.html" if out is None else checked.path(where, "out", out)
    frames = checked.count(where, "frames", frames)
    if frames > 100_000:
        raise ValueError(f"{where}: frames must be at most 100000, got {frames}")
    _core.write_report(folder, out, frames)
    return pathlib.Path(out)
