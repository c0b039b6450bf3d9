"""deploydyn: deployment dynamics of flexible bar structures under thermal loading, from Python.

    import deploydyn
    model = deploydyn.load("examples/paper/general.yaml", overrides={"thermal.dT": 130})
    result = model.run()                        # in memory; model.run(out="results/hot") also
    result["mstrain.2"]                         # numpy array, a column of history.csv
    result.values, result.columns               # the whole history as (rows × columns)
    result.summary["drivers"]["motor"]["peak"]  # summary.json as a dict
    deploydyn.__version__                       # "0.1.0", the project's version
    deploydyn.read_result("results/hot")        # a result folder, also one still running
    deploydyn.read_result("results/hot").envelopes[("2", "axial_force_N")]["max"]  # every step's peak
    deploydyn.folder_status("results/hot")      # "completed", "killed", ...
    deploydyn.run_study("study.yaml", comm=MPI.COMM_WORLD)  # a study file, also under mpirun

Models come from a model file (`load`), from text (`loads`), from a dict in the file's layout
(`from_dict`), or from a `ModelBuilder`. Every model, however made, is read and checked by the
same C++ loader as the command line's, so the checks and messages are the CLI's.

Errors:
  - bad input (a model file, an override, a built model) raises `InputError`, a ValueError whose
    message is the CLI's one line `SOURCE:LINE:COLUMN: FIELD: PROBLEM`; its attributes `source`,
    `line`, `column` (None when unknown), `field` and `problem` hold the parts. A model whose
    mechanics cannot be built (e.g. a driven bar along its rotation axis) raises ValueError.
  - an argument of the wrong type raises TypeError, and a count or size out of range
    ValueError, naming the function, the parameter and what it takes ("roof: units must be
    an int, not float 1.7"). Counts are ints: a float, even 2.0, or a bool is refused.
  - results that cannot be written (a full disk, a file-size limit, no permission, a folder
    that another run owns) raise `OutputError`, an OSError with `errno` (None when the
    operating system gave no error, e.g. a folder in use), `strerror` and `filename`; the
    folder's summary.json then says "failed" and why, if it could be written.
  - a solver failure is NOT an exception: `run` returns a Result whose `status` is "failed"
    (`result.ok` is False, `result.summary["failure"]` says where and why), like the CLI's exit
    code 1, and keeps the history up to the failure. `run(check=True)` or
    `result.raise_for_status()` raise `RunFailed` instead.
  - Ctrl-C during a run (in any phase: the initial equilibrium's load steps too), a
    continuation, modes, run_study (alone, not over MPI), roof or load stops it within a
    fraction of a second and raises KeyboardInterrupt (a run into a folder keeps what was
    written, with status "interrupted" in summary.json; a study its finished cases). Python
    gives Ctrl-C to the main thread only: for a call in another thread, pass
    `stop=threading.Event()` to run, continuation, modes or run_study; once set, the call ends
    the same way and returns what it computed (status "interrupted").

Result folders (`read_result`, `folder_status`): a run owns its folder (a lock on
.deploydyn.lock) and its summary.json says "running" until the run ends, then "completed",
"failed" or "interrupted". A folder whose summary.json still says "running" but whose lock no
process holds was left by a killed run: its status reads "killed" (`Result.ok` False), and the
last row of its history may be cut off; readers leave such a row out with an
`IncompleteHistoryWarning` (`Result.n_dropped_rows` counts it). Any other malformed row of a
history raises ValueError naming the file and line.

`run` releases the GIL: runs of different models in threads go in parallel.
"""
import copy
import errno
import json
import math
import numbers
import os
import pathlib

import numpy as np

from deploydyn import _core
from deploydyn.result_folder import IncompleteHistoryWarning
from deploydyn.study import run_study
from deploydyn import result_folder as _result_folder

InputError = _core.InputError
OutputError = _core.OutputError
# The project's version (CMakeLists.txt `project(deploydyn VERSION ...)`), as `deploydyn --version`.
__version__ = _core.__version__

__all__ = [
    "InputError", "OutputError", "RunFailed", "IncompleteHistoryWarning", "Model", "Result",
    "ModelBuilder", "load", "loads", "from_dict", "roof", "read_result", "read_envelopes", "folder_status",
    "run_study",
    "constant", "smooth_step", "smooth_trapezoid", "paper_eq23", "table",
    "polynomial", "harmonic", "cosine_ramp", "cycloidal", "piecewise", "sum_of",
]


class RunFailed(RuntimeError):
    """A run that did not complete, raised only on request (run(check=True),
    Result.raise_for_status()). `result` holds what was computed up to the failure."""

    def __init__(self, result):
        super().__init__(result.message)
        self.result = result


# ---------------------------------------------------------------------------------------------
# Argument checks: a message that names the function, the parameter and what it takes, before
# a value reaches pybind11 ("incompatible function arguments") or the loader ("cannot open
# file").

_INT_MAX = 2**31 - 1  # the C++ side's int
# Times of one modal analysis, as the model file's analysis.at allows (docs/model-format.md,
# "Input limits"): each is a static solve and an eigenproblem.
_MAX_MODAL_TIMES = 100_000


