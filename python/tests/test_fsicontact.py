"""The Python module against the command line (issue 31): the same summary.json to the
last digit, the same errors as exceptions of the exit status's class, progress,
Ctrl-C, and NumPy histories. Run by ctest (tests/CMakeLists.txt) with PYTHONPATH at
the build's python/ and FSICONTACT_BINARY, FSICONTACT_SOURCE_DIR set."""
import json
import os
import signal
import subprocess
import threading

import numpy as np
import pytest

import fsicontact

SOURCE = os.environ["FSICONTACT_SOURCE_DIR"]
BINARY = os.environ["FSICONTACT_BINARY"]
CASES = os.path.join(SOURCE, "cases")


def without_times(value):
    """The value with every duration (a key ending in _s: seconds) left out."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if not k.endswith("_s")}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def comparable(summary):
    """summary.json but what differs between two runs of the same case: the timings,
    the output directory, and whether the process's allocator had huge pages (the
    program starts itself again with them; a Python process is started by Python)."""
    s = without_times(summary)
    s["parameters"] = {k: v for k, v in s["parameters"].items() if k != "output"}
    s["program"] = {k: v for k, v in s["program"].items() if k != "huge_pages"}
    return s


def cli_summary(tmp_path, *args):
    out = tmp_path / "cli"
    subprocess.run([BINARY, "run", *args, "--out", str(out), "-q"], check=False, capture_output=True)
    with open(out / "summary.json") as f:
        return json.load(f)


def test_a_coupled_run_gives_the_command_lines_summary_to_the_last_digit(tmp_path):
    case = os.path.join(CASES, "paper-7.2.toml")
    r = fsicontact.run(case, set={"coupling.scheme": "aitken"}, out=tmp_path / "py")
    expected = cli_summary(tmp_path, case, "--set", "coupling.scheme=aitken")
    assert r.converged and r.status == "converged" and r.exit_status == 0
    assert comparable(r.summary) == comparable(expected)
    assert r.summary["program"]["version"] == fsicontact.version().split()[1]
    assert len(r.history["iteration"]) == r.summary["iterations"]


def test_a_dict_is_the_case_file_it_spells(tmp_path):
    as_dict = {"name": "from-a-dict", "fluid": {"h": 0.02}, "coupling": {"scheme": "iqn-ils", "tol": 1e-6}}
    path = tmp_path / "case.toml"
    path.write_text('name = "from-a-dict"\n[fluid]\nh = 0.02\n[coupling]\nscheme = "iqn-ils"\ntol = 1e-6\n')
    a = fsicontact.run(as_dict, out=tmp_path / "a")
    b = fsicontact.run(str(path), out=tmp_path / "b")
    assert comparable(a.summary) == comparable(b.summary)


@pytest.mark.parametrize("case,overrides,words", [
    ({"coupling": {"omega": 5}}, None, ["coupling.omega = 5", "(0, 1]"]),
    ({"fluid": {"h": "fine"}}, None, ["fluid.h", "number"]),
    ({"structure": {"f": np.zeros((2, 2))}}, None, ["structure.f"]),
    ({"nonsense": {"x": 1}}, None, ["nonsense"]),
    (None, {"coupling.tol": object()}, ["coupling.tol", "object"]),
    (None, {"coupling.nope": 1}, ["coupling.nope"]),
    (None, ["coupling.tol=1"], ["set", "dict"]),
    (42, None, ["case", "int"]),
])
def test_bad_input_is_an_input_error_naming_the_key_and_nothing_is_written(tmp_path, case, overrides, words):
    out = tmp_path / "never"
    with pytest.raises(fsicontact.InputError) as e:
        fsicontact.run(case, set=overrides, out=out)
    for w in words:
        assert w in str(e.value)
    assert not out.exists()


def test_the_same_message_as_the_command_line(tmp_path):
    done = subprocess.run([BINARY, "run", "--set", "coupling.omega=5", "--out", str(tmp_path / "c")],
                          capture_output=True, text=True)
    assert done.returncode == 2
    with pytest.raises(fsicontact.InputError) as e:
        fsicontact.run(set={"coupling.omega": 5}, out=tmp_path / "p")
    assert str(e.value) in done.stderr


def test_a_failure_after_validation_is_a_solver_failure_with_its_summary(tmp_path, monkeypatch):
    monkeypatch.setenv("FSICONTACT_FAULT", "fluid")
    with pytest.raises(fsicontact.SolverFailure) as e:
        fsicontact.run(os.path.join(CASES, "paper-7.2.toml"), out=tmp_path / "f")
    assert "injected fault" in str(e.value)
    with open(tmp_path / "f" / "summary.json") as f:
        assert json.load(f)["status"] == "failed"


def test_the_iteration_limit_is_a_result_that_did_not_converge(tmp_path):
    r = fsicontact.run(set={"coupling.max_iterations": 2}, out=tmp_path / "l")
    assert not r.converged and r.status == "iteration limit" and r.exit_status == 3


def test_progress_is_called_once_per_pass(tmp_path):
    lines = []
    r = fsicontact.run(set={"coupling.scheme": "aitken"}, out=tmp_path / "p", progress=lines.append)
    passes = [l for l in lines if l.startswith("[coupling] it")]
    assert len(passes) == r.summary["iterations"]


def test_ctrl_c_stops_the_run_writes_what_it_has_and_raises_keyboard_interrupt(tmp_path):
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # constant omega to 1e-12: about 100 passes, several seconds
        fsicontact.run(set={"coupling.tol": 1e-12, "coupling.max_iterations": 100000}, out=tmp_path / "i")
    timer.join()
    with open(tmp_path / "i" / "summary.json") as f:
        assert json.load(f)["status"] == "interrupted"
    # the host's own handler is back: Python's SIGINT handler raises KeyboardInterrupt again
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_time_runs_history_is_numpy_columns(tmp_path):
    r = fsicontact.run(os.path.join(CASES, "bar-impact.toml"), set={"time.t_end": 0.002, "output.png": False},
                       out=tmp_path / "t")
    h = r.history
    assert isinstance(h["t"], np.ndarray) and h["t"].dtype == float
    assert len(h["t"]) == r.summary["steps"] + 1  # the initial state and one line per step
    assert np.all(np.diff(h["t"]) > 0)


def test_help_says_what_run_does():
    assert "InputError" in fsicontact.run.__doc__ and "progress" in fsicontact.run.__doc__
