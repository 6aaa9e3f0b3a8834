#!/usr/bin/env python3
"""The bar impact's three numbers from a run's outputs (docs/validation.md, "Bar impact").

    scripts/bar_impact_check.py OUT_DIR [OUT_DIR ...]

Against the closed form of Doyen, Ern & Piperno (2011) for cases/bar-impact.toml
(L = 1, H = 0.1, c = 10, v0 = 0.1, rho = 1): the first contact interval's duration
(summary.json, against 2L/c), the contact stress's plateau (history.csv's contact force
over H, averaged over the middle 60 % of the contact, against rho c v0) and the centre of
mass's velocity after it (against +v0); the largest energy drift and the number of contacts.
"""
import csv
import json
import sys

L, H, C, V0, RHO = 1.0, 0.1, 10.0, 0.1, 1.0

for out in sys.argv[1:]:
    summary = json.load(open(out + "/summary.json"))
    rows = list(csv.DictReader(open(out + "/history.csv")))
    first = summary["contact_intervals"][0]
    t0, t1 = first["start"], first["end"]
    middle = [float(r["contact_fx"]) for r in rows if t0 + 0.2 * (t1 - t0) <= float(r["t"]) <= t1 - 0.2 * (t1 - t0)]
    plateau = sum(middle) / len(middle) / H if middle else float("nan")  # a chattering first contact has none
    after = first["velocity_after"][0] if first["velocity_after"] else float("nan")
    print(f"{out}: duration {first['duration']:.5f} ({(first['duration'] / (2 * L / C) - 1) * 100:+.2f} %), "
          f"plateau {plateau:.4f} Pa ({(plateau / (RHO * C * V0) - 1) * 100:+.2f} %), "
          f"rebound {after:.5f} m/s ({(after / V0 - 1) * 100:+.2f} %), contacts {len(summary['contact_intervals'])}, "
          f"energy drift {summary['energy']['max_relative_drift']:.2g}, "
          f"final/initial energy {summary['energy']['final'] / summary['energy']['initial']:.3g}")
