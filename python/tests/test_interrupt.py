"""Ctrl-C stops every long call within a fraction of a second and keeps what it computed; a
threading.Event passed as `stop` does the same for a call in another thread, which Ctrl-C does
not reach (issue 32, item 4). Model.run's own Ctrl-C tests are in test_run_status.py."""
import json
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import deploydyn
from conftest import GENERAL

# Generous under load: each call below would otherwise go on for 10 s to minutes.
LATE = 3.0


def interrupt(tmp_path, setup, call, delay=0.5, then=None):
    """Runs `setup`, then `call` in a new interpreter that sends itself SIGINT `delay` s after
    the call started; returns how long after the signal KeyboardInterrupt reached the script,
    and with `then` (code run after it), also the line that code printed."""
    script = tmp_path / "interrupted.py"
    script.write_text(textwrap.dedent("""\
        import os, signal, sys, threading, time, deploydyn
        {setup}
        sent = []
        def interrupt():
            sent.append(time.perf_counter())
            os.kill(os.getpid(), signal.SIGINT)
        threading.Timer({delay}, interrupt).start()
        try:
            {call}
        except KeyboardInterrupt:
            print(time.perf_counter() - sent[0], flush=True)
            {then}
            sys.exit(3)
        """).format(setup=setup, call=call, delay=delay, then="{then}"))
    script.write_text(script.read_text().replace("{then}", textwrap.indent(then or "pass", " " * 4).lstrip()))
    process = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    try:
        output, _ = process.communicate(timeout=120)
    finally:
        process.kill()
    assert process.returncode == 3, f"no KeyboardInterrupt (exit {process.returncode}): {output}"
    lines = output.splitlines()
    return float(lines[0]) if then is None else (float(lines[0]), lines[1])


def test_ctrl_c_stops_a_continuation(tmp_path):
    """A 3000-unit roof's deployment path takes ~15 s; it went on 39 s after Ctrl-C."""
    late = interrupt(tmp_path, "model = deploydyn.roof(3000)",
                     "model.continuation('driver', end=5.0, max_steps=10**6)")
    assert late < LATE, f"KeyboardInterrupt {late:.2f} s after the signal"


def test_ctrl_c_stops_modes_in_an_equilibrium(tmp_path):
    """The equilibrium before the modes, here a million load steps (~10 s), was not stopped."""
    late = interrupt(tmp_path, "model = deploydyn.roof(20, overrides={'analysis.load_steps': 1000000})",
                     "model.modes(count=3, at=[0.0, 1.0])")
    assert late < LATE, f"KeyboardInterrupt {late:.2f} s after the signal"


def test_ctrl_c_stops_a_roof_being_generated(tmp_path):
    """roof(10**6) writes and reads a model of 3·10⁶ bars: minutes, deaf to Ctrl-C."""
    late = interrupt(tmp_path, "", "deploydyn.roof(10**6)")
    assert late < LATE, f"KeyboardInterrupt {late:.2f} s after the signal"


@pytest.mark.parametrize("setup, call", [("", "deploydyn.roof(10**6)"),
                                         ("text = deploydyn._core.roof_yaml(10**5, 1, 130.0, 'sliding')",
                                          "deploydyn.loads(text)")], ids=["roof", "loads"])
def test_an_interrupted_model_call_leaves_no_work_behind(tmp_path, setup, call):
    """roof() and loads() of a large model left their thread reading or generating it in the
    background after KeyboardInterrupt (a core busy for minutes, its memory growing): now the
    call stops it before it returns, so that no thread of deploydyn's is left, and no CPU used."""
    after = textwrap.dedent("""\
        import json
        cpu = time.process_time()
        time.sleep(1.0)
        print(json.dumps({'threads': len(os.listdir('/proc/self/task')), 'threads_before': threads_before,
                          'cpu_s': time.process_time() - cpu}), flush=True)
        """)
    late, report = interrupt(tmp_path, setup + "\nthreads_before = len(os.listdir('/proc/self/task'))", call,
                             then=after)
    assert late < LATE, f"KeyboardInterrupt {late:.2f} s after the signal"
    report = json.loads(report)
    # (The Timer thread that sent the signal has ended too.)
    assert report["threads"] <= report["threads_before"], report
    assert report["cpu_s"] < 0.2, report


