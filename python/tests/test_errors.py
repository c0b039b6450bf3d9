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
