"""Model.window and deploydyn.report: what `deploydyn window` and `deploydyn report` give, from
Python, and their argument errors."""
import json

import numpy as np
import pytest

import deploydyn
from conftest import SOURCE_DIR, run_cli

PARALLEL = SOURCE_DIR / "examples" / "paper" / "parallel.yaml"
BOOM = SOURCE_DIR / "examples" / "boom" / "boom.yaml"
WINDOW = ("--dT", "-170:130", "--positions", "5", "--deployments", "3")


def test_window_gives_what_the_command_gives(tmp_path):
    window = deploydyn.load(PARALLEL).window(dT=(-170, 130), positions=5, deployments=3, out=tmp_path / "py")
    run_cli("window", PARALLEL, *WINDOW, "--out", tmp_path / "cli")
    cli = json.loads((tmp_path / "cli" / "window.json").read_text())
    written = json.loads((tmp_path / "py" / "window.json").read_text())
    for key in ("status", "positions", "cold", "hot", "regimes", "deployments"):
        assert window[key] == cli[key] == written[key], key
    # The cold parallel linkage jams at its dead centre (docs/theory.md, "The deployability
    # window": −84.8435 °C in closed form); hot, it deploys over the whole range.
    assert window["cold"]["threshold"]["kind"] == "limit_point"
    assert window["cold"]["threshold"]["dT"] == pytest.approx(-84.8435, abs=1e-4)
    assert window["hot"]["threshold"] is None
    assert [d["regime"] for d in window["deployments"]] == ["jams", "stress-free", "stress-free"]
    assert window["deployments"][0]["verdict"]["deploys"] is False
    table = np.loadtxt(tmp_path / "cli" / "window.csv", delimiter=",", skiprows=1, usecols=range(6))
    for i, name in enumerate(("t", "dT", "lowest_eigenvalue", "peak_axial_force", "peak_mstrain", "driver_effort")):
        np.testing.assert_allclose(window["samples"][name], table[:, i], rtol=1e-15, atol=0, err_msg=name)
    branches = np.loadtxt(tmp_path / "cli" / "window.csv", delimiter=",", skiprows=1, usecols=6, dtype=str)
    assert list(window["samples"]["branch"]) == list(branches)
    # The −170 °C level cannot start: its stressed equilibrium is the last row, pulled straight.
    assert branches[-1] == "stressed" and list(branches[:-1]) == ["traced"] * (len(branches) - 1)
    stressed = window["deployments"][0]["stressed"]
    assert stressed["peak_mstrain"] == pytest.approx(652e-6, abs=1e-6)
    assert abs(stressed["driver_effort"]) == pytest.approx(62.8, abs=0.05)


def test_window_of_a_model_with_overrides_records_them():
    window = deploydyn.load(PARALLEL, overrides={"analysis.end": 2.5}).window(dT=(-20, 20), positions=3,
                                                                               deployments=0)
    assert window["set"] == ["analysis.end=2.5"]
    assert window["positions"][-1] == pytest.approx(2.5)
    assert window["deployments"] == []


def test_window_arguments_and_models_it_refuses():
    model = deploydyn.load(PARALLEL)
    with pytest.raises(ValueError, match=r"Model.window: dT must be \(lo, hi\) with lo ≤ 0 ≤ hi"):
        model.window(dT=(10, 20))
    with pytest.raises(TypeError, match="Model.window: dT must be a pair"):
        model.window(dT=5)
    with pytest.raises(TypeError, match="Model.window: positions must be an int"):
        model.window(positions=2.0)
    with pytest.raises(ValueError, match="at most 10000 positions"):
        model.window(positions=10001)
    with pytest.raises(deploydyn.InputError, match="spring"):  # a spring-driven boom has no drivers to move
        deploydyn.load(BOOM).window()
    with pytest.raises(ValueError, match="load must be 'uniform' or 'model'"):
        model.window(load="hot")
    with pytest.raises(ValueError, match="with load='model' the range is `scale`"):
        model.window(load="model", dT=(-10, 10))
    with pytest.raises(ValueError, match=r"scale must be \(lo, hi\) with lo ≤ 0 ≤ hi"):
        model.window(load="model", scale=(1, 2))
    with pytest.raises(deploydyn.InputError, match="it has none"):  # the example's dT is 0
        model.window(load="model")


