#!/usr/bin/env python3
"""DFG 2D-2's three numbers from a run's history.csv (docs/validation.md, "DFG 2D-2").

    scripts/dfg_2d2_check.py OUT_DIR [OUT_DIR ...] [--from T]

For cases/dfg-2d2.toml (D = 0.1, mean inflow U = 1, rho = 1): C_D = 20 F_x and
C_L = 20 F_y from history.csv's obstacle_1_force_x and _y; their largest values over
t >= T (default 9 s, the periodic regime); the Strouhal number St = D / (U * period),
the period the mean spacing of the lift's upward crossings of its mean (linear
interpolation between steps) over t >= T. Against Schaefer & Turek's ranges (John 2004's
digits): C_D,max 3.22-3.24 (3.2262), C_L,max 0.99-1.01 (1.0020), St 0.295-0.305 (0.3010).
"""
import csv
import sys

D, U = 0.1, 1.0
args = sys.argv[1:]
t_from = 9.0
if "--from" in args:
    k = args.index("--from")
    t_from = float(args[k + 1])
    del args[k:k + 2]

for out in args:
    rows = [r for r in csv.DictReader(open(out + "/history.csv")) if float(r["t"]) >= t_from]
    t = [float(r["t"]) for r in rows]
    cd = [20 * float(r["obstacle_1_force_x"]) for r in rows]
    cl = [20 * float(r["obstacle_1_force_y"]) for r in rows]
    mean = sum(cl) / len(cl)
    ups = [t[i] + (t[i + 1] - t[i]) * (mean - cl[i]) / (cl[i + 1] - cl[i])
           for i in range(len(cl) - 1) if cl[i] < mean <= cl[i + 1]]
    st = D / (U * (ups[-1] - ups[0]) / (len(ups) - 1)) if len(ups) > 1 else float("nan")
    print(f"{out}: t in [{t[0]:g}, {t[-1]:g}] s, C_D,max {max(cd):.4f}, C_L,max {max(cl):.4f}, "
          f"C_L,min {min(cl):.4f}, St {st:.4f} ({len(ups) - 1} periods)")
