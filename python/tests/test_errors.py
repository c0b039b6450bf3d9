"""Bad input raises ValueError (deploydyn.InputError) with the CLI's message: file, line, field."""
import pytest

import deploydyn
from conftest import run_cli

BAD_AREA = """\
nodes:
  A: [0, 0]
  B: [1, 0]
materials:
  steel: {E: 2.0e11, alpha: 1.2e-5}
elements:
  1: {nodes: [A, B], area: -1, material: steel, mass: 1}
supports: [{node: A}, {node: B}]
"""


def cli_error(*args):
    """The message `deploydyn check` prints for bad input (exit code 2), without 'error: '."""
    done = run_cli("check", *args, check=False)
    assert done.returncode == 2, done.stderr
    return done.stderr.strip().removeprefix("error: ")


def test_bad_value_names_file_line_and_field(tmp_path):
    model_file = tmp_path / "bad.yaml"
    model_file.write_text(BAD_AREA)
    with pytest.raises(ValueError) as error:
        deploydyn.load(model_file)
    message = str(error.value)
    assert message.startswith(f"{model_file}:7:")
    assert "elements.1.area: must be positive (m²), got -1" in message
    assert error.value.source == str(model_file)
    assert error.value.line == 7
    assert error.value.field == "elements.1.area"
    assert message == cli_error(model_file)


def test_unknown_key_suggests_the_known_one(tmp_path):
    model_file = tmp_path / "typo.yaml"
    model_file.write_text(BAD_AREA.replace("area: -1", "aera: 1e-4"))
    with pytest.raises(deploydyn.InputError) as error:
        deploydyn.load(model_file)
    assert str(error.value).startswith(f"{model_file}:7:")
    assert "did you mean 'area'?" in str(error.value)
    assert str(error.value) == cli_error(model_file)


def test_bad_override_names_the_override(general_model):
    with pytest.raises(ValueError) as error:
        deploydyn.load(general_model, overrides={"thermal.dT": "abc"})
    assert str(error.value).startswith("--set thermal.dT=abc: thermal.dT: unknown function 'abc'")
    assert str(error.value) == cli_error(general_model, "--set", "thermal.dT=abc")


def test_missing_file(tmp_path):
    missing = tmp_path / "nowhere.yaml"
    with pytest.raises(ValueError, match="nowhere.yaml: cannot open file"):
        deploydyn.load(missing)


def test_yaml_syntax_error_in_text():
    with pytest.raises(ValueError) as error:
        deploydyn.loads("nodes: [A: 1\n", source_name="snippet.yaml")
    assert str(error.value).startswith("snippet.yaml:")
    assert "YAML syntax" in str(error.value)
    assert error.value.line is not None


# Hostile input (issue 32): refused with a short message, never a crash or a half-read model.

GOOD = BAD_AREA.replace("area: -1", "area: 1e-4")


def test_deeply_nested_text_is_refused_not_a_crash():
    """10⁵ levels of brackets overflowed the stack and killed the interpreter."""
    text = '{"nodes": ' + "[" * 100_000 + "]" * 100_000 + "}"
    with pytest.raises(deploydyn.InputError) as error:
        deploydyn.loads(text, source_name="deep.json")
    assert str(error.value).startswith("deep.json:1:")
    assert "nest deeper than 256 levels here; a model file may nest at most 256" in str(error.value)
    assert len(str(error.value)) < 300


@pytest.mark.parametrize("text", [GOOD + "---\nname: second\n", '{"name": "a"} xyz', '{"name": "a"}{"b": 1}'])
def test_text_after_the_model_is_refused(text):
    """Only the first document or JSON value was read; the rest was silently dropped."""
    with pytest.raises(deploydyn.InputError, match="a second document starts here"):
        deploydyn.loads(text, source_name="two.yaml")


def test_name_not_utf8_is_refused_at_load(tmp_path):
    """A Latin-1 name loaded, then Model.name raised UnicodeDecodeError and the run died
    writing summary.json."""
    model_file = tmp_path / "latin1.yaml"
    model_file.write_bytes(b"name: caf\xe9\n" + GOOD.encode())
    with pytest.raises(deploydyn.InputError) as error:
        deploydyn.load(model_file)
    assert error.value.line == 1
    assert error.value.field == "name"
    assert error.value.problem == "must be UTF-8 text, got 'caf\\xE9'"
    assert str(error.value) == cli_error(model_file)


def test_path_with_nul_is_refused_naming_the_argument():
    with pytest.raises(ValueError, match=r"^load: path must not hold a NUL character"):
        deploydyn.load("a\0b")


# Arguments of the entry points (issue 32, item 9): a clear TypeError or ValueError naming the
# argument and what it takes, before any work; never a MemoryError, an AttributeError or nothing.

@pytest.fixture(scope="module")
def general(general_model):
    return deploydyn.load(general_model)


def test_modes_count_beyond_the_model_is_refused_before_allocating(general):
    """count=10⁹ tried to allocate 60 GiB (MemoryError) before the count was checked."""
    with pytest.raises(ValueError, match=r"^Model.modes: count must be at most 3 \(the model has 8 "
                                         r"coordinates and 5 constraint equations\), got 1000000000$"):
        general.modes(count=10**9)


@pytest.mark.parametrize("at, message", [
    ([0.0] * 100_001, r"at must be a time or a list of 1 to 100000 times \(s\), got 100001"),
    ([], r"at must be a time or a list of 1 to 100000 times \(s\), got 0"),
    ([0.5, float("nan")], r"at\[1\] must be a finite number, got nan"),
    (float("inf"), r"at\[0\] must be a finite number, got inf"),
    (-1, r"at\[0\] must be a time ≥ 0 \(s\), got -1.0"),
], ids=["too_many", "empty", "nan", "inf", "negative"])
def test_modes_times_are_checked_as_the_model_files(general, at, message):
    """As analysis.at in a model file: 1 to 10⁵ finite times ≥ 0 (NaN gave a result of NaN)."""
    with pytest.raises(ValueError, match="^Model.modes: " + message):
        general.modes(count=1, at=at)


@pytest.mark.parametrize("name", ["time", "start", "end"])
def test_continuation_refuses_times_and_bounds_that_are_not_finite(general, name):
    """time=nan was taken and traced a path of NaN."""
    arguments = {"parameter": "thermal", "end": 1.0, name: float("nan")}
    with pytest.raises(ValueError, match=rf"^Model.continuation: {name} must be a finite number, got nan$"):
        general.continuation(**arguments)


@pytest.mark.parametrize("arguments, error, message", [
    ({"file": None}, TypeError, r"file must be a path \(str or pathlib.Path\), not NoneType None"),
    ({"out": 5}, TypeError, r"out must be a path \(str or pathlib.Path\), not int 5"),
    ({"comm": 5}, TypeError, r"comm must be an mpi4py communicator \(e.g. MPI.COMM_WORLD\) or None, "
                             r"not int 5"),
    ({"jobs": -1}, ValueError, r"jobs must be at least 0, got -1"),
    ({"resume": "yes"}, TypeError, r"resume must be a bool, not str 'yes'"),
], ids=["file_none", "out_int", "comm_int", "jobs_negative", "resume_str"])
def test_run_study_names_the_bad_argument(source_dir, tmp_path, arguments, error, message):
    """run_study(None) raised os.fspath's message, comm=5 an AttributeError from inside."""
    arguments = {"file": source_dir / "examples" / "paper" / "general_study.yaml",
                 "out": tmp_path / "out", **arguments}
    with pytest.raises(error, match="^run_study: " + message + "$"):
        deploydyn.run_study(**arguments)
    assert not (tmp_path / "out").exists()