def long_study(tmp_path):
    """A study file: case `quick` takes 0.03 s, case `long` (1 µs steps) about a minute."""
    study = tmp_path / "study.yaml"
    study.write_text(f"model: {json.dumps(str(GENERAL))}\n"
                     "cases:\n  quick: {}\n  long: {analysis.step: 1.0e-6}\n")
    return study


def test_ctrl_c_stops_a_study_and_keeps_its_finished_cases(tmp_path):
    """The study ran every case to its end before Ctrl-C acted, and its outcomes were lost."""
    out = tmp_path / "out"
    late = interrupt(tmp_path, "", f"deploydyn.run_study({str(long_study(tmp_path))!r}, out={str(out)!r})")
    assert late < LATE, f"KeyboardInterrupt {late:.2f} s after the signal"
    status = json.loads((out / "study.json").read_text())
    assert status["status"] == "interrupted"
    assert status["cases"]["quick"]["status"] == "completed"
    assert status["cases"]["long"]["status"] == "interrupted"
    assert deploydyn.read_result(out / "quick").ok
    assert 0 < json.loads((out / "long" / "summary.json").read_text())["final_time"] < 5.0
    assert "quick" in (out / "study.csv").read_text()


# A call in another thread: Python gives signals to the main thread only, so `stop` stops it.

def in_thread(call, after=0.5):
    """`call(stop)` in a thread, with stop set `after` s; returns (its result, seconds it ran
    after stop was set)."""
    stop = threading.Event()
    outcome = {}
    worker = threading.Thread(target=lambda: outcome.setdefault("result", call(stop)))
    worker.start()
    time.sleep(after)
    stop.set()
    set_at = time.perf_counter()
    worker.join(timeout=60)
    assert not worker.is_alive(), "the call did not stop"
    return outcome["result"], time.perf_counter() - set_at


@pytest.mark.parametrize("into_folder", [False, True], ids=["in_memory", "into_folder"])
def test_stop_ends_a_run_in_a_thread_keeping_its_history(tmp_path, into_folder):
    model = deploydyn.load(GENERAL, overrides={"analysis.step": 1e-6})  # a minute's run
    out = tmp_path / "out" if into_folder else None
    result, late = in_thread(lambda stop: model.run(out=out, stop=stop))
    assert late < LATE
    assert result.status == "interrupted"
    assert result.values.shape[0] > 1 and 0 < result.t[-1] < 5.0
    if into_folder:
        assert deploydyn.folder_status(out) == "interrupted"


def test_stop_ends_a_continuation_in_a_thread_keeping_its_points():
    model = deploydyn.roof(3000)
    # 1.5 s: the path has 19 points after 0.5 s on a quiet machine, but at load 8 its set-up took
    # all of 0.5 s and left one; the test needs two before the stop.
    path, late = in_thread(lambda stop: model.continuation("driver", end=5.0, max_steps=10**6, stop=stop), after=1.5)
    assert late < LATE
    assert path["end"] == "stopped"
    assert len(path["mu"]) > 1 and 0 < path["mu"][-1] < 5.0


def test_stop_ends_modes_in_a_thread():
    model = deploydyn.roof(20, overrides={"analysis.load_steps": 1000000})
    modes, late = in_thread(lambda stop: model.modes(count=3, at=[0.0, 1.0], stop=stop))
    assert late < LATE
    assert modes["failures"] == ["stopped before the equilibrium was reached", "stopped before this time"]
    assert np.isnan(modes["omega2"]).all()


def test_stop_ends_a_study_in_a_thread_returning_its_cases(tmp_path):
    out = tmp_path / "out"
    cases, late = in_thread(lambda stop: deploydyn.run_study(long_study(tmp_path), out=out, stop=stop))
    assert late < LATE
    assert {c["name"]: c["status"] for c in cases} == {"quick": "completed", "long": "interrupted"}
    assert json.loads((out / "study.json").read_text())["status"] == "interrupted"


def test_stop_must_be_an_event(general_model):
    with pytest.raises(TypeError, match=r"^Model.run: stop must be a threading.Event \(or any object "
                                        r"with is_set\(\)\) or None, not bool True$"):
        deploydyn.load(general_model).run(stop=True)
