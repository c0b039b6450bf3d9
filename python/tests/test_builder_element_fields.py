"""ModelBuilder's element arguments are checked against the C++ field tables (ElementField,
ElementKind::fields(), through deploydyn._core.element_fields()), not against a Python copy of
them: for every type and every key of its table the builder takes the key and its kind of value,
rejects an unknown key naming the allowed ones, asks for a missing required key by name; and a
key or type added to the tables is taken with no Python edit."""
import pytest

import deploydyn
from deploydyn import _core, _element_fields

# One value of each kind, and one that is none of them. (The builder checks the kind; the
# loader checks the value at build.)
SAMPLE = {"function": deploydyn.smooth_step(0, 0, 1, 5), "names": ["A", "B"], "name": "steel",
          "numbers": [0.0, 0.0, 1.0], "number_or_numbers": [5.0e6, 23.4e6], "number": 2.5, "value": 2.5}
WRONG = {"function": [1, 2], "names": 3.5, "name": 1.5, "numbers": "up", "number_or_numbers": "stiff",
         "number": "2.5", "value": {1.5}}


def tables():
    return _element_fields.element_fields()


def required(type):
    return {f.key: SAMPLE[_element_fields.value_kind(f)]
            for f in tables()[type].values() if f.default == "required"}


def test_the_tables_are_the_loaders_and_the_docs():
    """The binding gives every type of the loader with its keys in the table's order; each key
    is documented in docs/model-format.md's table of its type."""
    raw = _core.element_fields()
    assert {"bar", "beam", "cable", "hinge"} <= set(raw)
    assert [f[0] for f in raw["bar"]][:3] == ["nodes", "area", "section"]
    assert all(len(f) == 4 and all(isinstance(part, str) for part in f) for fs in raw.values() for f in fs)
    docs = (__import__("conftest").SOURCE_DIR / "docs" / "model-format.md").read_text(encoding="utf-8")
    for fields in raw.values():
        for key, unit, default, allowed in fields:
            assert f"`{key}`" in docs, key


def test_the_words_of_the_tables_give_the_kinds_of_value():
    """What the table says a key takes: today's keys each have a kind the builder checks (a key
    whose words say none would still be taken, as "value", and checked by the loader alone)."""
    kinds = {(t, k): _element_fields.value_kind(f) for t, fs in tables().items() for k, f in fs.items()}
    assert "value" not in kinds.values(), [tk for tk, kind in kinds.items() if kind == "value"]
    assert kinds[("bar", "nodes")] == "names" and kinds[("hinge", "rotation_nodes")] == "names"
    assert kinds[("bar", "material")] == "name" and kinds[("cable", "section")] == "name"
    assert kinds[("beam", "orientation")] == "numbers" and kinds[("hinge", "axis")] == "numbers"
    assert kinds[("cable", "rest_length")] == "function" and kinds[("beam", "dT_gradient_z")] == "function"
    assert kinds[("hinge", "friction")] == "number" and kinds[("beam", "shear_factor")] == "number"
    assert kinds[("beam", "mass_per_length")] == "number" and kinds[("beam", "torsional_stiffness")] == "number"
    assert all(kinds[("beam", key)] == "number_or_numbers"
               for key in ("rotary_inertia_per_length", "shear_stiffness", "bending_stiffness"))


@pytest.mark.parametrize("type, key", [(t, k) for t, fs in _element_fields.element_fields().items()
                                       for k in fs])
def test_every_key_of_every_table_is_taken_and_its_kind_checked(type, key):
    field = tables()[type][key]
    kind = _element_fields.value_kind(field)
    builder = deploydyn.ModelBuilder().element("e", type, **{**required(type), key: SAMPLE[kind]})
    assert builder.to_dict()["elements"]["e"][key] == SAMPLE[kind]
    with pytest.raises(TypeError, match=rf"^ModelBuilder\.element: {key}\b"):
        deploydyn.ModelBuilder().element("e", type, **{**required(type), key: WRONG[kind]})


@pytest.mark.parametrize("type", list(_element_fields.element_fields()))
def test_an_unknown_key_is_refused_naming_the_allowed_ones(type):
    with pytest.raises(TypeError) as error:
        deploydyn.ModelBuilder().element("e", type, **required(type), colour="red")
    message = str(error.value)
    assert message.startswith("ModelBuilder.element: unexpected keyword argument 'colour'")
    assert all(key in message for key in tables()[type])


