"""deploydyn.scissor: the generated scissor structures from Python, the same model as `deploydyn
generate scissor` writes, and its errors."""
import subprocess

import pytest

import deploydyn
from conftest import CLI


@pytest.mark.parametrize("python, command", [
    ({}, []),
    (dict(form="translational", units=3, span=6.0, elements=1, delta_t=-20.0),
     ["--form", "translational", "--units", "3", "--span", "6", "--elements", "1", "--delta-t", "-20"]),
    (dict(form="ring", units=8, span=4.0, gradient=5.0, deploy_time=4.0, end_time=5.0),
     ["--form", "ring", "--units", "8", "--span", "4", "--gradient", "5", "--deploy-time", "4", "--end-time", "5"]),
    (dict(hinge_offset=0.2, folded_angle=20, deployed_angle=100, area=1e-3, inertia=5e-7, depth=0.08),
     ["--hinge-offset", "0.2", "--folded-angle", "20", "--deployed-angle", "100", "--area", "1e-3",
      "--inertia", "5e-7", "--depth", "0.08"]),
])
def test_scissor_is_what_the_command_writes(tmp_path, python, command):
    file = tmp_path / "scissor.yaml"
    subprocess.run([str(CLI), "generate", "scissor", *command, "--out", str(file)], check=True, capture_output=True)
    assert deploydyn.scissor(**python).to_yaml() == deploydyn.load(file).to_yaml()


def test_scissor_overrides_and_errors():
    model = deploydyn.scissor(units=2, overrides={"analysis.end": 11})
    assert model.analysis["end"] == 11
    assert sum(1 for e in model.elements.values() if e["type"] == "beam") == 2 * 2 * 2 * 2
    with pytest.raises(ValueError, match="scissor: form must be translational, polar or ring"):
        deploydyn.scissor(form="fan")
    with pytest.raises(ValueError, match="units must be a multiple of 4"):
        deploydyn.scissor(form="ring", units=6)
    with pytest.raises(TypeError, match="scissor: units must be an int"):
        deploydyn.scissor(units=6.0)
    with pytest.raises(TypeError, match="scissor: span must be a number"):
        deploydyn.scissor(span="10")
