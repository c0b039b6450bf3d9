"""deploydyn: deployment dynamics of flexible bar structures under thermal loading, from Python.

    import deploydyn
    model = deploydyn.load("examples/paper/general.yaml", overrides={"thermal.dT": 130})
    result = model.run()                        # in memory; model.run(out="results/hot") also
    result["mstrain.2"]                         # numpy array, a column of history.csv
    result.values, result.columns               # the whole history as (rows × columns)
    result.summary["drivers"]["motor"]["peak"]  # summary.json as a dict

Models come from a model file (`load`), from text (`loads`), from a dict in the file's layout
(`from_dict`), or from a `ModelBuilder`. Every model, however made, is read and checked by the
same C++ loader as the command line's, so the checks and messages are the CLI's.

Errors:
  - bad input (a model file, an override, a built model) raises `InputError`, a ValueError whose
    message is the CLI's one line `SOURCE:LINE:COLUMN: FIELD: PROBLEM`; its attributes `source`,
    `line`, `column` (None when unknown), `field` and `problem` hold the parts. A model whose
    mechanics cannot be built (e.g. a driven bar along its rotation axis) raises ValueError.
  - a solver failure is NOT an exception: `run` returns a Result whose `status` is "failed"
    (`result.ok` is False, `result.summary["failure"]` says where and why), like the CLI's exit
    code 1, and keeps the history up to the failure. `run(check=True)` or
    `result.raise_for_status()` raise `RunFailed` instead.
  - Ctrl-C during a run stops it after the current step and raises KeyboardInterrupt (a run
    into a folder keeps what was written, with status "interrupted" in summary.json).

`run` releases the GIL: runs of different models in threads go in parallel.
"""
import copy
import json
import math
import numbers
import pathlib

import numpy as np

from deploydyn import _core

InputError = _core.InputError

__all__ = [
    "InputError", "RunFailed", "Model", "Result", "ModelBuilder", "load", "loads", "from_dict", "roof",
    "read_result", "constant", "smooth_step", "smooth_trapezoid", "paper_eq23", "table",
]


class RunFailed(RuntimeError):
    """A run that did not complete, raised only on request (run(check=True),
    Result.raise_for_status()). `result` holds what was computed up to the failure."""

    def __init__(self, result):
        super().__init__(result.message)
        self.result = result


# ---------------------------------------------------------------------------------------------
# Overrides