def _shown(value):
    """`value` for a message: its type and a short repr."""
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def _is_number(value):
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _count(where, name, value, minimum=1):
    """An int (not a bool, not a float even if whole) of at least `minimum`."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{where}: {name} must be an int, not {_shown(value)}")
    value = int(value)
    if value < minimum:
        raise ValueError(f"{where}: {name} must be at least {minimum}, got {value}")
    if value > _INT_MAX:
        raise ValueError(f"{where}: {name} must be at most {_INT_MAX}, got {value}")
    return value


def _number(where, name, value):
    """`value`, checked to be a real number (int or float, numpy's too; not a bool)."""
    if not _is_number(value):
        raise TypeError(f"{where}: {name} must be a number (int or float), not {_shown(value)}")
    return value


def _finite(where, name, value):
    """A number that is not NaN or infinite, as a float."""
    value = float(_number(where, name, value))
    if not math.isfinite(value):
        raise ValueError(f"{where}: {name} must be a finite number, got {value}")
    return value


def _numbers(where, name, values):
    """A sequence of numbers (a list, tuple or 1-D array), checked, as a list."""
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise TypeError(f"{where}: {name} must be a sequence of numbers, not {_shown(values)}")
    values = list(values)
    for i, value in enumerate(values):
        if not _is_number(value):
            raise TypeError(f"{where}: {name}[{i}] must be a number, not {_shown(value)}")
    return values


def _text(where, name, value):
    if not isinstance(value, str):
        raise TypeError(f"{where}: {name} must be a str, not {_shown(value)}")
    return value


def _name(where, name, value):
    """A node, element, material, driver or function name: a str, or an int (as `1:` in a file)."""
    if isinstance(value, str):
        return value
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return str(int(value))
    raise TypeError(f"{where}: {name} must be a name (str, or int), not {_shown(value)}")


def _path(where, name, value):
    """A file or folder path: a str or an os.PathLike (pathlib.Path), not empty."""
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{where}: {name} must be a path (str or pathlib.Path), "
                        f"not {_shown(value)}")
    path = os.fspath(value)
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if not path:
        raise ValueError(f"{where}: {name} must not be empty")
    if "\0" in path:  # the operating system would see only the part before it
        raise ValueError(f"{where}: {name} must not hold a NUL character (\\0), got {_shown(value)}")
    return pathlib.Path(path)


def _stop(where, stop):
    """The `stop` argument of a long call: None, or what it asks is_set() of (threading.Event)."""
    if stop is not None and not callable(getattr(stop, "is_set", None)):
        raise TypeError(f"{where}: stop must be a threading.Event (or any object with is_set()) "
                        f"or None, not {_shown(stop)}")
    return stop


def _time_function(where, name, value):
    """A function of time as the model file takes it: a number, a function's name, or a dict
    (constant(...), smooth_step(...), ...)."""
    if _is_number(value) or isinstance(value, str) or isinstance(value, dict):
        return value
    raise TypeError(f"{where}: {name} must be a number, a function's name (str) or a function "
                    f"(dict, e.g. deploydyn.smooth_step(...)), not {_shown(value)}")


def _plain(value, field, where):
    """`value` (a model file's content) with only what JSON holds: dicts with text keys, lists,
    text, numbers (numpy's as Python's), booleans, None. TypeError names the field."""
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, (np.ndarray, np.bool_)):
        return _plain(value.tolist(), field, where)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            if isinstance(key, bool) or not isinstance(key, (str, numbers.Integral)):
                raise TypeError(f"{where}: {field or 'the model'}: keys must be names (str, or "
                                f"int), not {_shown(key)}")
            key = str(key) if isinstance(key, str) else str(int(key))
            out[key] = _plain(item, f"{field}.{key}" if field else key, where)
        return out
    if isinstance(value, (list, tuple)):
        return [_plain(item, f"{field}.{i}", where) for i, item in enumerate(value)]
    raise TypeError(f"{where}: {field or 'the model'} must be a number, text, list or dict, "
                    f"not {_shown(value)}")


# ---------------------------------------------------------------------------------------------
# Overrides


def _value_text(where, path, value):
    """An override value as the text --set takes: numbers in their shortest exact form; a dict
    or list (a function such as smooth_step(...), a list of axes) as a YAML flow value, which
    JSON is."""
    if isinstance(value, (dict, list, tuple)):
        return json.dumps(_plain(list(value) if isinstance(value, tuple) else value, path, where),
                          ensure_ascii=False)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, str):
        return value
    raise TypeError(f"{where}: override {path}: the value must be a number, bool, text, dict "
                    f"or list, not {_shown(value)}")


_OVERRIDES_TAKE = ("a dict {path: value}, a 'PATH=VALUE' text, or a list of such texts or "
                   "(path, value) pairs")


def _override_pairs(where, overrides):
    """Overrides as (path, text) pairs, from a dict {path: value}, a "PATH=VALUE" string, or a
    list of such strings or (path, value) pairs."""
    if overrides is None:
        return []
    if isinstance(overrides, str):
        overrides = [overrides]
    elif isinstance(overrides, dict):
        overrides = list(overrides.items())
    elif isinstance(overrides, (list, tuple)):
        overrides = list(overrides)
    else:
        raise TypeError(f"{where}: overrides must be {_OVERRIDES_TAKE}, not {_shown(overrides)}")
    pairs = []
    for item in overrides:
        if isinstance(item, str):
            pairs.append(_core.parse_override(item))
        elif isinstance(item, (list, tuple)) and len(item) == 2:
            path = _text(where, "an override's path", item[0])
            pairs.append((path, _value_text(where, path, item[1])))
        else:
            raise TypeError(f"{where}: overrides must be {_OVERRIDES_TAKE}; "
                            f"an item is {_shown(item)}")
    return pairs


def _merge(pairs, new_pairs):
    """Earlier overrides with new ones; a new one of the same path replaces the earlier."""
    paths = {path for path, _ in new_pairs}
    return [p for p in pairs if p[0] not in paths] + list(new_pairs)


# ---------------------------------------------------------------------------------------------
# Models


