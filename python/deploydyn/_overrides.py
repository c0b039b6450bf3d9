"""Overrides of model values, as the command line's --set takes them: from a dict {path: value},
a "PATH=VALUE" text, or a list of such texts or (path, value) pairs, to (path, value text)
pairs for the loader."""
import json
import numbers

from deploydyn import _arguments as checked
from deploydyn import _core


def value_text(where, path, value):
    """An override value as the text --set takes: numbers in their shortest exact form; a dict
    or list (a function such as smooth_step(...), a list of axes) as a YAML flow value, which
    JSON is."""
    if isinstance(value, (dict, list, tuple)):
        return json.dumps(checked.plain(list(value) if isinstance(value, tuple) else value, path, where),
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
                    f"or list, not {checked.shown(value)}")


OVERRIDES_TAKE = ("a dict {path: value}, a 'PATH=VALUE' text, or a list of such texts or "
                   "(path, value) pairs")


def override_pairs(where, overrides):
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
        raise TypeError(f"{where}: overrides must be {OVERRIDES_TAKE}, not {checked.shown(overrides)}")
    pairs = []
    for item in overrides:
        if isinstance(item, str):
            pairs.append(_core.parse_override(item))
        elif isinstance(item, (list, tuple)) and len(item) == 2:
            path = checked.text(where, "an override's path", item[0])
            pairs.append((path, value_text(where, path, item[1])))
        else:
            raise TypeError(f"{where}: overrides must be {OVERRIDES_TAKE}; "
                            f"an item is {checked.shown(item)}")
    return pairs


def merge_overrides(pairs, new_pairs):
    """Earlier overrides with new ones; a new one of the same path replaces the earlier."""
    paths = {path for path, _ in new_pairs}
    return [p for p in pairs if p[0] not in paths] + list(new_pairs)
