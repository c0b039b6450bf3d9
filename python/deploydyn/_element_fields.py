"""The keys of every element type's entries, from the C++ field tables (ElementField,
ElementKind::fields(): what docs/model-format.md tabulates), and the ModelBuilder's checks of an
element's arguments made from them. A new element type, or a new key of one, needs no edit here:
the builder accepts the table's keys, rejects others naming the allowed ones, and asks for the
keys whose default is "required". Values are checked by the loader at `build`; here only their
Python type, by what the table's words say a key takes (`value_kind`)."""
import functools
from typing import NamedTuple

from deploydyn import _arguments as checked
from deploydyn import _core


class ElementField(NamedTuple):
    """One key of an element's entry, as the C++ table states it."""
    key: str
    unit: str     # SI; empty for names and plain numbers
    default: str  # "required" when the key must be given
    allowed: str  # what values are accepted, in words


@functools.cache
def element_fields():
    """{element type: {key: ElementField}}, in the loader's order of types and keys."""
    return {kind: {field[0]: ElementField(*field) for field in fields}
            for kind, fields in _core.element_fields().items()}


def value_kind(field):
    """What a key's value is, read from its table entry: "function" (a function of time),
    "names" (a list of node names), "name" (of a material or section), "numbers" (a vector),
    "number_or_numbers" (a vector in 3D, a number in 2D: a beam's sectional values), "number",
    or "value" (anything a model file holds: the loader alone checks it)."""
    if field.allowed.startswith("a function"):
        return "function"
    if field.allowed.startswith("a number or a vector"):
        return "number_or_numbers"
    if "node names" in field.allowed:
        return "names"
    if field.allowed.startswith("a name from"):
        return "name"
    if "a vector" in field.allowed or field.default.startswith("["):
        return "numbers"
    if field.unit or field.allowed.startswith((">", "≥", "<", "≤")):
        return "number"
    return "value"


_CHECKS = {
    "function": checked.time_function,
    "names": checked.names,
    "name": checked.name,
    "numbers": checked.numbers,
    "number_or_numbers": lambda where, key, value: (
        value if checked.is_number(value) else checked.numbers(where, key, value)),
    "number": checked.number,
    "value": lambda where, key, value: checked.plain(value, key, where),
}


def element_spec(where, type, fields):
    """The model file's entry of an element of `type` with `fields` ({key: value}), each key
    checked against the type's field table: an unknown type is a ValueError, an unknown key or
    a missing required one a TypeError, a value of the wrong Python type a TypeError naming the
    key (the loader checks the values themselves at `build`)."""
    tables = element_fields()
    if type not in tables:
        raise ValueError(f"{where}: type must be one of {', '.join(tables)}, not {type!r}")
    table = tables[type]
    for key in fields:
        if key not in table:
            raise TypeError(f"{where}: unexpected keyword argument {key!r}: a {type}'s keys are "
                            f"{', '.join(table)}")
    for field in table.values():
        if field.default == "required" and field.key not in fields:
            raise TypeError(f"{where}: a {type} needs {field.key!r} ({field.allowed})")
    return {key: _CHECKS[value_kind(table[key])](where, key, value) for key, value in fields.items()}
