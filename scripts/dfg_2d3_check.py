#!/usr/bin/env python3
"""DFG 2D-3's numbers from a run's history.csv (docs/validation.md, "DFG 2D-3").

    scripts/dfg_2d3_check.py OUT_DIR [OUT_DIR ...]

For cases/dfg-2d3.toml (D = 0.1, the mean inflow U = 1 at its peak, rho = 1): C_D = 20 F_x
and C_L = 20 F_y from history.csv's obstacle_1_force_x and _y over t in [0, 8]; each
one's largest value and its time, refined by the parabola through the largest sample
and its two neighbours. Against John 2004's reference values (Int. J. Numer. Meth.
Fluids 44, 777-788): C_D,max 2.950921575 at t = 3.93625, C_L,max 0.47795 at t = 5.693125.
"""
import csv
import sys

REFERENCE = {"C_D": (2.950921575, 3.93625), "C_L": (0.47795, 5.693125)}


def peak(t, c):
    """The largest value of the samples c(t) and its time, by a parabola through three."""
    i = max(range(len(c)), key=lambda k: c[k])
    if i == 0 or i == len(c) - 1:
        return c[i], t[i]
    a, b, d = c[i - 1], c[i], c[i + 1]
    h = t[i + 1] - t[i]
    denom = a - 2 * b + d
    s = 0.5 * (a - d) / denom if denom != 0 else 0.0  # the vertex, in steps from t[i]
    return b - 0.25 * (a - d) * s, t[i] + s * h


for out in sys.argv[1:]:
    rows = list(csv.DictReader(open(out + "/history.csv")))
    t = [float(r["t"]) for r in rows]
    values = {"C_D": [20 * float(r["obstacle_1_force_x"]) for r in rows],
              "C_L": [20 * float(r["obstacle_1_force_y"]) for r in rows]}
    parts = []
    for name, c in values.items():
        value, when = peak(t, c)
        ref, ref_t = REFERENCE[name]
        parts.append(f"{name},max {value:.5f} at t = {when:.4f} (reference {ref:.5f} at {ref_t:.4f}; "
                     f"{100 * (value - ref) / ref:+.3f} %)")
    print(f"{out}: " + ", ".join(parts))