class Model:
    """A validated model. Make one with load, loads, from_dict or ModelBuilder.build.

    Overriding values (`set`, `with_overrides`) reads the source again with the overrides
    applied, exactly as --set does, so every check applies to the new values.
    """

    def __init__(self, _source, _overrides=()):
        # _source: ("file", path) or ("text", text, source_name, with_position)
        self._source = _source
        self._overrides = list(_overrides)
        self._core = self._load(self._overrides)

    def _load(self, overrides):
        if self._source[0] == "file":
            return _core.load_file(self._source[1], overrides)
        _, text, source_name, with_position = self._source
        return _core.load_text(text, source_name, overrides, with_position)

    # -- overriding -----------------------------------------------------------------------------
    def set(self, path_or_overrides, value=None):
        """Override values in place: set("thermal.dT", 130), set({"thermal.dT": 130, ...}) or
        set("thermal.dT=130"). On an error the model is left as it was. Returns the model."""
        if value is not None:
            path_or_overrides = {_text("Model.set", "path", path_or_overrides): value}
        overrides = _merge(self._overrides, _override_pairs("Model.set", path_or_overrides))
        self._core = self._load(overrides)
        self._overrides = overrides
        return self

    def with_overrides(self, overrides):
        """A new model: this one with `overrides` (dict, list or "PATH=VALUE") applied."""
        return Model(self._source,
                     _merge(self._overrides, _override_pairs("Model.with_overrides", overrides)))

    @property
    def overrides(self):
        """The overrides applied, as (path, value text) pairs."""
        return list(self._overrides)

    @property
    def source(self):
        """The model file, or the name that error messages give a model made from text."""
        return self._source[1] if self._source[0] == "file" else self._source[2]

    # -- contents -------------------------------------------------------------------------------
    @property
    def name(self):
        """The model's `name` (empty when the file gives none)."""
        return self._core.name

    @property
    def description(self):
        """The model's `description` (empty when the file gives none)."""
        return self._core.description

    @property
    def dimension(self):
        """2 or 3."""
        return self._core.dimension

    @property
    def nodes(self):
        """{name: initial position (m) as a tuple}."""
        return {n["name"]: n["position"] for n in self._core.nodes}

    @property
    def elements(self):
        """{name: {"type", then the keys of its type as the model file spells them (a bar:
        "nodes": (a, b), "area" m², "material", "mass" kg, "length" m (L0)), and "E" Pa,
        "alpha" 1/°C of its material}}."""
        return {e["name"]: e for e in self._core.elements}

    @property
    def supports(self):
        """[{"node": name, "fix": ["x", "y"]}, ...]."""
        return self._core.supports

    @property
    def joints(self):
        """{name: {"type": "pin", "nodes": [A, B], and "axis" (3D, between beam nodes)}}."""
        return {j["name"]: j for j in self._core.joints}

    @property
    def drivers(self):
        """{name: {"type", then by type: bar_angle "element", "pivot" (3D "axis"); coordinate
        "node", "direction"; revolute "joint"; hinge_angle "nodes" [A, H, B] (3D "axis");
        "reading", "effort": "torque" | "force"}}."""
        return {d["name"]: d for d in self._core.drivers}

    @property
    def analysis(self):
        """{"type", "end" s, "step" s, "output_interval" s, "load_steps"}; for type "modal" also
        "modes" and "at" (s)."""
        return self._core.analysis

    @property
    def history_columns(self):
        """The columns of history.csv (and of Result.values) for this model."""
        return self._core.history_columns

    def temperature_changes(self, t=0.0):
        """{element: ΔT (°C) at time t}."""
        t = float(_number("Model.temperature_changes", "t", t))
        return dict(zip(self.elements, self._core.temperature_changes(t)))

    def to_yaml(self):
        """The model as a model file, every default explicit, overrides applied."""
        return self._core.to_yaml()

    def save(self, path):
        """Write to_yaml() to `path`; load(path) reads back the same model."""
        _path("Model.save", "path", path).write_text(self.to_yaml(), encoding="utf-8")

    # -- running --------------------------------------------------------------------------------
    def run(self, out=None, check=False, stop=None):
        """Run the analysis; return a Result.

        out: a folder to write history.csv and summary.json into, as `deploydyn run --out`
        does (the Result then reads them back: the values are the same to the last bit);
        None keeps everything in memory. check: raise RunFailed unless the run completed.
        stop: a threading.Event (or any object with is_set()); once it is set the run ends
        within a fraction of a second with status "interrupted", keeping what it computed.
        The way to stop a run in another thread, which Ctrl-C does not reach.
        A model of analysis type "modal" gives modes.csv's table instead of the history (columns
        frame, t, mode, omega2, frequency, dT_C, position.<driver>; summary["modes"] per time).
        Results that cannot be written raise OutputError (an OSError).
        """
        if not isinstance(check, bool):
            raise TypeError(f"Model.run: check must be a bool, not {_shown(check)}")
        stop = _stop("Model.run", stop)
        if out is None:
            raw = self._core.run_in_memory(stop)
            result = Result(raw["columns"], raw["values"], json.loads(raw["summary_json"]))
        else:
            out = _path("Model.run", "out", out)
            raw = self._core.run_into_folder(out, stop)
            result = _read_result(out, raw["history_file"], raw["summary_file"], stacklevel=3)
        if check:
            result.raise_for_status()
        return result

    def continuation(self, parameter, end, start=0.0, eigenvalues=3, max_steps=2000, time=0.0,
                     switch_branch=False, stop_at="end", stop=None):
        """Trace the static equilibrium as `parameter` goes from `start` to `end`, through limit
        points (arc-length continuation, docs/theory.md "Path following and stability"), as a
        model of `analysis: {type: continuation}` does: "thermal" scales every ΔT (μ = 1: the
        model's own), "load" scales the loads and gravity; drivers and ΔT(t) are read at `time`
        (s). "driver" follows a quasi-static deployment: μ is the time (s) at which the drivers'
        positions, ΔT(t) and the loads are read (`time` is not used). With `switch_branch`, the
        path leaves at its first bifurcation along the critical mode and follows the bifurcated
        branch. stop_at: "end" (the path goes on to `end`) or "first_event" (it ends at its first
        event, that event its last point, "end" then "first_event"), as the model key `stop_at`.
        Returns a dict: "mu", "displacement_norm" (m), "eigenvalues" (points × eigenvalues,
        N/m, of the tangent stiffness on the constraint-compatible motions; NaN when not
        computed), "n_negative", "q" (points × coordinates), "events" (dicts with "kind"
        limit_point | bifurcation | singular_constraints, "mu", "mu_error", "point", "mode",
        "axial_forces", "description"), "end" and "message" (how it ended: "stopped" once
        `stop`, a threading.Event as for run, is set)."""
        where = "Model.continuation"
        parameter = _text(where, "parameter", parameter)
        end = _finite(where, "end", end)
        start = _finite(where, "start", start)
        eigenvalues = _count(where, "eigenvalues", eigenvalues, minimum=0)
        max_steps = _count(where, "max_steps", max_steps)
        time = _finite(where, "time", time)
        if not isinstance(switch_branch, bool):
            raise TypeError(f"{where}: switch_branch must be a bool, not {_shown(switch_branch)}")
        if stop_at not in ("end", "first_event"):
            raise ValueError(f"{where}: stop_at must be 'end' or 'first_event', not {_shown(stop_at)}")
        stop = _stop(where, stop)
        raw = self._core.continuation(parameter, start, end, eigenvalues, max_steps, time, switch_branch,
                                      stop_at, stop)
        out = dict(raw)
        for key in ("mu", "displacement_norm", "eigenvalues", "n_negative", "q"):
            out[key] = np.asarray(raw[key])
        out["events"] = [dict(e, mode=np.asarray(e["mode"]), axial_forces=np.asarray(e["axial_forces"]))
                         for e in raw["events"]]
        return out

    def modes(self, count=10, at=0.0, stop=None):
        """Natural frequencies and modes about the static equilibrium at time(s) `at` (the
        thermal state at t = 0, then the drivers moved quasi-statically), as `deploydyn modes`
        computes them. Returns a dict of numpy arrays: "times" (s), "omega2" (rad²/s², times ×
        count, ascending; < 0: unstable), "frequency" (Hz, NaN where ω² < 0), "modes" (times ×
        coordinates × count, M-orthonormal), "coordinates" (labels such as "x.B"), "failures"
        (per time "" or why no modes were found; those rows are NaN). count: 1 to the model's
        coordinates − constraint equations; at: a time ≥ 0 or a list of 1 to 100 000 of them,
        as the model file's analysis.at (ValueError beyond). stop: a threading.Event as for
        run; once set, the times not reached are failures "stopped ..."."""
        where = "Model.modes"
        count = _count(where, "count", count)  # at most the free coordinates: checked by _core
        times = _numbers(where, "at", [at] if _is_number(at) else at)
        if not 1 <= len(times) <= _MAX_MODAL_TIMES:
            raise ValueError(f"{where}: at must be a time or a list of 1 to {_MAX_MODAL_TIMES} "
                             f"times (s), got {len(times)}")
        for i, t in enumerate(times):
            times[i] = _finite(where, f"at[{i}]", t)
            if times[i] < 0:
                raise ValueError(f"{where}: at[{i}] must be a time ≥ 0 (s), got {times[i]}")
        raw = self._core.modes(count, times, _stop(where, stop))
        omega2 = np.asarray(raw["omega2"])
        with np.errstate(invalid="ignore"):
            frequency = np.where(omega2 >= 0, np.sqrt(np.abs(omega2)) / (2 * np.pi), np.nan)
        return {"times": np.asarray(times), "omega2": omega2, "frequency": frequency,
                "modes": np.asarray(raw["modes"]), "coordinates": list(raw["coordinates"]),
                "failures": list(raw["failures"])}

    def __repr__(self):
        extra = f", overrides={dict(self._overrides)}" if self._overrides else ""
        return (f"<deploydyn.Model {self.name or '(unnamed)'!r} from {self.source}: "
                f"{len(self.nodes)} nodes, {len(self.elements)} bars{extra}>")


