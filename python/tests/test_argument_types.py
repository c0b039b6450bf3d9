"""Arguments of the wrong type: TypeError (or ValueError for a value out of range) naming the
function, the parameter and what it takes, never pybind11's "incompatible function arguments",
the loader's "cannot open file", or a silent conversion (roof(1.7) once built 1 unit)."""
import pathlib

import numpy as np
import pytest

import deploydyn

NOT_A_COUNT = [(1.7, "float 1.7"), (2.0, "float 2.0"), (True, "bool True"), ("2", "str '2'"),
               (None, "NoneType None")]


@pytest.mark.parametrize("value, shown", NOT_A_COUNT)
@pytest.mark.parametrize("parameter", ["units", "trusses"])
def test_roof_counts_are_ints(parameter, value, shown):
    arguments = {"units": 2, "trusses": 1, parameter: value}
    with pytest.raises(TypeError) as error:
        deploydyn.roof(**arguments)
    assert str(error.value) == f"roof: {parameter} must be an int, not {shown}"


def test_roof_counts_in_range_and_numpy_ints():
    with pytest.raises(ValueError, match=r"^roof: units must be at least 1, got 0$"):
        deploydyn.roof(0)
    with pytest.raises(ValueError,
                       match=r"^roof: trusses must be at most 2147483647, got 2147483648$"):
        deploydyn.roof(1, trusses=2**31)
    assert len(deploydyn.roof(np.int64(2), bearings="pinned").elements) == 5


def test_roof_temperature_is_a_number():
    with pytest.raises(TypeError,
                       match=r"^roof: delta_t must be a number \(int or float\), not str 'hot'$"):
        deploydyn.roof(1, delta_t="hot")
    with pytest.raises(TypeError, match="roof: delta_t must be a number"):
        deploydyn.roof(1, delta_t=True)
    assert deploydyn.roof(1, delta_t=np.float32(10)).temperature_changes()["post0"] == 10.0


@pytest.mark.parametrize("call, message", [
    (lambda: deploydyn.load(3), "load: path must be a path (str or pathlib.Path), not int 3"),
    (lambda: deploydyn.load(None),
     "load: path must be a path (str or pathlib.Path), not NoneType None"),
    (lambda: deploydyn.read_result(7),
     "read_result: folder must be a path (str or pathlib.Path), not int 7"),
    (lambda: deploydyn.read_result(".", history_file=1.5),
     "read_result: history_file must be a path (str or pathlib.Path), not float 1.5"),
    (lambda: deploydyn.folder_status(["a"]),
     "folder_status: folder must be a path (str or pathlib.Path), not list ['a']"),
    (lambda: deploydyn.loads(b"nodes: {}"), "loads: text must be a str, not bytes b'nodes: {}'"),
    (lambda: deploydyn.loads("nodes: {}", source_name=1),
     "loads: source_name must be a str, not int 1"),
    (lambda: deploydyn.from_dict([("nodes", {})]),
     "from_dict: spec must be a dict laid out as a model file, not list [('nodes', {})]"),
])
def test_paths_and_texts(call, message):
    with pytest.raises(TypeError) as error:
        call()
    assert str(error.value) == message


def test_empty_path_is_a_value_error():
    with pytest.raises(ValueError, match=r"^load: path must not be empty$"):
        deploydyn.load("")


def test_overrides_of_the_wrong_shape(general_model):
    with pytest.raises(TypeError, match=r"^load: overrides must be a dict \{path: value\}, a "
                                        r"'PATH=VALUE' text, or a list .* not int 5$"):
        deploydyn.load(general_model, overrides=5)
    with pytest.raises(TypeError, match=r"^roof: overrides must be .*; an item is int 3$"):
        deploydyn.roof(1, overrides=["analysis.end=1", 3])
    with pytest.raises(TypeError,
                       match=r"^from_dict: an override's path must be a str, not int 1$"):
        deploydyn.from_dict({}, overrides=[(1, 2)])
    with pytest.raises(TypeError, match=r"^Model\.set: override thermal\.dT: the value must be a "
                                        r"number, bool, text, dict or list, not set \{1\}$"):
        deploydyn.load(general_model).set("thermal.dT", {1})
    # A list is a YAML flow value, checked by the loader like --set's: not a function of time.
    with pytest.raises(deploydyn.InputError, match=r"thermal\.dT: expected a function"):
        deploydyn.load(general_model).set("thermal.dT", [1, 2])
    with pytest.raises(TypeError, match=r"^Model\.set: path must be a str, not int 5$"):
        deploydyn.load(general_model).set(5, 1)


def test_from_dict_names_the_field_and_takes_numpy_values():
    spec = {"nodes": {"A": [0, 0], "B": np.array([1.0, 0.0])},
            "materials": {"m": {"E": np.float64(1e9)}},
            "elements": {1: {"nodes": ["A", "B"], "area": np.float32(1e-4), "material": "m",
                             "mass": np.int64(1)}},
            "supports": [{"node": "A"}, {"node": "B"}],
            "analysis": {"type": "static", "end": 1, "step": 1}}
    assert deploydyn.from_dict(spec).run(check=True).values.shape[0] == 2
    spec["elements"][1]["area"] = {1e-4}
    with pytest.raises(TypeError, match=r"^from_dict: elements\.1\.area must be a number, text, "
                                        r"list or dict, not set \{0\.0001\}$"):
        deploydyn.from_dict(spec)


