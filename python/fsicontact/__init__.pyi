"""fsicontact from Python: fluid-structure interaction with contact (see __init__.py)."""
import os
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

class InputError(ValueError):
    """Invalid input (the command line's exit 2): the message names the file, key and allowed range."""

class SolverFailure(RuntimeError):
    """A failure after validation (exit 1): summary.json in the output directory says so."""

class Fields(dict[str, np.ndarray]):
    def __getattr__(self, name: str) -> np.ndarray: ...

class Result:
    summary: dict
    history: dict[str, np.ndarray]
    structure: Optional[Fields]
    fluid: Optional[Fields]
    status: str
    converged: bool
    exit_status: int
    out_dir: str
    report: str

class StudyResult:
    summary: dict
    runs: dict[Union[int, str], Result]
    table: dict[str, np.ndarray]
    exit_status: int
    out_dir: str
    report: str

Case = Union[str, os.PathLike, Mapping[str, Any], None]

def version() -> str: ...
def run(case: Case = ..., set: Optional[Mapping[str, Any]] = ..., out: Union[str, os.PathLike, None] = ...,
        progress: Optional[Callable[[str], None]] = ..., fields: bool = ...) -> Result: ...
def sweep(case: Case, rows: Union[str, os.PathLike, Sequence[Mapping[str, Any]]], set: Optional[Mapping[str, Any]] = ...,
          out: Union[str, os.PathLike, None] = ..., keep_outputs: bool = ...,
          progress: Optional[Callable[[str], None]] = ..., fields: bool = ...) -> StudyResult: ...
def converge(case: Case, levels: int = ..., ratio: float = ..., schemes: Optional[Sequence[str]] = ...,
             refine: str = ..., set: Optional[Mapping[str, Any]] = ..., out: Union[str, os.PathLike, None] = ...,
             progress: Optional[Callable[[str], None]] = ..., fields: bool = ...) -> StudyResult: ...