def _value_text(value):
    """An override value as the text --set takes: numbers in their shortest exact form."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, str):
        return value
    raise TypeError(f"override value {value!r}: give a number or a text, not {type(value).__name__}")


def _override_pairs(overrides):
    """Overrides as (path, text) pairs, from a dict {path: value}, a "PATH=VALUE" string, or a
    list of such strings or (path, value) pairs."""
    if overrides is None:
        return []
    if isinstance(overrides, str):
        overrides = [overrides]
    if isinstance(overrides, dict):
        overrides = list(overrides.items())
    pairs = []
    for item in overrides:
        if isinstance(item, str):
            pairs.append(_core.parse_override(item))
        else:
            path, value = item
            pairs.append((str(path), _value_text(value)))
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
            path_or_overrides = {path_or_overrides: value}
        overrides = _merge(self._overrides, _override_pairs(path_or_overrides))
        self._core = self._load(overrides)
        self._overrides = overrides
        return self

    def with_overrides(self, overrides):
        """A new model: this one with `overrides` (dict, list or "PATH=VALUE") applied."""
        return Model(self._source, _merge(self._overrides, _override_pairs(overrides)))

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
        return self._core.name

    @property
    def description(self):
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
        """{name: {"nodes": (a, b), "material", "area" m², "mass" kg, "length" m (L0),
        "E" Pa, "alpha" 1/°C}}."""
        return {e["name"]: e for e in self._core.elements}

    @property
    def supports(self):
        """[{"node": name, "fix": ["x", "y"]}, ...]."""
        return self._core.supports

    @property
    def drivers(self):
        """{name: {"type", "element"/"pivot" or "node"/"direction", "reading",
        "effort": "torque" | "force"}}."""
        return {d["name"]: d for d in self._core.drivers}

    @property
    def analysis(self):
        """{"type", "end" s, "step" s, "output_interval" s, "load_steps"}."""
        return self._core.analysis

    @property
    def history_columns(self):
        """The columns of history.csv (and of Result.values) for this model."""
        return self._core.history_columns

    def temperature_changes(self, t=0.0):
        """{element: ΔT (°C) at time t}."""
        return dict(zip(self.elements, self._core.temperature_changes(t)))

    def to_yaml(self):
        """The model as a model file, every default explicit, overrides applied."""
        return self._core.to_yaml()

    def save(self, path):
        """Write to_yaml() to `path`; load(path) reads back the same model."""
        pathlib.Path(path).write_text(self.to_yaml(), encoding="utf-8")

    # -- running --------------------------------------------------------------------------------
    def run(self, out=None, check=False):
        """Run the analysis; return a Result.

        out: a folder to write history.csv and summary.json into, as `deploydyn run --out`
        does (the Result then reads them back: the values are the same to the last bit);
        None keeps everything in memory. check: raise RunFailed unless the run completed.
        """
        if out is None:
            raw = self._core.run_in_memory()
            result = Result(raw["columns"], raw["values"], json.loads(raw["summary_json"]))
        else:
            raw = self._core.run_into_folder(pathlib.Path(out))
            result = read_result(out, history_file=raw["history_file"],
                                 summary_file=raw["summary_file"])
        if check:
            result.raise_for_status()
        return result

    def __repr__(self):
        extra = f", overrides={dict(self._overrides)}" if self._overrides else ""
        return (f"<deploydyn.Model {self.name or '(unnamed)'!r} from {self.source}: "
                f"{len(self.nodes)} nodes, {len(self.elements)} bars{extra}>")


def load(path, overrides=None):
    """Read a model file (YAML or JSON), with overrides as --set applies them:
    {"thermal.dT": 130}, ["thermal.dT=130"] or [("thermal.dT", 130)]."""
    return Model(("file", str(path)), _override_pairs(overrides))


def loads(text, source_name="<string>", overrides=None):
    """Read a model from text in the model-file format; errors name `source_name` and the line."""
    return Model(("text", text, source_name, True), _override_pairs(overrides))


def from_dict(spec, source_name=None, overrides=None):
    """A model from a dict laid out as a model file ({"nodes": {...}, "elements": {...}, ...}).
    Errors name the field (e.g. elements.2.area) but no line: there is no file."""
    name = spec.get("name") if isinstance(spec, dict) else None
    source_name = source_name or (f"<model {name!r} built in Python>" if name else
                                  "<model built in Python>")
    text = json.dumps(spec, indent=1, ensure_ascii=False, allow_nan=True)
    return Model(("text", text, source_name, False), _override_pairs(overrides))


def roof(units, trusses=1, delta_t=130.0, overrides=None):
    """A foldable roof of the paper's parallel four-bar units, as `deploydyn generate roof` writes
    it: trusses=1 a planar truss of `units` units, trusses > 1 a 3D roof; posts deploy from 5° to
    upright in 5 s; delta_t (°C) is the model-wide temperature change."""
    text = _core.roof_yaml(int(units), int(trusses), float(delta_t))
    return Model(("text", text, f"<roof of {trusses} x {units} units>", False),
                 _override_pairs(overrides))


# ---------------------------------------------------------------------------------------------
# Time functions (for profiles, ΔT, load factors): what the model file's mappings hold.


def constant(value):
    return {"type": "constant", "value": value}


def smooth_step(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, ADAMS' cubic STEP in between."""
    return {"type": "smooth_step", "t0": t0, "v0": v0, "t1": t1, "v1": v1}


def smooth_trapezoid(amplitude, rise, fall):
    """0 → amplitude over rise = (t0, t1), held, back to 0 over fall = (t2, t3)."""
    return {"type": "smooth_trapezoid", "amplitude": amplitude, "rise": list(rise),
            "fall": list(fall)}


def paper_eq23(**changes):
    """The paper's Eq. (23) (amplitude 0.365, rise [0, 1], fall [4, 5]); keywords change parts."""
    spec = {"type": "paper_eq23"}
    spec.update({k: list(v) if isinstance(v, (tuple, list)) else v for k, v in changes.items()})
    return spec


