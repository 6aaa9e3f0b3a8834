"""fsicontact from Python: fluid-structure interaction with contact (see __init__.py)."""
import os
from typing import Any, Callable, Mapping, Optional, Union

import numpy as np

class InputError(ValueError):
    """Invalid input (the command line's exit 2): the message names the file, key and allowed range."""

class SolverFailure(RuntimeError):
    """A failure after validation (exit 1): summary.json in the output directory says so."""

class Result:
    summary: dict
    history: dict[str, np.ndarray]
    status: str
    converged: bool
    exit_status: int
    out_dir: str
    report: str

def version() -> str: ...
def run(case: Union[str, os.PathLike, Mapping[str, Any], None] = ..., set: Optional[Mapping[str, Any]] = ...,
        out: Union[str, os.PathLike, None] = ..., progress: Optional[Callable[[str], None]] = ...) -> Result: ...
