"""deploydyn.run_study (python/deploydyn/study.py) without MPI: the case folders and study.csv of
`deploydyn study`, the cases' outcomes in order, resume, and its errors."""
import json

import pytest

import deploydyn
from conftest import SOURCE_DIR, run_cli

STUDY = SOURCE_DIR / "examples" / "paper" / "general_study.yaml"


def test_writes_what_the_command_writes(tmp_path):
    cases = deploydyn.run_study(STUDY, out=tmp_path / "py")
    run_cli("study", STUDY, "--out", tmp_path / "cli", "--quiet")
    status = json.loads((tmp_path / "cli" / "study.json").read_text())
    assert [c["name"] for c in cases] == list(status["cases"])
    assert all(c["status"] == "completed" and c["process"] == 0 and not c["resumed"] for c in cases)
    for case in cases:
        assert (tmp_path / "py" / case["name"] / "history.csv").read_bytes() == \
            (tmp_path / "cli" / case["name"] / "history.csv").read_bytes()
    assert json.loads((tmp_path / "py" / "study.json").read_text())["status"] == "completed"


def test_resume_keeps_the_completed_cases(tmp_path):
    deploydyn.run_study(STUDY, out=tmp_path, jobs=1)
    again = deploydyn.run_study(STUDY, out=tmp_path, resume=True)
    assert all(c["resumed"] and c["status"] == "completed" for c in again)


def test_bad_input_raises(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("model: nowhere.yaml\ncases:\n  a: {}\n")
    with pytest.raises(deploydyn.InputError) as error:
        deploydyn.run_study(bad, out=tmp_path / "out")
    assert error.value.line == 1 and error.value.field == "model"
    with pytest.raises(TypeError, match="jobs must be an int"):
        deploydyn.run_study(STUDY, out=tmp_path / "out", jobs=1.5)


def test_overrides_change_every_case_as_the_command_line_set_does(tmp_path):
    cases = deploydyn.run_study(STUDY, out=tmp_path / "py", overrides={"analysis.end": 0.05})
    run_cli("study", STUDY, "--out", tmp_path / "cli", "--quiet", "--set", "analysis.end=0.05")
    for case in cases:
        summary = json.loads((tmp_path / "py" / case["name"] / "summary.json").read_text())
        assert summary["final_time"] == pytest.approx(0.05)
        assert (tmp_path / "py" / case["name"] / "history.csv").read_bytes() == \
            (tmp_path / "cli" / case["name"] / "history.csv").read_bytes()
    with pytest.raises(deploydyn.InputError, match="analysis.end"):
        deploydyn.run_study(STUDY, out=tmp_path / "bad", overrides="analysis.end=-1")
