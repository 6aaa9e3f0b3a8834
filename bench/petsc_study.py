#!/usr/bin/env python3
"""The fluid's linear solvers against h and ε (issue 32; docs/performance.md "PETSc").

One fluid solve of the §7.2 case around the structure at rest (coupling.max_iterations
= 1: the first pass's solve, then the structure's, then a stop that is not a failure of
the solver) for each fluid size h, penalty ε and fluid.linear_solver; prints a markdown
table of wall time, peak memory and, for "petsc-iterative", the GMRES iterations.

    bench/petsc_study.py [--program build/app/fsicontact] [--h 0.02 0.01 0.005]
                         [--eps 1e-3 1e-5 1e-7] [--solvers mumps petsc-iterative]
"""
import argparse
import json
import os
import re
import subprocess
import tempfile


def run(program, h, eps, solver, out):
    cmd = ["/usr/bin/time", "-f", "%e %M", program, "run", "-q", "--out", out,
           "--set", f"fluid.h={h}", "--set", f"coupling.eps={eps}", "--set", "coupling.eps_rule=\"fixed\"",
           "--set", "coupling.max_iterations=1", "--set", f"fluid.linear_solver=\"{solver}\"",
           "--set", "output.png=false", "--set", "output.vtu=false"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall, kb = p.stderr.strip().splitlines()[-1].split()
    s = json.load(open(os.path.join(out, "summary.json")))
    f = s.get("fluid", {})
    its = f.get("linear_iterations", [])
    return {"wall": float(wall), "mb": int(kb) / 1024, "unknowns": f.get("unknowns"),
            "iterations": its[0] if its else None, "status": s.get("status")}


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--program", default="build/app/fsicontact")
    a.add_argument("--h", nargs="+", default=["0.02", "0.01", "0.005"])
    a.add_argument("--eps", nargs="+", default=["1e-3", "1e-5", "1e-7"])
    a.add_argument("--solvers", nargs="+", default=["mumps", "petsc-iterative"])
    o = a.parse_args()
    print("| h | ε | unknowns | solver | wall | peak memory | GMRES iterations |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for h in o.h:
            for eps in o.eps:
                for solver in o.solvers:
                    r = run(o.program, h, eps, solver, os.path.join(tmp, re.sub(r"\W", "_", f"{h}-{eps}-{solver}")))
                    its = "" if r["iterations"] is None else str(r["iterations"])
                    print(f"| {h} | {eps} | {r['unknowns']} | {solver} | {r['wall']:.2f} s | {r['mb']:.0f} MB | {its} |",
                          flush=True)


if __name__ == "__main__":
    main()
