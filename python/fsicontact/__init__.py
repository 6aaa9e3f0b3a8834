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
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _fsicontact
from ._toml import dumps as _toml_dumps

InputError = _fsicontact.InputError
SolverFailure = _fsicontact.SolverFailure

__all__ = ["run", "sweep", "converge", "Result", "StudyResult", "Fields", "InputError", "SolverFailure", "version"]


def version() -> str:
    """The version, the commit and the libraries, as `fsicontact --version` prints them."""
    return _fsicontact.version().strip()


class Fields(dict):
    """A final state's fields as NumPy arrays, what structure.vtu / fluid.vtu hold; keys
    also read as attributes (r.structure.displacement).

    structure: vertices (n, 2) reference, deformed (n, 2), triangles (m, 3), or (m, 6)
               for P2 (vertices, then the midpoints of edges 01, 12, 20), displacement
               (n, 2), displacement_magnitude, contact_multiplier, contact_status (n,:
               1 where the contact is active), von_mises (m,: per triangle)
    fluid:     vertices (n, 2), triangles (m, 3), velocity (n, 2: its P1 part),
               velocity_magnitude, pressure (n,), chi (m,: per triangle)
    """

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None


class Result:
    """One run's outcome.

    summary      the dict of summary.json (status, the answer, timings, "program")
    history      history.csv's columns as NumPy arrays (empty if the run wrote none)
    structure    the final structure's Fields (None: no structure, or fields=False)
    fluid        the final fluid's Fields (None: no fluid, or fields=False)
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
        self.structure: Optional[Fields] = Fields(native["structure"]) if native.get("structure") is not None else None
        self.fluid: Optional[Fields] = Fields(native["fluid"]) if native.get("fluid") is not None else None

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
        out: Union[str, os.PathLike, None] = None, progress: Optional[Callable[[str], None]] = None,
        fields: bool = True) -> Result:
    """Runs one case as `fsicontact run` does and returns its Result.

    case      a case file's path, a dict in the case file's structure
              ({"fluid": {"h": 0.02}, "coupling": {"scheme": "aitken"}}), or None for the
              paper's §7.2 case; relative paths in a file resolve against the file
    set       overrides, {"section.key": value}, as --set section.key=value
    out       the output directory (as --out); None: a new temporary directory
    progress  called with each progress line (one per coupling pass or solver iteration)
    fields    the final state's fields as arrays in Result.structure and Result.fluid

    Raises InputError (invalid input: exit 2, nothing written) or SolverFailure (a
    failure after validation: exit 1, summary.json written). Ctrl-C stops the run after
    its current iteration, writes what it has, and raises KeyboardInterrupt.
    """
    sets, out = _sets_and_out(set, out)
    text, origin, is_path = _case_text(case)
    _check_progress(progress)
    native = _fsicontact.run(text, origin, is_path, sets, out, progress, bool(fields))
    _raise_for(native)
    return Result(native)


def _sets_and_out(set: Optional[Mapping[str, Any]], out: Union[str, os.PathLike, None]):
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
    return sets, os.fspath(out)


def _case_text(case: Union[str, os.PathLike, Mapping[str, Any], None]):
    if case is None or isinstance(case, (str, os.PathLike)):
        return (os.fspath(case) if case is not None else ""), "", True
    if isinstance(case, Mapping):
        return _toml_dumps(case), "<dict>", False
    raise InputError(f"case: expected a path or a dict, not {type(case).__name__}")


def _check_progress(progress: Any) -> None:
    if progress is not None and not callable(progress):
        raise InputError("progress: expected a callable taking one line (str)")


def _raise_for(native: Mapping[str, Any]) -> None:
    if native["exit_status"] == 1 and "failure" in native:
        raise SolverFailure(native["failure"])
    if native["interrupted"]:
        raise KeyboardInterrupt(f"fsicontact: interrupted; what was computed is in {native['out_dir']}")


class StudyResult:
    """A sweep's or a convergence study's outcome.

    summary      the dict of the study's summary.json
    runs         each run's Result: a sweep's by row (0, 1, ...), a study's by its
                 directory ("level-1", "level-2-aitken", "level-3-eps")
    table        a sweep's table.csv columns as NumPy arrays (empty for converge)
    exit_status  the command line's: 0, 1 (a run failed), 3 (a run at its limit)
    out_dir      where its files are
    report       the table the command line prints
    """

    def __init__(self, native: Mapping[str, Any]):
        self.out_dir: str = native["out_dir"]
        self.exit_status: int = native["exit_status"]
        self.report: str = native["report"]
        if "summary" in native:
            self.summary: dict = json.loads(native["summary"])
        else:
            with open(os.path.join(self.out_dir, "summary.json")) as f:
                self.summary = json.load(f)
        self.runs: dict = {key: Result(r) for key, r in native["runs"].items()}
        self.table: dict = _read_history(os.path.join(self.out_dir, "table.csv"))

    def __repr__(self) -> str:
        return f"<fsicontact.StudyResult {self.summary.get('problem', '')}: {len(self.runs)} runs, in {self.out_dir}>"


def sweep(case: Union[str, os.PathLike, Mapping[str, Any], None], rows: Union[str, os.PathLike, Sequence[Mapping[str, Any]]],
          set: Optional[Mapping[str, Any]] = None, out: Union[str, os.PathLike, None] = None,
          keep_outputs: bool = False, progress: Optional[Callable[[str], None]] = None,
          fields: bool = True) -> StudyResult:
    """Runs one case per row as `fsicontact sweep` does (e.g. the paper's Table 1).

    rows          a CSV file whose headers are case keys (section.key; paper.* columns
                  are references, "label" names a row), or a list of dicts
                  [{"coupling.omega": 0.5, "coupling.eps": 1e-4}, ...]
    keep_outputs  write each row's .vtu and .png too
    Other arguments as run(); StudyResult.runs[i] is row i's Result.
    """
    sets, out = _sets_and_out(set, out)
    text, origin, is_path = _case_text(case)
    _check_progress(progress)
    with tempfile.TemporaryDirectory(prefix="fsicontact-rows-") as tmp:
        if isinstance(rows, (str, os.PathLike)):
            rows_path = os.fspath(rows)
        elif isinstance(rows, Sequence) and all(isinstance(r, Mapping) for r in rows):
            rows_path = os.path.join(tmp, "rows.csv")
            _write_rows(rows_path, rows)
        else:
            raise InputError(f"rows: expected a CSV path or a list of dicts, not {type(rows).__name__}")
        native = _fsicontact.sweep(text, origin, is_path, rows_path, sets, out, bool(keep_outputs), progress,
                                   bool(fields))
    _raise_for(native)
    return StudyResult(native)


def _write_rows(path: str, rows: Sequence[Mapping[str, Any]]) -> None:
    keys: list = []
    for r in rows:
        for k in r:
            if not isinstance(k, str):
                raise InputError(f"rows: the key {k!r} is not a string 'section.key'")
            if k not in keys:
                keys.append(k)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([_set_value(r[k], "rows " + k).strip('"') if k in r else "" for k in keys])


def converge(case: Union[str, os.PathLike, Mapping[str, Any], None], levels: int = 3, ratio: float = 2,
             schemes: Optional[Sequence[str]] = None, refine: str = "all", set: Optional[Mapping[str, Any]] = None,
             out: Union[str, os.PathLike, None] = None, progress: Optional[Callable[[str], None]] = None,
             fields: bool = False) -> StudyResult:
    """Runs the case on refined levels as `fsicontact converge` does: per quantity the
    values, the observed order, the extrapolated value and its error bar
    (StudyResult.summary["quantities"]).

    levels   3 to 10, the case itself the coarsest; ratio: the size ratio per level
    schemes  coupling schemes run at every level (the first gives the values)
    refine   "all", "fluid" or "structure"
    fields   each run's final fields in StudyResult.runs (off by default: the finest
             levels' are large)
    Other arguments as run().
    """
    sets, out = _sets_and_out(set, out)
    text, origin, is_path = _case_text(case)
    _check_progress(progress)
    if isinstance(schemes, str):
        schemes = schemes.split(",")
    native = _fsicontact.converge(text, origin, is_path, sets, out, int(levels), float(ratio), list(schemes or []),
                                  str(refine), progress, bool(fields))
    _raise_for(native)
    return StudyResult(native)
