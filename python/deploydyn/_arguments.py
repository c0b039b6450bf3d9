"""Argument checks: a message that names the function, the parameter and what it takes, before
a value reaches pybind11 ("incompatible function arguments") or the loader ("cannot open
file"). Every check takes `where` (the function, "ModelBuilder.bar") and the parameter's name."""
import math
from numbers import Integral, Real
import os
import pathlib

import numpy as np

INT_MAX = 2**31 - 1  # the C++ side's int


def shown(value):
    """`value` for a message: its type and a short repr."""
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def is_number(value):
    return isinstance(value, Real) and not isinstance(value, bool)


def count(where, name, value, minimum=1):
    """An int (not a bool, not a float even if whole) of at least `minimum`."""
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise TypeError(f"{where}: {name} must be an int, not {shown(value)}")
    value = int(value)
    if value < minimum:
        raise ValueError(f"{where}: {name} must be at least {minimum}, got {value}")
    if value > INT_MAX:
        raise ValueError(f"{where}: {name} must be at most {INT_MAX}, got {value}")
    return value


def number(where, name, value):
    """`value`, checked to be a real number (int or float, numpy's too; not a bool)."""
    if not is_number(value):
        raise TypeError(f"{where}: {name} must be a number (int or float), not {shown(value)}")
    return value


def finite(where, name, value):
    """A number that is not NaN or infinite, as a float."""
    value = float(number(where, name, value))
    if not math.isfinite(value):
        raise ValueError(f"{where}: {name} must be a finite number, got {value}")
    return value


def numbers(where, name, values):
    """A sequence of numbers (a list, tuple or 1-D array), checked, as a list."""
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise TypeError(f"{where}: {name} must be a sequence of numbers, not {shown(values)}")
    values = list(values)
    for i, value in enumerate(values):
        if not is_number(value):
            raise TypeError(f"{where}: {name}[{i}] must be a number, not {shown(value)}")
    return values


def text(where, name, value):
    if not isinstance(value, str):
        raise TypeError(f"{where}: {name} must be a str, not {shown(value)}")
    return value


def name(where, name, value):
    """A node, element, material, driver or function name: a str, or an int (as `1:` in a file)."""
    if isinstance(value, str):
        return value
    if isinstance(value, Integral) and not isinstance(value, bool):
        return str(int(value))
    raise TypeError(f"{where}: {name} must be a name (str, or int), not {shown(value)}")


def names(where, field, values):
    """A list of names (a hinge's nodes), each a str or an int."""
    if isinstance(values, (str, bytes, dict)) or not hasattr(values, "__iter__"):
        raise TypeError(f"{where}: {field} must be a list of names (str, or int), "
                        f"not {shown(values)}")
    return [name(where, f"{field}[{i}]", value) for i, value in enumerate(values)]


def path(where, name, value):
    """A file or folder path: a str or an os.PathLike (pathlib.Path), not empty."""
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{where}: {name} must be a path (str or pathlib.Path), "
                        f"not {shown(value)}")
    path = os.fspath(value)
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if not path:
        raise ValueError(f"{where}: {name} must not be empty")
    if "\0" in path:  # the operating system would see only the part before it
        raise ValueError(f"{where}: {name} must not hold a NUL character (\\0), got {shown(value)}")
    return pathlib.Path(path)


def stop(where, stop):
    """The `stop` argument of a long call: None, or what it asks is_set() of (threading.Event)."""
    if stop is not None and not callable(getattr(stop, "is_set", None)):
        raise TypeError(f"{where}: stop must be a threading.Event (or any object with is_set()) "
                        f"or None, not {shown(stop)}")
    return stop


def time_function(where, name, value):
    """A function of time as the model file takes it: a number, a function's name, or a dict
    (constant(...), smooth_step(...), ...)."""
    if is_number(value) or isinstance(value, str) or isinstance(value, dict):
        return value
    raise TypeError(f"{where}: {name} must be a number, a function's name (str) or a function "
                    f"(dict, e.g. deploydyn.smooth_step(...)), not {shown(value)}")


def plain(value, field, where):
    """`value` (a model file's content) with only what JSON holds: dicts with text keys, lists,
    text, numbers (numpy's as Python's), booleans, None. TypeError names the field."""
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, (np.ndarray, np.bool_)):
        return plain(value.tolist(), field, where)
    if isinstance(value, Integral):
        return int(value)
    if isinstance(value, Real):
        return float(value)
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            if isinstance(key, bool) or not isinstance(key, (str, Integral)):
                raise TypeError(f"{where}: {field or 'the model'}: keys must be names (str, or "
                                f"int), not {shown(key)}")
            key = str(key) if isinstance(key, str) else str(int(key))
            out[key] = plain(item, f"{field}.{key}" if field else key, where)
        return out
    if isinstance(value, (list, tuple)):
        return [plain(item, f"{field}.{i}", where) for i, item in enumerate(value)]
    raise TypeError(f"{where}: {field or 'the model'} must be a number, text, list or dict, "
                    f"not {shown(value)}")
