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
    deploydyn.report("results/hot")             # results/hot/report.html, as `deploydyn report`
    model.window(dT=(-170, 130))                # the deployability window, as `deploydyn window`

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
# The package is thin: each concern is a private module, and this file re-exports their public
# names, so that `deploydyn.X` is the one way to reach them.
#   _arguments       checks of Python arguments, with messages naming function and parameter
#   _overrides       overrides as --set takes them
#   _model           Model, load, loads, from_dict, roof, scissor: models and what they run
#   _builder         ModelBuilder: a model in code
#   _element_fields  the element types' keys, from the C++ field tables (ElementKind::fields())
#   _time_functions  constant, smooth_step, ...: functions of time as the model file writes them
#   _results         Result, RunFailed, read_result, read_envelopes, folder_status, report
#   result_folder    reading a result folder's status and history (public module)
#   study            run_study (public module)
from deploydyn import _core
from deploydyn._builder import ModelBuilder
from deploydyn._model import Model, from_dict, load, loads, roof, scissor
from deploydyn._results import Result, RunFailed, folder_status, read_envelopes, read_result, report
from deploydyn._time_functions import (constant, cosine_ramp, cycloidal, harmonic, paper_eq23,
                                       piecewise, polynomial, smooth_step, smooth_trapezoid,
                                       sum_of, table)
from deploydyn.result_folder import IncompleteHistoryWarning
from deploydyn.study import run_study
from deploydyn import result_folder, study  # noqa: F401 (public modules, as before the split)

InputError = _core.InputError
OutputError = _core.OutputError
# The project's version (CMakeLists.txt `project(deploydyn VERSION ...)`), as `deploydyn --version`.
__version__ = _core.__version__

__all__ = [
    "InputError", "OutputError", "RunFailed", "IncompleteHistoryWarning", "Model", "Result",
    "ModelBuilder", "load", "loads", "from_dict", "roof", "read_result", "read_envelopes", "folder_status",
    "report", "run_study", "scissor",
    "constant", "smooth_step", "smooth_trapezoid", "paper_eq23", "table",
    "polynomial", "harmonic", "cosine_ramp", "cycloidal", "piecewise", "sum_of",
]

# What the private modules define shows as deploydyn's own (help(), tracebacks, repr of a
# class), as before the split; the private module layout is free to change.
for _name in __all__:
    _public = globals()[_name]
    if getattr(_public, "__module__", "").startswith("deploydyn._") and _public.__module__ != "deploydyn._core":
        _public.__module__ = __name__
del _name, _public
