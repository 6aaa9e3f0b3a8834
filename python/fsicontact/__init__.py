"""fsicontact from Python: fluid-structure interaction with contact (issue 31).

    import fsicontact
    r = fsicontact.run("cases/paper-7.2.toml", set={"coupling.scheme": "aitken"})
    r.summary["max_displacement"], r.history["passes"]

A run goes through the command line's own path: the same validation and messages, the
same summary.json. Errors are exceptions of the exit status's class: InputError
(exit 2: invalid input, nothing written), SolverFailure (exit 1: a failure after
validation; summary.json says so). A run that stops at its iteration limit (exit 3)
or is interrupted returns a Result whose `converged` is False and `status` says why.
"""
from __future__ import annotations

import csv
import json
import os
import tempfile
from typing import Any, Callable, Mapping, Optional, Union

import numpy as np

from . import _fsicontact
from ._toml import dumps as _toml_dumps

InputError = _fsicontact.InputError
SolverFailure = _fsicontact.SolverFailure

__all__ = ["run", "Result", "InputError", "SolverFailure", "version"]


def version() -> str:
    """The version, the commit and the libraries, as `fsicontact --version` prints them."""
    return _fsicontact.version().strip()


class Result:
    """One run's outcome.

    summary      the dict of summary.json (status, the answer, timings, "program")
    history      history.csv's columns as NumPy arrays (empty if the run wrote none)
    status       summary["status"]: "converged", "iteration limit", "interrupted", ...
    converged    whether it converged
    exit_status  the command line's: 0, 3 (iteration limit), 128 + signal
    out_dir      where its files are
    report       the paragraph the command line prints
    """

    def __init__(self, native: Mapping[str, Any]):
        self.summary: dict = json.loads(native["summary"])
        self.exit_status: int = native["exit_status"]
        self.out_dir: str = native["out_dir"]
        self.report: str = native["report"]
        self.status: str = self.summary.get("status", "")
        self.converged: bool = self.exit_status == 0
        self.history: dict = _read_history(os.path.join(self.out_dir, "history.csv"))

    def __repr__(self) -> str:
        return f"<fsicontact.Result {self.summary.get('name', '')!r}: {self.status}, in {self.out_dir}>"


def _read_history(path: str) -> dict:
    if not os.path.isfile(path):
        return {}
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    columns = list(zip(*rows[1:])) if len(rows) > 1 else [()] * len(rows[0])
    out = {}
    for name, values in zip(rows[0], columns):
        try:
            out[name] = np.array([float(v) for v in values])
        except ValueError:
            out[name] = np.array(values)
    return out


def _set_value(value: Any, key: str = "set") -> str:
    """A --set value in TOML syntax: numbers, booleans, strings, lists."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float, np.integer, np.floating)):
        return repr(float(value)) if isinstance(value, (float, np.floating)) else str(int(value))
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_set_value(v, key) for v in list(value)) + "]"
    raise InputError(f"{key}: a value of type {type(value).__name__} cannot be a case value ({value!r})")


def run(case: Union[str, os.PathLike, Mapping[str, Any], None] = None, set: Optional[Mapping[str, Any]] = None,
        out: Union[str, os.PathLike, None] = None, progress: Optional[Callable[[str], None]] = None) -> Result:
    """Runs one case as `fsicontact run` does and returns its Result.

    case      a case file's path, a dict in the case file's structure
              ({"fluid": {"h": 0.02}, "coupling": {"scheme": "aitken"}}), or None for the
              paper's §7.2 case; relative paths in a file resolve against the file
    set       overrides, {"section.key": value}, as --set section.key=value
    out       the output directory (as --out); None: a new temporary directory
    progress  called with each progress line (one per coupling pass or solver iteration)

    Raises InputError (invalid input: exit 2, nothing written) or SolverFailure (a
    failure after validation: exit 1, summary.json written). Ctrl-C stops the run after
    its current iteration, writes what it has, and raises KeyboardInterrupt.
    """
    if set is not None and not isinstance(set, Mapping):
        raise InputError(f"set: expected a dict {{'section.key': value}}, not {type(set).__name__}")
    sets = []
    for key, value in (set or {}).items():
        if not isinstance(key, str):
            raise InputError(f"set: the key {key!r} is not a string 'section.key'")
        sets.append(f"{key}={_set_value(value, 'set ' + key)}")
    if out is None:
        out = tempfile.mkdtemp(prefix="fsicontact-")
    elif not isinstance(out, (str, os.PathLike)):
        raise InputError(f"out: expected a directory path, not {type(out).__name__}")
    if case is None or isinstance(case, (str, os.PathLike)):
        text, origin, is_path = os.fspath(case) if case is not None else "", "", True
    elif isinstance(case, Mapping):
        text, origin, is_path = _toml_dumps(case), "<dict>", False
    else:
        raise InputError(f"case: expected a path or a dict, not {type(case).__name__}")
    if progress is not None and not callable(progress):
        raise InputError("progress: expected a callable taking one line (str)")
    native = _fsicontact.run(text, origin, is_path, sets, os.fspath(out), progress)
    if native["exit_status"] == 1:
        raise SolverFailure(native["failure"])
    if native["interrupted"]:
        raise KeyboardInterrupt(f"fsicontact: interrupted; what was computed is in {native['out_dir']}")
    return Result(native)
