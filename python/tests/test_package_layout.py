"""The package split into modules by concern (deploydyn/_model.py, _builder.py, ...) behind a
thin __init__: every public name of the one-file package is still deploydyn.X, and is the
package's own (its __module__ "deploydyn", so help() and tracebacks read as before)."""
import inspect

import deploydyn

# dir(deploydyn) before the split, without the modules it imported for itself (copy, errno,
# json, math, np, numbers, os, pathlib): the public functions, classes and exceptions ...
PUBLIC_NAMES_BEFORE_THE_SPLIT = {
    "IncompleteHistoryWarning", "InputError", "Model", "ModelBuilder", "OutputError", "Result",
    "RunFailed", "constant", "cosine_ramp", "cycloidal", "folder_status", "from_dict", "harmonic",
    "load", "loads", "paper_eq23", "piecewise", "polynomial", "read_envelopes", "read_result",
    "roof", "run_study", "smooth_step", "smooth_trapezoid", "sum_of", "table"}
# Public names added since, each on purpose.
PUBLIC_NAMES_ADDED = {"report", "scissor"}
# ... and its public modules.
PUBLIC_MODULES_BEFORE_THE_SPLIT = {"result_folder", "study"}


def public(predicate):
    return {n for n in dir(deploydyn) if not n.startswith("_") and predicate(getattr(deploydyn, n))}


def test_the_public_names_are_those_before_the_split():
    assert public(lambda x: not inspect.ismodule(x)) == PUBLIC_NAMES_BEFORE_THE_SPLIT | PUBLIC_NAMES_ADDED
    assert set(deploydyn.__all__) == PUBLIC_NAMES_BEFORE_THE_SPLIT | PUBLIC_NAMES_ADDED
    modules = public(inspect.ismodule)
    assert PUBLIC_MODULES_BEFORE_THE_SPLIT <= modules
    # The modules by concern are private: no new public name.
    assert all(getattr(deploydyn, m).__name__.startswith("deploydyn.") for m in
               PUBLIC_MODULES_BEFORE_THE_SPLIT)
    assert {m for m in modules if getattr(deploydyn, m).__name__.startswith("deploydyn.")} == \
        PUBLIC_MODULES_BEFORE_THE_SPLIT


def test_the_public_names_are_the_packages_own():
    for name in PUBLIC_NAMES_BEFORE_THE_SPLIT - {"InputError", "OutputError"}:
        module = getattr(deploydyn, name).__module__
        assert module in ("deploydyn", "deploydyn.result_folder", "deploydyn.study"), (name, module)
    assert repr(deploydyn.ModelBuilder) == "<class 'deploydyn.ModelBuilder'>"