def table(points):
    """Linear between (t, value) points, held constant outside."""
    return {"type": "table", "points": [[float(t), float(v)] for t, v in points]}


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
    table(...). Nothing is checked until `build`, which checks everything the loader checks.
    """

    def __init__(self, name="", description=""):
        self._spec = {"name": name} if name else {}
        if description:
            self._spec["description"] = description

    def _section(self, key, kind=dict):
        return self._spec.setdefault(key, kind())

    def node(self, name, x, y, z=None, mass=None):
        """A node at (x, y[, z]) m, with an optional point mass (kg)."""
        at = [x, y] if z is None else [x, y, z]
        self._section("nodes")[str(name)] = at if mass is None else {"at": at, "mass": mass}
        return self

    def material(self, name, E, alpha=0.0, density=None):
        """E (Pa), alpha (1/°C), density (kg/m³, for bars that give no mass)."""
        spec = {"E": E, "alpha": alpha}
        if density is not None:
            spec["density"] = density
        self._section("materials")[str(name)] = spec
        return self

    def bar(self, name, node_a, node_b, area, material, mass=None, length=None, dT=None):
        """A bar between two nodes: area (m²), mass (kg; default density·area·L0), length
        (m, the reference length L0; default the nodes' distance), dT (its own ΔT(t), °C)."""
        spec = {"nodes": [str(node_a), str(node_b)], "area": area, "material": str(material)}
        for key, value in (("mass", mass), ("length", length), ("dT", dT)):
            if value is not None:
                spec[key] = value
        self._section("elements")[str(name)] = spec
        return self

    def support(self, node, fix=None):
        """Fix a node's coordinates: all axes, or those in `fix` (e.g. ["y"])."""
        spec = {"node": str(node)}
        if fix is not None:
            spec["fix"] = list(fix)
        self._section("supports", list).append(spec)
        return self

    def bar_angle_driver(self, name, element, profile, pivot=None, reading="angular_velocity",
                         axis=None):
        """Turn bar `element` about `pivot` (default its first node); reading
        "angular_velocity" (profile ω(t), rad/s) or "angle" (rad)."""
        spec = {"type": "bar_angle", "element": str(element), "profile": profile,
                "reading": reading}
        if pivot is not None:
            spec["pivot"] = str(pivot)
        if axis is not None:
            spec["axis"] = list(axis)
        self._section("drivers")[str(name)] = spec
        return self

    def coordinate_driver(self, name, node, direction, profile, reading="velocity"):
        """Prescribe coordinate `direction` ("x", "y", "z") of `node`; reading "velocity"
        (m/s) or "displacement" (m)."""
        self._section("drivers")[str(name)] = {
            "type": "coordinate", "node": str(node), "direction": direction, "profile": profile,
            "reading": reading}
        return self

    def load(self, node, force, factor=None):
        """A nodal force (N), times factor(t) (default 1)."""
        spec = {"node": str(node), "force": list(force)}
        if factor is not None:
            spec["factor"] = factor
        self._section("loads", list).append(spec)
        return self

    def function(self, name, spec):
        """A named function of time, usable by name in profiles, dT and factors."""
        self._section("functions")[str(name)] = spec
        return self

    def thermal(self, dT):
        """ΔT(t) (°C) of every bar without its own."""
        self._section("thermal")["dT"] = dT
        return self

    def gravity(self, *g):
        """Gravity (m/s²), one component per axis."""
        self._spec["gravity"] = list(g[0]) if len(g) == 1 else list(g)
        return self

    def analysis(self, **options):
        """Analysis options as in the file: type ("static"/"dynamic"), end, step,
        output_interval, load_steps, mass, integrator={...}, newton={...}."""
        self._section("analysis").update(options)
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
    2-D float array; history: {column: 1-D array}; summary: summary.json as a dict; status:
    "completed", "failed" or "interrupted"; folder: the result folder, or None.
    """

    def __init__(self, columns, values, summary, folder=None):
        self.columns = list(columns)
        self.values = np.asarray(values, dtype=float).reshape(-1, len(self.columns))
        self.history = {name: self.values[:, i].copy() for i, name in enumerate(self.columns)}
        self.summary = summary
        self.folder = pathlib.Path(folder) if folder is not None else None

    @property
    def status(self):
        return self.summary.get("status")

    @property
    def message(self):
        return self.summary.get("message", "")

    @property
    def ok(self):
        return self.status == "completed"

    @property
    def failure(self):
        """Where and why it failed (summary.json's "failure"), or None."""
        return self.summary.get("failure")

    @property
    def t(self):
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

    def raise_for_status(self):
        """Raise RunFailed unless the run completed."""
        if not self.ok:
            raise RunFailed(self)
        return self

    def __repr__(self):
        return (f"<deploydyn.Result {self.status}: {self.values.shape[0]} rows × "
                f"{len(self.columns)} columns{f' in {self.folder}' if self.folder else ''}>")


def read_result(folder, history_file=None, summary_file=None):
    """A Result from a result folder written by `deploydyn run` or Model.run(out=...)."""
    folder = pathlib.Path(folder)
    history_file = pathlib.Path(history_file or folder / "history.csv")
    summary_file = pathlib.Path(summary_file or folder / "summary.json")
    with open(history_file, encoding="utf-8") as f:
        columns = f.readline().strip().split(",")
        rows = [line for line in f if line.strip()]
    values = (np.loadtxt(rows, delimiter=",", ndmin=2) if rows
              else np.empty((0, len(columns))))
    summary = json.loads(summary_file.read_text(encoding="utf-8"))
    return Result(columns, values, summary, folder=folder)