def load(path, overrides=None):
    """Read a model file (YAML or JSON), with overrides as --set applies them:
    {"thermal.dT": 130}, ["thermal.dT=130"] or [("thermal.dT", 130)]."""
    path = _path("load", "path", path)
    return Model(("file", str(path)), _override_pairs("load", overrides))


def loads(text, source_name="<string>", overrides=None):
    """Read a model from text in the model-file format; errors name `source_name` and the line."""
    _text("loads", "text", text)
    _text("loads", "source_name", source_name)
    return Model(("text", text, source_name, True), _override_pairs("loads", overrides))


def from_dict(spec, source_name=None, overrides=None):
    """A model from a dict laid out as a model file ({"nodes": {...}, "elements": {...}, ...}).
    Errors name the field (e.g. elements.2.area) but no line: there is no file. Values may be
    numpy numbers or arrays; anything JSON cannot hold is a TypeError naming the field."""
    if not isinstance(spec, dict):
        raise TypeError("from_dict: spec must be a dict laid out as a model file, "
                        f"not {_shown(spec)}")
    if source_name is not None:
        _text("from_dict", "source_name", source_name)
    spec = _plain(spec, "", "from_dict")
    name = spec.get("name")
    source_name = source_name or (f"<model {name!r} built in Python>" if name else
                                  "<model built in Python>")
    text = json.dumps(spec, indent=1, ensure_ascii=False, allow_nan=True)
    return Model(("text", text, source_name, False), _override_pairs("from_dict", overrides))


def roof(units, trusses=1, delta_t=130.0, bearings="sliding", overrides=None):
    """A foldable roof of the paper's parallel four-bar units, as `deploydyn generate roof` writes
    it: trusses=1 a planar truss of `units` units, trusses > 1 a 3D roof; posts deploy from 5° to
    upright in 5 s; delta_t (°C) is the model-wide temperature change; bearings "sliding"
    (expansion bearings and bottom members: free to expand, the default) or "pinned" (every foot
    pinned to a ground that does not expand). units and trusses are ints (a float, even 2.0, is
    refused: TypeError)."""
    units = _count("roof", "units", units)
    trusses = _count("roof", "trusses", trusses)
    delta_t = float(_number("roof", "delta_t", delta_t))
    bearings = _text("roof", "bearings", bearings)
    text = _core.roof_yaml(units, trusses, delta_t, bearings)
    return Model(("text", text, f"<roof of {trusses} x {units} units>", False),
                 _override_pairs("roof", overrides))


# ---------------------------------------------------------------------------------------------
# Time functions (for profiles, ΔT, load factors): what the model file's mappings hold.