@pytest.mark.parametrize("type, key", [(t, f.key) for t, fs in _element_fields.element_fields().items()
                                       for f in fs.values() if f.default == "required"])
def test_a_missing_required_key_is_named(type, key):
    fields = required(type)
    del fields[key]
    with pytest.raises(TypeError, match=rf"^ModelBuilder\.element: a {type} needs '{key}' \("):
        deploydyn.ModelBuilder().element("e", type, **fields)


def test_there_are_required_keys_to_test():
    assert {t for t, fs in tables().items() if any(f.default == "required" for f in fs.values())} >= \
        {"bar", "beam", "cable"}


def test_an_unknown_type_names_the_types():
    with pytest.raises(ValueError, match=r"^ModelBuilder\.element: type must be one of bar, beam, "
                                         r"cable, hinge(, \w+)*, not 'truss'$"):
        deploydyn.ModelBuilder().element("e", "truss", nodes=["A", "B"])


def test_the_methods_take_the_other_keys_by_name():
    b = (deploydyn.ModelBuilder()
         .bar("b", "A", "B", area=1e-4, material="steel", inertia=1e-9)
         .cable("c", "A", "B", area=1e-5, material="steel", break_load=5e3)
         .beam("m", "A", "B", area=1e-4, inertia_z=1e-9, material="steel", section_modulus_z=1e-7))
    elements = b.to_dict()["elements"]
    assert elements["b"]["inertia"] == 1e-9 and elements["c"]["break_load"] == 5e3
    assert elements["m"]["section_modulus_z"] == 1e-7
    with pytest.raises(TypeError, match=r"^ModelBuilder\.beam: unexpected keyword argument 'spin'"):
        deploydyn.ModelBuilder().beam("m", "A", "B", area=1e-4, inertia_z=1e-9, material="s", spin=1)
    with pytest.raises(TypeError, match=r"^ModelBuilder\.bar: 'nodes' is a parameter of its own"):
        deploydyn.ModelBuilder().bar("b", "A", "B", area=1e-4, material="s", nodes=["A", "B"])
    with pytest.raises(TypeError, match=r"^ModelBuilder\.hinge: nodes\[1\] must be a name"):
        deploydyn.ModelBuilder().hinge("h", nodes=["A", None, "B"])


@pytest.fixture
def added_to_the_tables(monkeypatch):
    """The C++ tables with a key added to the bar ("spin", a number in rad/s) and a new type
    ("strut"): what a C++ edit alone would give."""
    real = _core.element_fields()
    grown = dict(real, bar=real["bar"] + [("spin", "rad/s", "none", "> 0: a made-up key")],
                 strut=[("nodes", "", "required", "two different node names"),
                        ("material", "", "required", "a name from `materials`"),
                        ("preload", "N", "0", "≥ 0: a made-up key")])
    monkeypatch.setattr(_core, "element_fields", lambda: grown)
    _element_fields.element_fields.cache_clear()
    yield
    _element_fields.element_fields.cache_clear()


def test_a_key_or_type_added_to_the_tables_needs_no_python_edit(added_to_the_tables):
    b = deploydyn.ModelBuilder().bar("1", "A", "B", area=1e-4, material="steel", spin=3.0)
    b.element("2", "bar", nodes=["A", "B"], area=1e-4, material="steel", spin=4.0)
    b.element("3", "strut", nodes=["A", "B"], material="steel", preload=10.0)
    elements = b.to_dict()["elements"]
    assert elements["1"]["spin"] == 3.0 and elements["2"]["spin"] == 4.0
    assert elements["3"] == {"type": "strut", "nodes": ["A", "B"], "material": "steel", "preload": 10.0}
    with pytest.raises(TypeError, match=r"^ModelBuilder\.bar: spin must be a number"):
        deploydyn.ModelBuilder().bar("1", "A", "B", area=1e-4, material="steel", spin="fast")
    with pytest.raises(TypeError, match=r"^ModelBuilder\.element: a strut needs 'material'"):
        deploydyn.ModelBuilder().element("3", "strut", nodes=["A", "B"])
