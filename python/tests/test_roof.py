"""deploydyn.roof: the generated roofs from Python, the same model as `deploydyn generate roof`."""
import subprocess

import numpy as np
import pytest

import deploydyn
from conftest import CLI


@pytest.mark.parametrize("bearings, n_elements", [("sliding", 10), ("pinned", 7)])
def test_planar_roof_is_what_the_command_writes(tmp_path, bearings, n_elements):
    # 4 posts and 3 chords; sliding bearings add 3 bottom chords.
    model = deploydyn.roof(3, delta_t=0, bearings=bearings)
    assert model.dimension == 2
    assert len(model.nodes) == 8 and len(model.elements) == n_elements and len(model.drivers) == 1
    file = tmp_path / "roof.yaml"
    subprocess.run([str(CLI), "generate", "roof", "--units", "3", "--delta-t", "0", "--bearings",
                    bearings, "--out", str(file)], check=True, capture_output=True)
    assert model.to_yaml() == deploydyn.load(file).to_yaml()


def test_unknown_bearings_are_a_value_error():
    with pytest.raises(ValueError, match="bearings must be sliding"):
        deploydyn.roof(2, bearings="hinged")


def test_three_dimensional_roof_deploys_upright():
    model = deploydyn.roof(2, trusses=2, delta_t=0, overrides={"analysis.output_interval": 0.05})
    assert model.dimension == 3
    result = model.run()
    assert result.summary["status"] == "completed"
    # Every post ends upright: its top straight above its pinned bottom node.
    final = result.summary["final_positions"]
    for name in model.elements:
        if name.startswith("post"):
            bottom, top = (final[n] for n in model.elements[name]["nodes"])
            assert np.hypot(top[0] - bottom[0], top[2] - bottom[2]) < 1e-3 * 0.288, name


def test_bad_size_is_a_value_error():
    with pytest.raises(ValueError, match="units"):
        deploydyn.roof(0)
