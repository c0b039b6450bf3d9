"""How a run ends: a solver failure is a status (RunFailed only on request); the GIL is released."""
import json
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import deploydyn

UNDRIVEN = {  # a four-bar linkage without a driver, in a static run: it cannot stand
    "nodes": {"A": [0, 0], "B": [0.286904073050423, 0.0251008539113255],
              "C": [0.643904073050423, 0.0251008539113255], "D": [0.357, 0]},
    "materials": {"steel": {"E": 1.5e11, "alpha": 2.0e-5}},
    "elements": {"1": {"nodes": ["A", "B"], "area": 4.64e-5, "material": "steel", "mass": 0.288},
                 "2": {"nodes": ["B", "C"], "area": 4.64e-5, "material": "steel", "mass": 0.357},
                 "3": {"nodes": ["C", "D"], "area": 4.64e-5, "material": "steel", "mass": 0.288}},
    "supports": [{"node": "A"}, {"node": "D"}],
    "analysis": {"type": "static", "end": 1, "step": 0.1},
}


def test_solver_failure_is_a_status_not_an_exception(tmp_path):
    model = deploydyn.from_dict(UNDRIVEN)
    result = model.run()
    assert result.status == "failed"
    assert not result.ok
    assert "free motion: part with nodes B, C" in result.failure["reason"]
    assert result.message
    with pytest.raises(deploydyn.RunFailed) as error:
        result.raise_for_status()
    assert error.value.result is result
    with pytest.raises(deploydyn.RunFailed, match="free motion|fail"):
        model.run(check=True)
    in_folder = model.run(out=tmp_path)             # the folder gets summary.json all the same
    assert in_folder.status == "failed"
    assert (tmp_path / "summary.json").exists()
    assert in_folder.values.shape[1] == len(model.history_columns)


def test_threads_run_in_parallel_and_agree(general_model):
    """While a run computes, other Python threads go on (the GIL is released)."""
    model = deploydyn.load(general_model, overrides={"analysis.step": 2.5e-5})  # 0.1–0.3 s
    serial = model.run()

    results = {}
    runner = threading.Thread(target=lambda: results.setdefault("run", model.run()))
    # This thread keeps turning while the run computes: its longest pause is a few thread
    # switch intervals (5 ms), not the whole run as it would be if the run held the GIL.
    longest_pause, last = 0.0, time.perf_counter()
    start = last
    runner.start()
    while runner.is_alive():
        now = time.perf_counter()
        longest_pause, last = max(longest_pause, now - last), now
    duration = time.perf_counter() - start
    runner.join()
    np.testing.assert_array_equal(results["run"].values, serial.values)
    assert duration > 0.04, duration
    assert longest_pause < 0.5 * duration, (longest_pause, duration)

    hot = model.with_overrides({"thermal.dT": 130})
    pair = [None, None]
    threads = [threading.Thread(target=lambda i=i, m=m: pair.__setitem__(i, m.run()))
               for i, m in enumerate((model, hot))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    np.testing.assert_array_equal(pair[0].values, serial.values)
    np.testing.assert_array_equal(pair[1].values, hot.run().values)


def test_ctrl_c_stops_a_run_and_keeps_its_results(general_model, tmp_path):
    """SIGINT during a run (GIL released) stops it after the current step: KeyboardInterrupt,
    and the folder's summary.json says "interrupted"."""
    script = tmp_path / "long_run.py"
    script.write_text(
        "import sys, deploydyn\n"
        f"model = deploydyn.load({str(general_model)!r}, overrides={{'analysis.step': 1e-6}})\n"
        "print('started', flush=True)\n"
        "try:\n"
        f"    model.run(out={str(tmp_path / 'out')!r})\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    sys.exit(3)\n")
    process = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "started"
    time.sleep(0.5)
    start = time.perf_counter()
    process.send_signal(signal.SIGINT)
    output, _ = process.communicate(timeout=60)
    assert time.perf_counter() - start < 5.0          # the 5 000 000-step run did not go on
    assert process.returncode == 3, output
    assert output.strip() == "interrupted"
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    assert 0 < summary["final_time"] < 5.0


@pytest.mark.parametrize("into_folder", [False, True], ids=["in_memory", "into_folder"])
def test_ctrl_c_stops_a_long_initial_equilibrium_at_once(tmp_path, into_folder):
    """Ctrl-C acts within a fraction of a second in every phase, not only between time steps:
    here during the initial equilibrium of a roof with a million load steps (~10 s)."""
    out = tmp_path / "out"
    script = tmp_path / "long_equilibrium.py"
    script.write_text(
        "import os, signal, sys, threading, time, deploydyn\n"
        "model = deploydyn.roof(20, overrides={'analysis.load_steps': 1000000})\n"
        "sent = []\n"
        "def interrupt():\n"
        "    sent.append(time.perf_counter())\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "threading.Timer(0.3, interrupt).start()\n"
        "try:\n"
        f"    model.run(out={str(out)!r}) if {into_folder} else model.run()\n"
        "except KeyboardInterrupt:\n"
        "    print(time.perf_counter() - sent[0], flush=True)\n"
        "    sys.exit(3)\n")
    process = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    try:
        output, _ = process.communicate(timeout=60)
    finally:
        process.kill()
    assert process.returncode == 3, f"no KeyboardInterrupt (exit {process.returncode}): {output}"
    assert float(output) < 1.0, f"KeyboardInterrupt {float(output):.2f} s after the signal"
    if into_folder:
        summary = json.loads((out / "summary.json").read_text())
        assert summary["status"] == "interrupted"
        assert "initial equilibrium" in summary["message"]
        assert deploydyn.folder_status(out) == "interrupted"
