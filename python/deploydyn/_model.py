"""Models: Model (a validated model, and what it runs: run, continuation, modes, window), and the ways
to make one (load, loads, from_dict, roof, scissor). Every model is read by the C++ loader."""
import json

import numpy as np

from deploydyn import _arguments as checked
from deploydyn import _core
from deploydyn._overrides import merge_overrides, override_pairs
from deploydyn._results import Result, read_result_folder

# Times of one modal analysis, as the model file's analysis.at allows (docs/model-format.md,
# "Input limits"): each is a static solve and an eigenproblem.
MAX_MODAL_TIMES = 100_000


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
            path_or_overrides = {checked.text("Model.set", "path", path_or_overrides): value}
        overrides = merge_overrides(self._overrides, override_pairs("Model.set", path_or_overrides))
        self._core = self._load(overrides)
        self._overrides = overrides
        return self

    def with_overrides(self, overrides):
        """A new model: this one with `overrides` (dict, list or "PATH=VALUE") applied."""
        return Model(self._source,
                     merge_overrides(self._overrides, override_pairs("Model.with_overrides", overrides)))

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
        "alpha" 1/°C of its material (at the reference temperature when a table gives them),
        and "E_table", "alpha_table" ({"temperature_C": (...), "value": (...)}) when it does}}."""
        return {e["name"]: e for e in self._core.elements}

    @property
    def supports(self):
        """[{"node": name, "fix": ["x", "y"], and "axis" (a hinge to ground), "offset" (m) when
        given}, ...]."""
        return self._core.supports

    @property
    def joints(self):
        """{name: {"type": "pin", "ball" or "universal", "nodes": [A, B], and "axis" (a pin in
        3D between beam nodes), "arms" (universal), "offsets" (m, when given)}}."""
        return {j["name"]: j for j in self._core.joints}

    @property
    def drivers(self):
        """{name: {"type", then by type: bar_angle "element", "pivot" (3D "axis"); coordinate
        "node", "direction"; revolute "joint" or "support"; hinge_angle "nodes" [A, H, B] (3D "axis");
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
        t = float(checked.number("Model.temperature_changes", "t", t))
        return dict(zip(self.elements, self._core.temperature_changes(t)))

    def to_yaml(self):
        """The model as a model file, every default explicit, overrides applied."""
        return self._core.to_yaml()

    def save(self, path):
        """Write to_yaml() to `path`; load(path) reads back the same model."""
        checked.path("Model.save", "path", path).write_text(self.to_yaml(), encoding="utf-8")

    # -- running --------------------------------------------------------------------------------
    def run(self, out=None, check=False, stop=None, restart_from=None, at=None, keep_every_state=False):
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
        restart_from: a result folder of an earlier run of this model (its states.bin): the run
        starts from the last state it kept, or with `at` (s) from the one kept at that output
        time, and continues that run bit for bit, as `deploydyn run --restart-from DIR --at T`
        (docs/model-format.md, "Restart"); a modal analysis takes the modes of that state. A
        folder that holds no state this model can start from raises ValueError naming
        restart_from or at. keep_every_state (with out): states.bin keeps every output time's
        state, not only the last, as `--keep-every-state`.
        """
        where = "Model.run"
        if not isinstance(check, bool):
            raise TypeError(f"{where}: check must be a bool, not {checked.shown(check)}")
        if not isinstance(keep_every_state, bool):
            raise TypeError(f"{where}: keep_every_state must be a bool, not {checked.shown(keep_every_state)}")
        stop = checked.stop(where, stop)
        if restart_from is not None:
            restart_from = checked.path(where, "restart_from", restart_from)
        if at is not None:
            if restart_from is None:
                raise ValueError(f"{where}: at (s) chooses a state of restart_from; give restart_from too")
            at = checked.finite(where, "at", at)
        if keep_every_state and out is None:
            raise ValueError(f"{where}: keep_every_state keeps states in out's states.bin; give out too")
        with _restart_names(where):
            if out is None:
                raw = self._core.run_in_memory(stop, restart_from, at)
                temperatures = ({name: raw["temperature_values"][:, i].copy()
                                 for i, name in enumerate(raw["temperature_columns"])}
                                if "temperature_columns" in raw else {})
                result = Result(raw["columns"], raw["values"], json.loads(raw["summary_json"]),
                                temperatures=temperatures)
            else:
                out = checked.path(where, "out", out)
                raw = self._core.run_into_folder(out, stop, restart_from, at, keep_every_state)
                result = read_result_folder(out, raw["history_file"], raw["summary_file"], stacklevel=3)
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
        positions, ΔT(t) and the loads are read (`time` is not used). A model with an
        `environment` is traced in its steady temperature field at `time` (docs/theory.md, "The
        steady field of an environment"). With `switch_branch`, the
        path leaves at its first bifurcation along the critical mode and follows the bifurcated
        branch. stop_at: "end" (the path goes on to `end`) or "first_event" (it ends at its first
        event, that event its last point, "end" then "first_event"), as the model key `stop_at`.
        Returns a dict: "mu", "displacement_norm" (m), "eigenvalues" (points × eigenvalues,
        N/m, of the tangent stiffness on the constraint-compatible motions; NaN when not
        computed), "n_negative", "q" (points × coordinates), "coordinates" (the labels of q's
        columns, such as "x.B", as in Model.modes), "columns" and "values" (points × columns:
        what path.csv holds after its own columns, the columns of history.csv at each point
        with output.select applied, but t and the energies: positions "x.B" (m), forces
        "force.b1" (N), reactions, ...), "events" (dicts with "kind"
        limit_point | bifurcation | singular_constraints, "mu", "mu_error", "point", "mode",
        "axial_forces", "description"), "end" and "message" (how it ended: "stopped" once
        `stop`, a threading.Event as for run, is set)."""
        where = "Model.continuation"
        parameter = checked.text(where, "parameter", parameter)
        end = checked.finite(where, "end", end)
        start = checked.finite(where, "start", start)
        eigenvalues = checked.count(where, "eigenvalues", eigenvalues, minimum=0)
        max_steps = checked.count(where, "max_steps", max_steps)
        time = checked.finite(where, "time", time)
        if not isinstance(switch_branch, bool):
            raise TypeError(f"{where}: switch_branch must be a bool, not {checked.shown(switch_branch)}")
        if stop_at not in ("end", "first_event"):
            raise ValueError(f"{where}: stop_at must be 'end' or 'first_event', not {checked.shown(stop_at)}")
        stop = checked.stop(where, stop)
        raw = self._core.continuation(parameter, start, end, eigenvalues, max_steps, time, switch_branch,
                                      stop_at, stop)
        out = dict(raw)
        for key in ("mu", "displacement_norm", "eigenvalues", "n_negative", "q", "values"):
            out[key] = np.asarray(raw[key])
        out["coordinates"] = list(raw["coordinates"])
        out["columns"] = list(raw["columns"])
        out["events"] = [dict(e, mode=np.asarray(e["mode"]), axial_forces=np.asarray(e["axial_forces"]))
                         for e in raw["events"]]
        return out

    def window(self, dT=None, positions=21, deployments=9, out=None, stop=None, load="uniform", scale=None,
               environment_time=None):
        """The deployability window, as `deploydyn window` computes it (docs/theory.md, "The
        deployability window"): over a range of thermal load levels, where the deployment stays
        stress-free, is stressed, jams or snaps, the thresholds located by continuation in the
        level at `positions` driver positions (1 to 10 000) over the analysis time, and
        `deployments` levels (0 to 1000) deployed quasi-statically, each with its verdict.
        load: "uniform" (the same ΔT on every member, over dT = (lo, hi), lo ≤ 0 ≤ hi, °C;
        default (-200, 200)) or "model" (the model's own ΔT and through-depth differences times
        a scale μ over scale = (lo, hi), lo ≤ 0 ≤ hi; default (-2, 2); every "dT" of the result
        is then μ, and "pattern" gives the model's values at μ = 1; for a model with an
        `environment` the load is the members' steady temperatures in the environment's state at
        environment_time (s, default 0), the structure as the file places it). With `out`, window.csv and
        window.json are written into that folder as the command's --out writes them. Returns
        window.json's content as a dict ("cold" and "hot": "reach", "threshold" {dT, dT_error,
        kind, t, description} or None, the first event per position in "edges"; "regimes" every
        10 °C or 0.05 of μ; "deployments" with their "verdict" and, where one jams, "stressed":
        the stressed equilibrium it sits on instead; "status") and "samples": window.csv's
        columns as numpy arrays ("t", "dT", "lowest_eigenvalue", "peak_axial_force",
        "peak_mstrain", "driver_effort", and "branch": "traced" or "stressed"). stop: a
        threading.Event as for run; once set, the window ends "interrupted" with what it has."""
        where = "Model.window"
        if load not in ("uniform", "model"):
            raise ValueError(f"{where}: load must be 'uniform' or 'model', not {checked.shown(load)}")
        name, given, unit = ("scale", scale, "") if load == "model" else ("dT", dT, " (°C)")
        wrong = dT if load == "model" else scale
        if wrong is not None:
            raise ValueError(f"{where}: with load={load!r} the range is `{name}`, not "
                             f"`{'dT' if load == 'model' else 'scale'}`")
        if given is None:
            given = (-2.0, 2.0) if load == "model" else (-200.0, 200.0)
        if checked.is_number(given) or isinstance(given, str) or len(given) != 2:
            raise TypeError(f"{where}: {name} must be a pair (lo, hi){unit}, not {checked.shown(given)}")
        lo, hi = (checked.finite(where, f"{name}[{i}]", value) for i, value in enumerate(given))
        if not lo <= 0.0 <= hi or lo == hi:
            raise ValueError(f"{where}: {name} must be (lo, hi) with lo ≤ 0 ≤ hi and lo < hi{unit}, got ({lo}, {hi})")
        positions = checked.count(where, "positions", positions)
        deployments = checked.count(where, "deployments", deployments, minimum=0)
        if positions > 10000 or deployments > 1000:
            raise ValueError(f"{where}: at most 10000 positions and 1000 deployments, got {positions} and {deployments}")
        folder = None if out is None else checked.path(where, "out", out)
        if environment_time is not None and load != "model":
            raise ValueError(f"{where}: environment_time is the environment state of load='model'")
        at = 0.0 if environment_time is None else checked.finite(where, "environment_time", environment_time)
        overrides = [f"{path}={value}" for path, value in self._overrides]
        raw = self._core.window(str(self.source), overrides, lo, hi, positions, deployments, folder,
                                checked.stop(where, stop), load, at)
        result = json.loads(raw["json"])
        result["samples"] = {name: np.asarray(values) for name, values in raw["samples"].items()}
        return result

    def modes(self, count=10, at=0.0, stop=None, hinges="free", from_=None):
        """Natural frequencies and modes about the static equilibrium at time(s) `at` (the
        thermal state at t = 0, then the drivers moved quasi-statically), as `deploydyn modes`
        computes them. Returns a dict of numpy arrays: "times" (s), "omega2" (rad²/s², times ×
        count, ascending; < 0: unstable), "frequency" (Hz, NaN where ω² < 0), "modes" (times ×
        coordinates × count, M-orthonormal), "coordinates" (labels such as "x.B"), "failures"
        (per time "" or why no modes were found; those rows are NaN). count: 1 to the model's
        coordinates − constraint equations; at: a time ≥ 0 or a list of 1 to 100 000 of them,
        as the model file's analysis.at (ValueError beyond). stop: a threading.Event as for
        run; once set, the times not reached are failures "stopped ...". hinges: what holds the
        hinges of a spring-driven structure, as `deploydyn modes --hinges`: "free" (as they are),
        "held" (every hinge with a spring, latch, stop or friction held at its initial angle, the
        stowed structure) or "latched" (every latch locked at its latch angle, the deployed
        structure); docs/theory.md, "Modes of stowed and deployed states". A model with an
        `environment` has its modes in the environment's steady temperature field at t = 0
        (docs/theory.md, "The steady field of an environment"). from_: a result folder
        of a run of this model, as `deploydyn modes --from`: the modes of the last state it kept
        (its positions, time and hinge modes), at that state's time ("times"); `at` and
        `hinges` are then not used."""
        where = "Model.modes"
        count = checked.count(where, "count", count)  # at most the free coordinates: checked by _core
        if hinges not in ("free", "held", "latched"):
            raise ValueError(f"{where}: hinges must be 'free', 'held' or 'latched', not {checked.shown(hinges)}")
        if from_ is not None:
            from_ = checked.path(where, "from_", from_)
        times = checked.numbers(where, "at", [at] if checked.is_number(at) else at)
        if not 1 <= len(times) <= MAX_MODAL_TIMES:
            raise ValueError(f"{where}: at must be a time or a list of 1 to {MAX_MODAL_TIMES} "
                             f"times (s), got {len(times)}")
        for i, t in enumerate(times):
            times[i] = checked.finite(where, f"at[{i}]", t)
            if times[i] < 0:
                raise ValueError(f"{where}: at[{i}] must be a time ≥ 0 (s), got {times[i]}")
        with _restart_names(where, folder="from_"):
            raw = self._core.modes(count, times, checked.stop(where, stop), hinges, from_)
        omega2 = np.asarray(raw["omega2"])
        with np.errstate(invalid="ignore"):
            frequency = np.where(omega2 >= 0, np.sqrt(np.abs(omega2)) / (2 * np.pi), np.nan)
        return {"times": np.asarray(raw["times"]), "omega2": omega2, "frequency": frequency,
                "modes": np.asarray(raw["modes"]), "coordinates": list(raw["coordinates"]),
                "failures": list(raw["failures"])}

    def __repr__(self):
        extra = f", overrides={dict(self._overrides)}" if self._overrides else ""
        return (f"<deploydyn.Model {self.name or '(unnamed)'!r} from {self.source}: "
                f"{len(self.nodes)} nodes, {len(self.elements)} bars{extra}>")


class _restart_names:
    """Names a restart's errors by the Python arguments (restart_from or from_, at) instead of
    the command line's options (--restart-from, --at) that the C++ messages name."""

    def __init__(self, where, folder="restart_from"):
        self._where, self._folder = where, folder

    def __enter__(self):
        return self

    def __exit__(self, kind, error, traceback):
        if kind is ValueError and ("(--restart-from)" in str(error) or "(--at)" in str(error)):
            message = str(error).replace("(--restart-from)", f"({self._folder})").replace("(--at)", "(at)")
            raise ValueError(f"{self._where}: {message}") from None
        return False


def load(path, overrides=None):
    """Read a model file (YAML or JSON), with overrides as --set applies them:
    {"thermal.dT": 130}, ["thermal.dT=130"] or [("thermal.dT", 130)]."""
    path = checked.path("load", "path", path)
    return Model(("file", str(path)), override_pairs("load", overrides))


def loads(text, source_name="<string>", overrides=None):
    """Read a model from text in the model-file format; errors name `source_name` and the line."""
    checked.text("loads", "text", text)
    checked.text("loads", "source_name", source_name)
    return Model(("text", text, source_name, True), override_pairs("loads", overrides))


def from_dict(spec, source_name=None, overrides=None):
    """A model from a dict laid out as a model file ({"nodes": {...}, "elements": {...}, ...}).
    Errors name the field (e.g. elements.2.area) but no line: there is no file. Values may be
    numpy numbers or arrays; anything JSON cannot hold is a TypeError naming the field."""
    if not isinstance(spec, dict):
        raise TypeError("from_dict: spec must be a dict laid out as a model file, "
                        f"not {checked.shown(spec)}")
    if source_name is not None:
        checked.text("from_dict", "source_name", source_name)
    spec = checked.plain(spec, "", "from_dict")
    name = spec.get("name")
    source_name = source_name or (f"<model {name!r} built in Python>" if name else
                                  "<model built in Python>")
    text = json.dumps(spec, indent=1, ensure_ascii=False, allow_nan=True)
    return Model(("text", text, source_name, False), override_pairs("from_dict", overrides))


def roof(units, trusses=1, delta_t=130.0, bearings="sliding", overrides=None):
    """A foldable roof of the paper's parallel four-bar units, as `deploydyn generate roof` writes
    it: trusses=1 a planar truss of `units` units, trusses > 1 a 3D roof; posts deploy from 5° to
    upright in 5 s; delta_t (°C) is the model-wide temperature change; bearings "sliding"
    (expansion bearings and bottom members: free to expand, the default) or "pinned" (every foot
    pinned to a ground that does not expand). units and trusses are ints (a float, even 2.0, is
    refused: TypeError)."""
    units = checked.count("roof", "units", units)
    trusses = checked.count("roof", "trusses", trusses)
    delta_t = float(checked.number("roof", "delta_t", delta_t))
    bearings = checked.text("roof", "bearings", bearings)
    text = _core.roof_yaml(units, trusses, delta_t, bearings)
    return Model(("text", text, f"<roof of {trusses} x {units} units>", False),
                 override_pairs("roof", overrides))



def scissor(form="polar", units=None, span=None, hinge_offset=None, folded_angle=None, deployed_angle=None,
            elements=None, area=None, inertia=None, depth=None, delta_t=None, gradient=None,
            deploy_time=None, end_time=None, overrides=None):
    """A planar scissor structure of beams pinned at their central hinges, as `deploydyn generate
    scissor` writes it (docs/scissor-structures.md): form "translational" (straight girder),
    "polar" (circular arch, hinges `hinge_offset` off mid-length, a share of the half-length in
    (0, 0.9]) or "ring" (Hoberman's angulated units; units a multiple of 4, ≥ 8), `units`
    scissor units, deployed `span` (m: between the arch's feet, or the ring's outer diameter),
    opening angles at the central hinges folded and deployed (degrees), `elements` beam
    elements from a member's end to its hinge, the members' `area` (m²), `inertia` (m⁴) and
    `depth` (m), a uniform `delta_t` and a through-depth `gradient` (°C), opened by a revolute
    actuator in `deploy_time` and held to `end_time` (s). None (the default) takes the
    command's default (`deploydyn generate scissor --help`: 6 units, 10 m, ΔT = 130 °C, ...). A
    value out of range raises ValueError naming it, as the command does."""
    where = "scissor"
    form = checked.text(where, "form", form)
    given = {}
    for name, value in (("units", units), ("elements", elements)):
        if value is not None:
            given[name] = checked.count(where, name, value)
    for name, value in (("span", span), ("hinge_offset", hinge_offset), ("folded_angle", folded_angle),
                        ("deployed_angle", deployed_angle), ("area", area), ("inertia", inertia),
                        ("depth", depth), ("delta_t", delta_t), ("gradient", gradient),
                        ("deploy_time", deploy_time), ("end_time", end_time)):
        if value is not None:
            given[name] = float(checked.number(where, name, value))
    text = _core.scissor_yaml(form, given)
    return Model(("text", text, f"<scissor {form}>", False), override_pairs(where, overrides))