def test_model_methods(general_model, tmp_path):
    model = deploydyn.load(general_model)
    with pytest.raises(TypeError, match=r"^Model\.run: out must be a path \(str or "
                                        r"pathlib\.Path\), not int 5$"):
        model.run(out=5)
    with pytest.raises(TypeError, match=r"^Model\.run: check must be a bool, not str 'yes'$"):
        model.run(check="yes")
    with pytest.raises(TypeError, match=r"^Model\.temperature_changes: t must be a number"):
        model.temperature_changes("0")
    with pytest.raises(TypeError, match=r"^Model\.save: path must be a path"):
        model.save(None)
    model.save(tmp_path / "saved.yaml")                      # a pathlib.Path is a path
    assert deploydyn.load(str(tmp_path / "saved.yaml")).to_yaml() == model.to_yaml()


FUNCTION_OF_TIME = ("must be a number, a function's name (str) or a function (dict, e.g. "
                    "deploydyn.smooth_step(...))")


@pytest.mark.parametrize("call, message", [
    (lambda b: b.node("A", "0", 0),
     "ModelBuilder.node: x must be a number (int or float), not str '0'"),
    (lambda b: b.node("A", 0, 0, z=[1]),
     "ModelBuilder.node: z must be a number (int or float), not list [1]"),
    (lambda b: b.node(1.5, 0, 0),
     "ModelBuilder.node: name must be a name (str, or int), not float 1.5"),
    (lambda b: b.material("m", E="stiff"),
     "ModelBuilder.material: E must be a number (int or float), not str 'stiff'"),
    (lambda b: b.bar("1", "A", "B", area=None, material="m"),
     "ModelBuilder.bar: area must be a number (int or float), not NoneType None"),
    (lambda b: b.bar("1", "A", None, area=1e-4, material="m"),
     "ModelBuilder.bar: node_b must be a name (str, or int), not NoneType None"),
    (lambda b: b.bar("1", "A", "B", area=1e-4, material="m", dT=[1, 2]),
     f"ModelBuilder.bar: dT {FUNCTION_OF_TIME}, not list [1, 2]"),
    (lambda b: b.support("A", fix=1),
     'ModelBuilder.support: fix must be a list of axis names ("x", "y", "z"), not int 1'),
    (lambda b: b.load("A", force=5),
     "ModelBuilder.load: force must be a sequence of numbers, not int 5"),
    (lambda b: b.load("A", force=[0, "down"]),
     "ModelBuilder.load: force[1] must be a number, not str 'down'"),
    (lambda b: b.thermal(None), f"ModelBuilder.thermal: dT {FUNCTION_OF_TIME}, not NoneType None"),
    (lambda b: b.gravity(0, "g"), "ModelBuilder.gravity: g[1] must be a number, not str 'g'"),
    (lambda b: b.coordinate_driver("d", "B", 0, 1.0),
     "ModelBuilder.coordinate_driver: direction must be a str, not int 0"),
    (lambda b: b.bar_angle_driver("d", "1", object),
     f"ModelBuilder.bar_angle_driver: profile {FUNCTION_OF_TIME}, not type <class 'object'>"),
    (lambda b: b.analysis(end={1}),
     "ModelBuilder.analysis: analysis.end must be a number, text, list or dict, not set {1}"),
    (lambda b: deploydyn.ModelBuilder(name=3), "ModelBuilder: name must be a str, not int 3"),
])
def test_builder_methods(call, message):
    with pytest.raises(TypeError) as error:
        call(deploydyn.ModelBuilder("m"))
    assert str(error.value) == message


def test_builder_accepts_numpy_and_int_names():
    model = (deploydyn.ModelBuilder("numpy")
             .node(1, np.float64(0), 0).node(2, 1, np.int32(0))
             .material("steel", E=np.float32(2e11))
             .bar(1, 1, 2, area=1e-4, material="steel", mass=1)
             .support(1).support(2, fix="y")
             .gravity(np.array([0.0, 0.0]))
             .analysis(type="static", end=np.float64(1.0), step=1)
             .build())
    assert list(model.elements) == ["1"]
    assert model.supports == [{"node": "1", "fix": ["x", "y"]}, {"node": "2", "fix": ["y"]}]


@pytest.mark.parametrize("call, error, message", [
    (lambda: deploydyn.constant("1"), TypeError,
     "constant: value must be a number (int or float), not str '1'"),
    (lambda: deploydyn.smooth_step(0, 0, None, 1), TypeError,
     "smooth_step: t1 must be a number (int or float), not NoneType None"),
    (lambda: deploydyn.smooth_trapezoid(1, (0, 1, 2), (3, 4)), ValueError,
     "smooth_trapezoid: rise must be two numbers (t_start, t_end), got 3"),
    (lambda: deploydyn.table(5), TypeError,
     "table: points must be a sequence of (t, value) pairs, not int 5"),
    (lambda: deploydyn.table([(0, 0), (1, "x")]), TypeError,
     "table: points[1][1] must be a number, not str 'x'"),
])
def test_time_functions(call, error, message):
    with pytest.raises(error) as raised:
        call()
    assert str(raised.value) == message


def test_no_raw_pybind11_message_for_any_public_function(tmp_path):
    """A sweep: every public function given an object of no sensible type says who and what."""
    nonsense = object()
    calls = [lambda: deploydyn.roof(nonsense), lambda: deploydyn.load(nonsense),
             lambda: deploydyn.loads(nonsense), lambda: deploydyn.from_dict(nonsense),
             lambda: deploydyn.read_result(nonsense), lambda: deploydyn.folder_status(nonsense),
             lambda: deploydyn.roof(1).run(out=nonsense), lambda: deploydyn.table(nonsense),
             lambda: deploydyn.roof(1, overrides=nonsense)]
    for call in calls:
        with pytest.raises(TypeError) as error:
            call()
        message = str(error.value)
        assert "incompatible function arguments" not in message and "must be" in message, message
    assert not list(pathlib.Path(tmp_path).iterdir())
