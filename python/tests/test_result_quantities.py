"""Reactions, displacements, stress and the output selection from Python, checked against
statics by hand and against the positions they derive from."""
import numpy as np
import pytest

import deploydyn

E = 2.0e11      # Pa
AREA = 1.0e-4   # m²
ALPHA = 1.2e-5  # 1/°C


def heated_bar(select=None):
    builder = (deploydyn.ModelBuilder("heated bar on a roller")
               .node("A", 0, 0).node("B", 1.5, 0).node("C", 1.5, 1.0)
               .material("steel", E=E, alpha=ALPHA)
               .bar("1", "A", "B", area=AREA, material="steel", mass=1.0)
               .bar("2", "B", "C", area=AREA, material="steel", mass=1.0, dT=0.0)
               .support("A").support("B", fix=["y"]).support("C")
               .thermal(100.0)
               .analysis(type="static", end=1.0, step=0.5))
    if select is not None:
        builder.output(select=select)
    return builder.build()


def test_reactions_close_the_statics_of_a_heated_bar_pushing_a_strut():
    result = heated_bar().run(check=True)
    # Bar 1 expands against strut 2, which the pin C holds: A and C take equal, opposite x forces.
    rA, rC = result["reaction.A.x"][-1], result["reaction.C.x"][-1]
    assert rA == pytest.approx(-rC, rel=1e-9)
    assert rA != 0.0
    # No loads and no motion: every component's reactions sum to zero, y included.
    total_y = result["reaction.A.y"][-1] + result["reaction.B.y"][-1] + result["reaction.C.y"][-1]
    assert abs(total_y) < 1e-9 * abs(rA)
    assert result.summary["reactions"]["A"]["x"]["min"] == pytest.approx(min(result["reaction.A.x"]))


def test_selection_gives_displacements_and_stress_and_leaves_out_the_rest():
    result = heated_bar(select={"nodes": ["B", "C"], "quantities": ["displacement", "stress"]}).run(check=True)
    assert result.columns == ["t", "ux.B", "uy.B", "ux.C", "uy.C", "stress.1", "stress.2"]
    full = heated_bar().run(check=True)
    np.testing.assert_array_equal(result["ux.B"], full["x.B"] - 1.5)
    np.testing.assert_array_equal(result["stress.1"], full["force.1"] / AREA)


def test_a_selection_that_matches_nothing_names_the_field():
    with pytest.raises(deploydyn.InputError, match=r"output\.select\.nodes\.0.*matches no node"):
        heated_bar(select={"nodes": ["Q*"]})


def test_envelopes_of_a_folder_hold_every_steps_extremes(tmp_path):
    model = deploydyn.load(deploydyn_example("paper/general.yaml"),
                           overrides={"analysis.end": 0.5, "analysis.step": 0.001,
                                      "analysis.output_interval": 0.1})
    result = model.run(out=tmp_path / "run", check=True)
    envelopes = result.envelopes
    dense = deploydyn.load(deploydyn_example("paper/general.yaml"),
                           overrides={"analysis.end": 0.5, "analysis.step": 0.001,
                                      "analysis.output_interval": 0.001}).run(check=True)
    for bar in ("1", "2", "3"):
        peak = envelopes[(bar, "axial_force_N")]
        assert peak["kind"] == "bar" and peak["unit"] == "N"
        # Every step's maximum, as the run written at every step has it; the 0.1 s rows miss it.
        assert peak["max"] == pytest.approx(dense[f"force.{bar}"].max(), rel=1e-7)
        assert peak["max"] >= result[f"force.{bar}"].max()
    assert deploydyn.read_envelopes(tmp_path / "nothing.csv") == {}


def deploydyn_example(name):
    import pathlib
    return pathlib.Path(__file__).resolve().parents[2] / "examples" / name