def test_window_of_the_models_own_load_is_in_its_scale():
    # 60 °C on every bar as the pattern: the cold jam at −84.8435 °C is at μ = −1.41406.
    window = deploydyn.load(PARALLEL, overrides={"thermal.dT": 60}).window(load="model", scale=(-2, 0), positions=1,
                                                                          deployments=0)
    assert window["load"] == "model" and window["units"]["dT"] == "1"
    assert window["pattern"]["hottest_axis_dT"] == 60.0
    assert window["cold"]["threshold"]["dT"] * 60.0 == pytest.approx(-84.8435, abs=1e-3)


def test_report_writes_what_the_command_writes(tmp_path):
    deploydyn.load(PARALLEL, overrides={"analysis.end": 0.5}).run(out=tmp_path / "run")
    page = deploydyn.report(tmp_path / "run", frames=20)
    assert page == tmp_path / "run" / "report.html"
    run_cli("report", tmp_path / "run", "--frames", "20", "--out", tmp_path / "cli.html", "--quiet")
    assert page.read_bytes() == (tmp_path / "cli.html").read_bytes()
    assert page.read_text().lstrip().lower().startswith("<!doctype html")
    with pytest.raises(ValueError, match="nowhere: not a folder"):
        deploydyn.report(tmp_path / "nowhere")
    (tmp_path / "run" / "summary.json").write_text("[1, 2]")
    with pytest.raises(ValueError, match="summary.json"):
        deploydyn.report(tmp_path / "run")
    with pytest.raises(ValueError, match="report: frames must be at most 100000"):
        deploydyn.report(tmp_path / "run", frames=100_001)


def test_the_window_of_an_environment_sweeps_its_steady_field_at_the_time_asked():
    """`load="model"` on a model with an environment: the members' steady temperatures at
    `environment_time`: a sunlit pinned tube at its radiative equilibrium outside the eclipse,
    at the sink's 3 K inside it."""
    source = SOURCE_DIR / "tests" / "thermal" / "models" / "sunlit_tube.yaml"
    model = deploydyn.load(source, overrides={"environment.eclipses": [[100, 200]]})
    lit = model.window(load="model", scale=(-1, 1), positions=2, deployments=0)
    steady_K = (0.5 * 1361.0 / (0.8 * 5.670374419e-8 * np.pi) + 3.0 ** 4) ** 0.25
    assert lit["pattern"]["hottest_axis_dT"] == pytest.approx(steady_K - 293.15, rel=1e-9)
    dark = model.window(load="model", scale=(-1, 1), positions=2, deployments=0, environment_time=150)
    assert dark["pattern"]["coldest_axis_dT"] == pytest.approx(3.0 - 293.15, rel=1e-9)
    assert "t = 150 s" in dark["pattern"]["source"]
    with pytest.raises(ValueError, match="environment_time is the environment state of load='model'"):
        model.window(environment_time=150)
    done = run_cli("window", source, "--environment-time", "150", check=False)
    assert done.returncode == 2 and "--environment-time" in done.stderr
    # A continuation is traced in the steady field at its `time`: the held tube's force is
    # −E A α ΔT* μ (Green strain, l = L), in the sun and in the eclipse.
    ea_alpha = 2.0e11 * np.pi / 4 * (0.02 ** 2 - 0.018 ** 2) * 1.2e-5
    for time, dT in ((0.0, steady_K - 293.15), (150.0, 3.0 - 293.15)):
        path = model.continuation("thermal", 1.0, time=time, eigenvalues=0)
        force = path["values"][:, path["columns"].index("force.tube")]
        assert force == pytest.approx(-ea_alpha * dT * path["mu"], rel=1e-6, abs=1e-6 * ea_alpha * abs(dT))
