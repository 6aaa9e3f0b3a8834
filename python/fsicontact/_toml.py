"""A case given as a dict, written as TOML text for the case reader (the one validation
path): tables of keys with numbers, booleans, strings and lists; [[obstacles]] as a
list of tables. Anything else is an InputError naming the key."""
import json
import math

import numpy as np


def _value(key, v):
    from . import InputError
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        if not math.isfinite(v):
            return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
        return repr(float(v))
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_value(key, x) for x in list(v)) + "]"
    raise InputError(f"{key}: a value of type {type(v).__name__} cannot be a case value ({v!r})")


def dumps(case):
    from . import InputError
    top, tables = [], []
    for key, v in case.items():
        if not isinstance(key, str):
            raise InputError(f"case: the key {key!r} is not a string")
        if isinstance(v, dict):
            lines = [f"[{key}]"]
            for k, x in v.items():
                lines.append(f"{k} = {_value(key + '.' + str(k), x)}")
            tables.append("\n".join(lines))
        elif isinstance(v, (list, tuple)) and v and all(isinstance(x, dict) for x in v):
            for x in v:
                lines = [f"[[{key}]]"] + [f"{k} = {_value(key + '.' + str(k), y)}" for k, y in x.items()]
                tables.append("\n".join(lines))
        else:
            top.append(f"{key} = {_value(key, v)}")
    return "\n".join(top + [""] + tables) + "\n"