def constant(value):
    """A function of time that is `value` at every t: {"type": "constant", "value": value}."""
    return {"type": "constant", "value": _number("constant", "value", value)}


def smooth_step(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, ADAMS' cubic STEP in between."""
    return {"type": "smooth_step", **{name: _number("smooth_step", name, value) for name, value in
                                      (("t0", t0), ("v0", v0), ("t1", t1), ("v1", v1))}}


def _pair(where, name, value):
    values = _numbers(where, name, value)
    if len(values) != 2:
        raise ValueError(f"{where}: {name} must be two numbers (t_start, t_end), got {len(values)}")
    return values


def smooth_trapezoid(amplitude, rise, fall):
    """0 → amplitude over rise = (t0, t1), held, back to 0 over fall = (t2, t3)."""
    return {"type": "smooth_trapezoid",
            "amplitude": _number("smooth_trapezoid", "amplitude", amplitude),
            "rise": _pair("smooth_trapezoid", "rise", rise),
            "fall": _pair("smooth_trapezoid", "fall", fall)}


def paper_eq23(**changes):
    """The paper's Eq. (23) (amplitude 0.365, rise [0, 1], fall [4, 5]); keywords change parts."""
    spec = {"type": "paper_eq23"}
    for key, value in changes.items():
        if key == "amplitude":
            spec[key] = _number("paper_eq23", key, value)
        elif key in ("rise", "fall"):
            spec[key] = _pair("paper_eq23", key, value)
        else:
            spec[key] = value  # the loader names what it does not know
    return spec


def table(points):
    """Linear between (t, value) points, held constant outside."""
    if isinstance(points, (str, bytes)) or not hasattr(points, "__iter__"):
        raise TypeError("table: points must be a sequence of (t, value) pairs, "
                        f"not {_shown(points)}")
    rows = []
    for i, point in enumerate(points):
        values = _numbers("table", f"points[{i}]", point)
        if len(values) != 2:
            raise ValueError(f"table: points[{i}] must be a (t, value) pair, "
                             f"got {len(values)} numbers")
        rows.append([float(v) for v in values])
    return {"type": "table", "points": rows}


def _ramp(kind, t0, v0, t1, v1):
    return {"type": kind, **{name: _number(kind, name, value) for name, value in
                             (("t0", t0), ("v0", v0), ("t1", t1), ("v1", v1))}}


def cosine_ramp(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, a half cosine in between: v0 + (v1 - v0)(1 - cos(pi s))/2,
    s = (t - t0)/(t1 - t0). Starts and stops at rest; its acceleration jumps at t0 and t1."""
    return _ramp("cosine_ramp", t0, v0, t1, v1)


def cycloidal(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, a cycloid in between: v0 + (v1 - v0)(s - sin(2 pi s)/(2 pi)),
    s = (t - t0)/(t1 - t0). Starts and stops at rest with zero acceleration (jerk-limited): a
    drive that does not set the structure ringing as smooth_step does."""
    return _ramp("cycloidal", t0, v0, t1, v1)


def polynomial(coefficients, interval=None):
    """c[0] + c[1] tau + c[2] tau**2 + ... (1 to 16 coefficients). Without `interval`, tau = t
    at every t; with interval = (t0, t1), tau = t - t0 on it and the function is held at its
    end values outside."""
    spec = {"type": "polynomial",
            "coefficients": [float(c) for c in _numbers("polynomial", "coefficients", coefficients)]}
    if interval is not None:
        spec["interval"] = _pair("polynomial", "interval", interval)
    return spec


def harmonic(amplitude, frequency, phase=0.0, offset=0.0):
    """offset + amplitude * sin(2 pi frequency t + phase); frequency in Hz (> 0), phase in rad."""
    return {"type": "harmonic", "amplitude": _number("harmonic", "amplitude", amplitude),
            "frequency": _number("harmonic", "frequency", frequency),
            "phase": _number("harmonic", "phase", phase),
            "offset": _number("harmonic", "offset", offset)}


def piecewise(pieces):
    """Each piece (t_from, t_to, function) on [t_from, t_to), the pieces in order, each starting
    where the one before ends, their values joining; held at the first value before and the last
    after. A function is a number, a function's name or any of these functions, in the absolute
    time t."""
    if isinstance(pieces, (str, bytes, dict)) or not hasattr(pieces, "__iter__"):
        raise TypeError(f"piecewise: pieces must be a sequence of (t_from, t_to, function), "
                        f"not {_shown(pieces)}")
    rows = []
    for i, piece in enumerate(pieces):
        if isinstance(piece, (str, bytes, dict)) or not hasattr(piece, "__len__") or len(piece) != 3:
            raise TypeError(f"piecewise: pieces[{i}] must be a (t_from, t_to, function) triple, "
                            f"not {_shown(piece)}")
        t_from, t_to, function = piece
        rows.append({"from": _number("piecewise", f"pieces[{i}] t_from", t_from),
                     "to": _number("piecewise", f"pieces[{i}] t_to", t_to),
                     "function": _time_function("piecewise", f"pieces[{i}] function", function)})
    return {"type": "piecewise", "pieces": rows}


def sum_of(*terms):
    """The sum of the given functions of time (numbers, names or any of these functions)."""
    return {"type": "sum",
            "terms": [_time_function("sum_of", f"terms[{i}]", term) for i, term in enumerate(terms)]}


class ModelBuilder:
    """Builds a model in code, in the model file's terms (docs/model-format.md); SI units.

        b = deploydyn.ModelBuilder("heated bar")
        b.node("A", 0, 0).node("B", 1, 0)
        b.material("steel", E=2e11, alpha=1.2e-5)
        b.bar("1", "A", "B", area=1e-4, material="steel", mass=0.785)
        b.support("A").support("B")
        b.thermal(100)                              # ΔT (°C) of every bar without its own
        b.analysis(type="static", end=1.0, step=0.5)
        model = b.build()

    Functions of time (driver profiles, ΔT, load factors) are a number, the name of a function
    added with `function`, "paper_eq23", or constant/smooth_step/smooth_trapezoid/paper_eq23/
    table/polynomial/harmonic/cosine_ramp/cycloidal/piecewise/sum_of(...). Each method checks the types of its arguments (TypeError naming the method and
    parameter); values are checked at `build`, which checks everything the loader checks.
    """

    def __init__(self, name="", description=""):
        name = _text("ModelBuilder", "name", name)
        description = _text("ModelBuilder", "description", description)
        self._spec = {"name": name} if name else {}
        if description:
            self._spec["description"] = description

    def _section(self, key, kind=dict):
        return self._spec.setdefault(key, kind())

    def node(self, name, x, y, z=None, mass=None):
        """A node at (x, y[, z]) m, with an optional point mass (kg)."""
        where = "ModelBuilder.node"
        at = [_number(where, axis, value) for axis, value in (("x", x), ("y", y), ("z", z))
              if value is not None or axis != "z"]
        spec = at if mass is None else {"at": at, "mass": _number(where, "mass", mass)}
        self._section("nodes")[_name(where, "name", name)] = spec
        return self

    def material(self, name, E, alpha=0.0, density=None, damping=None, yield_strength=None,
                 specific_heat=None, absorptivity=None, emissivity=None):
        """E (Pa), alpha (1/°C), density (kg/m³, for bars that give no mass), damping (material
        damping of its bars, cables and beams, as the model file's mapping: {"ratio": ζ, "frequency":
        f (Hz)}, {"loss_factor": η, "frequency": f} or {"time": τ (s)}), yield_strength (Pa, the
        stress the member checks allow); for an `environment`: specific_heat (J/(kg·K)),
        absorptivity α_s and emissivity ε (both in [0, 1])."""
        where = "ModelBuilder.material"
        spec = {"E": _number(where, "E", E), "alpha": _number(where, "alpha", alpha)}
        for key, value in (("density", density), ("yield_strength", yield_strength),
                           ("specific_heat", specific_heat), ("absorptivity", absorptivity),
                           ("emissivity", emissivity)):
            if value is not None:
                spec[key] = _number(where, key, value)
        if damping is not None:
            if not isinstance(damping, dict):
                raise TypeError(f"{where}: damping must be a dict such as {{'ratio': 0.02, 'frequency': 10}}, "
                                f"not {type(damping).__name__}")
            spec["damping"] = {_name(where, "damping key", k): _number(where, f"damping.{k}", v)
                               for k, v in damping.items()}
        self._section("materials")[_name(where, "name", name)] = spec
        return self

    def bar(self, name, node_a, node_b, area, material, mass=None, length=None, dT=None):
        """A bar between two nodes: area (m²), mass (kg; default density·area·L0), length
        (m, the reference length L0; default the nodes' distance), dT (its own ΔT(t), °C)."""
        where = "ModelBuilder.bar"
        spec = {"nodes": [_name(where, "node_a", node_a), _name(where, "node_b", node_b)],
                "area": _number(where, "area", area),
                "material": _name(where, "material", material)}
        for key, value in (("mass", mass), ("length", length)):
            if value is not None:
                spec[key] = _number(where, key, value)
        if dT is not None:
            spec["dT"] = _time_function(where, "dT", dT)
        self._section("elements")[_name(where, "name", name)] = spec
        return self

    def beam(self, name, node_a, node_b, area, inertia_z, material, shear_factor=None,
             shear_modulus=None, height_y=None, dT_gradient_y=None, mass=None, length=None,
             dT=None, **fields_3d):
        """A geometrically exact beam between two nodes (docs/theory.md, "Beams"): area (m²),
        inertia_z (m⁴, in-plane bending in 2D), shear_factor (default 5/6), shear_modulus (Pa,
        default E/2.6), height_y (m) and dT_gradient_y (T(+y) − T(−y), °C, a function of t),
        mass, length, dT as for `bar`. 3D keys (inertia_y, torsion, orientation, height_z,
        dT_gradient_z) go by name. Its nodes carry a rotation: clamp one with
        support(node, fix=["x", "y", "rotation"])."""
        where = "ModelBuilder.beam"
        spec = {"type": "beam",
                "nodes": [_name(where, "node_a", node_a), _name(where, "node_b", node_b)],
                "area": _number(where, "area", area),
                "inertia_z": _number(where, "inertia_z", inertia_z),
                "material": _name(where, "material", material)}
        for key, value in (("shear_factor", shear_factor), ("shear_modulus", shear_modulus),
                           ("height_y", height_y), ("mass", mass), ("length", length)):
            if value is not None:
                spec[key] = _number(where, key, value)
        for key, value in (("dT_gradient_y", dT_gradient_y), ("dT", dT)):
            if value is not None:
                spec[key] = _time_function(where, key, value)
        for key, value in fields_3d.items():
            if key in ("dT_gradient_z",):
                spec[key] = _time_function(where, key, value)
            elif key == "orientation":
                spec[key] = _numbers(where, key, value)
            elif key in ("inertia_y", "torsion", "height_z"):
                spec[key] = _number(where, key, value)
            else:
                raise TypeError(f"{where}: unexpected keyword argument '{key}'")
        self._section("elements")[_name(where, "name", name)] = spec
        return self

    def cable(self, name, node_a, node_b, area, material, rest_length=None, pretension=None,
              mass=None, dT=None):
        """A tension-only cable between two nodes (docs/theory.md, "Cables"): area (m²),
        rest_length (m, a number or a function of t: a winch; default the nodes' distance) or
        pretension (N, the initial cable's tension at ΔT = 0; not both), mass (kg; default
        density·area·L0(0)), dT (its own ΔT(t), °C)."""
        where = "ModelBuilder.cable"
        spec = {"type": "cable",
                "nodes": [_name(where, "node_a", node_a), _name(where, "node_b", node_b)],
                "area": _number(where, "area", area),
                "material": _name(where, "material", material)}
        for key, value in (("pretension", pretension), ("mass", mass)):
            if value is not None:
                spec[key] = _number(where, key, value)
        for key, value in (("rest_length", rest_length), ("dT", dT)):
            if value is not None:
                spec[key] = _time_function(where, key, value)
        self._section("elements")[_name(where, "name", name)] = spec
        return self

    def hinge(self, name, nodes=None, rotation_nodes=None, stiffness=None, rest_angle=None,
              damping=None, friction=None, pin_radius=None, stop_min=None, stop_max=None,
              latch=None, axis=None):
        """A hinge (docs/theory.md, "Hinges") on the angle at H between bars, nodes [A, H, B],
        or between two 2D beam nodes, rotation_nodes [A, B]: a torsion spring `stiffness`
        (N·m/rad) unloaded at `rest_angle` (rad), a damper `damping` (N·m·s/rad), Coulomb
        `friction` μ with `pin_radius` (m) pressed by the bar A–H's axial force, end stops
        `stop_min`/`stop_max` and a `latch` angle (rad); `axis` [ax, ay, az] in 3D."""
        where = "ModelBuilder.hinge"
        spec = {"type": "hinge"}
        if nodes is not None:
            spec["nodes"] = [_name(where, "nodes", n) for n in nodes]
        if rotation_nodes is not None:
            spec["rotation_nodes"] = [_name(where, "rotation_nodes", n) for n in rotation_nodes]
        for key, value in (("stiffness", stiffness), ("rest_angle", rest_angle), ("damping", damping),
                           ("friction", friction), ("pin_radius", pin_radius), ("stop_min", stop_min),
                           ("stop_max", stop_max), ("latch", latch)):
            if value is not None:
                spec[key] = _number(where, key, value)
        if axis is not None:
            spec["axis"] = _numbers(where, "axis", axis)
        self._section("elements")[_name(where, "name", name)] = spec
        return self

    def element(self, name, type, **fields):
        """An element of any type (`type`, e.g. "bar"), its keys as the model file spells them
        (docs/model-format.md); the loader checks them at `build`."""
        where = "ModelBuilder.element"
        spec = {"type": _name(where, "type", type)}
        spec.update(fields)
        self._section("elements")[_name(where, "name", name)] = spec
        return self

    def support(self, node, fix=None):
        """Fix a node's coordinates: all axes, or those in `fix` (e.g. ["y"], or "y"); "rotation"
        in `fix` clamps a beam's node."""
        where = "ModelBuilder.support"
        spec = {"node": _name(where, "node", node)}
        if fix is not None:
            axes = [fix] if isinstance(fix, str) else fix
            if not isinstance(axes, (list, tuple)) or not all(isinstance(a, str) for a in axes):
                raise TypeError(f"{where}: fix must be a list of axis names (\"x\", \"y\", "
                                f"\"z\"), not {_shown(fix)}")
            spec["fix"] = list(axes)
        self._section("supports", list).append(spec)
        return self

    def bar_angle_driver(self, name, element, profile, pivot=None, reading="angular_velocity",
                         axis=None):
        """Turn bar `element` about `pivot` (default its first node); reading
        "angular_velocity" (profile ω(t), rad/s) or "angle" (rad)."""
        where = "ModelBuilder.bar_angle_driver"
        spec = {"type": "bar_angle", "element": _name(where, "element", element),
                "profile": _time_function(where, "profile", profile),
                "reading": _text(where, "reading", reading)}
        if pivot is not None:
            spec["pivot"] = _name(where, "pivot", pivot)
        if axis is not None:
            spec["axis"] = _numbers(where, "axis", axis)
        self._section("drivers")[_name(where, "name", name)] = spec
        return self

    def joint(self, name, node_a, node_b, type="pin", axis=None):
        """A pin joint: nodes `node_a` and `node_b` (at one initial position) keep one position;
        in 3D between beam nodes `axis` [ax, ay, az] is required and stays common."""
        where = "ModelBuilder.joint"
        spec = {"type": _text(where, "type", type),
                "nodes": [_name(where, "node_a", node_a), _name(where, "node_b", node_b)]}
        if axis is not None:
            spec["axis"] = _numbers(where, "axis", axis)
        self._section("joints")[_name(where, "name", name)] = spec
        return self

    def revolute_driver(self, name, joint, profile, reading="angular_velocity"):
        """Turn node B of pin `joint` relative to node A about the joint's axis (nodes with
        rotations: beams); reading "angular_velocity" (rad/s) or "angle" (rad)."""
        where = "ModelBuilder.revolute_driver"
        self._section("drivers")[_name(where, "name", name)] = {
            "type": "revolute", "joint": _name(where, "joint", joint),
            "profile": _time_function(where, "profile", profile),
            "reading": _text(where, "reading", reading)}
        return self

    def hinge_angle_driver(self, name, node_a, hinge, node_b, profile, axis=None,
                           reading="angular_velocity"):
        """Drive the angle at `hinge` from hinge→`node_a` to hinge→`node_b`, about `axis`
        (required in 3D; z in 2D), from its initial value; reading "angular_velocity" (rad/s)
        or "angle" (rad). Fixes that one angle only."""
        where = "ModelBuilder.hinge_angle_driver"
        spec = {"type": "hinge_angle",
                "nodes": [_name(where, "node_a", node_a), _name(where, "hinge", hinge),
                          _name(where, "node_b", node_b)],
                "profile": _time_function(where, "profile", profile),
                "reading": _text(where, "reading", reading)}
        if axis is not None:
            spec["axis"] = _numbers(where, "axis", axis)
        self._section("drivers")[_name(where, "name", name)] = spec
        return self

    def coordinate_driver(self, name, node, direction, profile, reading="velocity"):
        """Prescribe coordinate `direction` ("x", "y", "z") of `node`; reading "velocity"
        (m/s) or "displacement" (m)."""
        where = "ModelBuilder.coordinate_driver"
        self._section("drivers")[_name(where, "name", name)] = {
            "type": "coordinate", "node": _name(where, "node", node),
            "direction": _text(where, "direction", direction),
            "profile": _time_function(where, "profile", profile),
            "reading": _text(where, "reading", reading)}
        return self

    def load(self, node, force=None, factor=None, moment=None):
        """A nodal force (N) and, in 2D on a beam's node, a moment (N·m, counter-clockwise),
        times factor(t) (default 1)."""
        where = "ModelBuilder.load"
        spec = {"node": _name(where, "node", node)}
        if force is not None:
            spec["force"] = _numbers(where, "force", force)
        if moment is not None:
            spec["moment"] = _number(where, "moment", moment)
        if factor is not None:
            spec["factor"] = _time_function(where, "factor", factor)
        self._section("loads", list).append(spec)
        return self

    def function(self, name, spec):
        """A named function of time, usable by name in profiles, dT and factors."""
        where = "ModelBuilder.function"
        self._section("functions")[_name(where, "name", name)] = _time_function(where, "spec", spec)
        return self

    def thermal(self, dT):
        """ΔT(t) (°C) of every bar without its own."""
        self._section("thermal")["dT"] = _time_function("ModelBuilder.thermal", "dT", dT)
        return self

    def environment(self, type, **keys):
        """The members' temperatures from their surroundings (docs/theory.md, "Temperatures from
        the environment"), as the model file's `environment`: type "orbit" (sun_direction,
        solar_constant, sink_temperature, eclipses, penumbra) or "ground" (latitude, longitude,
        start, utc_offset, up, north, direct_normal, diffuse, air_temperature, sky_temperature,
        convection), and reference_temperature and initial_temperature (K). Temperatures in K,
        fluxes in W/m². Not with `thermal`. Checked at `build` (InputError names
        environment.<key>)."""
        where = "ModelBuilder.environment"
        self._spec["environment"] = {"type": _text(where, "type", type), **_plain(keys, "environment", where)}
        return self

    def gravity(self, *g):
        """Gravity (m/s²), one component per axis: gravity(0, -9.81) or gravity([0, -9.81])."""
        values = g[0] if len(g) == 1 and not _is_number(g[0]) else g
        self._spec["gravity"] = _numbers("ModelBuilder.gravity", "g", values)
        return self

    def analysis(self, **options):
        """Analysis options as in the file: type ("static"/"dynamic"/"modal"), end, end_when
        ("end_time"/"all_latched"/"settled"), step, output_interval, load_steps, mass,
        integrator={...}, newton={...}, rayleigh={"alpha", "beta"} or {"ratios": [ζ1, ζ2],
        "frequencies": [f1, f2]} (Rayleigh damping), settle={"kinetic_energy", "rate", "hold",
        "node"} (with end_when="settled"). Their values are checked at `build` (InputError names
        analysis.<option>)."""
        self._section("analysis").update(_plain(options, "analysis", "ModelBuilder.analysis"))
        return self

    def output(self, **options):
        """Output options as in the file: history, summary (file names), vtk (bool), select={nodes,
        elements, quantities} (what history.csv holds: names or patterns, and column families such
        as "position", "displacement", "force", "stress", "reaction"). Checked at `build`."""
        self._section("output").update(_plain(options, "output", "ModelBuilder.output"))
        return self

    def to_dict(self):
        """The model file's content as a dict (a copy)."""
        return copy.deepcopy(self._spec)

    def build(self, overrides=None):
        """Check and return the Model; InputError names the field of any mistake."""
        return from_dict(self._spec, overrides=overrides)


# ---------------------------------------------------------------------------------------------
# Results


class Result:
    """The outcome of a run.

    columns: history.csv's column names; values: the history, one row per output time, as a
    2-D float array; history: {column: 1-D array}; summary: summary.json as a dict ({} when the
    folder has none); status: "completed", "failed" or "interrupted", and for a folder read
    with read_result also "running", "killed" or "unknown" (see folder_status), as it was when
    read; folder: the result folder, or None; n_dropped_rows: 1 when the history's incomplete
    last row was left out, else 0.
    """

    def __init__(self, columns, values, summary, folder=None, status=None, n_dropped_rows=0):
        self.columns = list(columns)
        self.values = np.asarray(values, dtype=float).reshape(-1, len(self.columns))
        self.history = {name: self.values[:, i].copy() for i, name in enumerate(self.columns)}
        self.summary = summary
        self.folder = pathlib.Path(folder) if folder is not None else None
        self.n_dropped_rows = n_dropped_rows
        self._status = status

    @property
    def status(self):
        """"completed", "failed" or "interrupted"; for a folder read with read_result also
        "running", "killed" or "unknown" (folder_status), as it was when read."""
        return self._status if self._status is not None else self.summary.get("status")

    @property
    def message(self):
        """summary.json's message; for a killed, running or unknown folder, what that means."""
        if self.status in ("killed", "running", "unknown"):
            return _result_folder.status_note(self.status)
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
    file = _path("read_envelopes", "file", file)
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
    folder = _path("read_result", "folder", folder)
    if history_file is not None:
        history_file = _path("read_result", "history_file", history_file)
    if summary_file is not None:
        summary_file = _path("read_result", "summary_file", summary_file)
    return _read_result(folder, history_file, summary_file, stacklevel=3)


def _read_result(folder, history_file, summary_file, stacklevel):
    folder = pathlib.Path(folder)
    summary_file = pathlib.Path(summary_file or folder / "summary.json")
    status, _ = _result_folder.read_status(folder, summary_file)
    try:
        summary = json.loads(summary_file.read_text(encoding="utf-8"))
    except FileNotFoundError:
        summary = {}
    except ValueError as error:
        raise ValueError(f"{summary_file}: not a JSON summary ({error})") from None
    if not isinstance(summary, dict):
        raise ValueError(f"{summary_file}: not a JSON summary (a {type(summary).__name__}, "
                         "not an object)")
    history_file = pathlib.Path(history_file or _result_folder.history_file_of(folder, summary))
    try:
        history = _result_folder.read_history(history_file, status=status,
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
    folder = _path("folder_status", "folder", folder)
    if status_file is not None:
        status_file = _path("folder_status", "status_file", status_file)
    return _result_folder.folder_status(folder, status_file)
