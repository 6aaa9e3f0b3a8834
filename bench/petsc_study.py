#!/usr/bin/env python3
"""The fluid's linear solvers against h and ε (issue 32; docs/performance.md "PETSc").

One fluid solve of the §7.2 case around the structure at rest (coupling.max_iterations
= 1: the first pass's solve, then the structure's, then a stop that is not a failure of
the solver; --passes P runs P passes, each a fluid solve, whose peak memory is a real
run's) for each fluid size h, penalty ε, fluid.linear_solver and number of MPI
ranks; prints a markdown table of wall time, the fluid's factorisation-and-solve time
(summary.json's fluid.factorization_s + solve_s: the preconditioner's set-up and the Krylov solve
for "petsc-iterative"), the fluid's assembly time, peak memory (the largest process's:
a rank's) and, for "petsc-iterative", the Krylov iterations. With --rounds R the whole
table is run R times, one round after the other (interleaved): this machine's timings
drift by tens of per cent within a session, so a ratio is read within a round.
--krylov runs "petsc-iterative" with each fluid.krylov given (PETSc's own options, such
as BoomerAMG's aggressive coarsening, go through PETSC_OPTIONS as usual).

    bench/petsc_study.py [--program build/app/fsicontact] [--h 0.02 0.01 0.005]
                         [--eps 1e-3 1e-5 1e-7] [--solvers mumps petsc-iterative]
                         [--krylov gmres bicgstab] [--ranks 1 2] [--rounds 1] [--passes 1]
"""
import argparse
import json
import os
import re
import subprocess
import tempfile


def run(program, h, eps, solver, krylov, ranks, out, passes=1):
    mpi = [] if ranks == 1 else ["mpiexec", "-n", str(ranks)]
    cmd = ["/usr/bin/time", "-f", "%e %M"] + mpi + [program, "run", "-q", "--out", out,
           "--set", f"fluid.h={h}", "--set", f"coupling.eps={eps}", "--set", "coupling.eps_rule=\"fixed\"",
           "--set", f"coupling.max_iterations={passes}", "--set", f"fluid.linear_solver=\"{solver}\"", "--set", f"fluid.krylov={krylov}",
           "--set", "output.png=false", "--set", "output.vtu=false"]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall, kb = p.stderr.strip().splitlines()[-1].split()
    s = json.load(open(os.path.join(out, "summary.json")))
    f = s.get("fluid", {})
    its = f.get("linear_iterations", [])
    its = [",".join(map(str, its))] if its else its
    return {"wall": float(wall), "mb": int(kb) / 1024, "unknowns": f.get("unknowns"),
            "fluid": f.get("factorization_s", 0) + f.get("solve_s", 0), "assembly": f.get("assembly_s", 0),
            "iterations": its[0] if its else None, "status": s.get("status")}


def table(o, tmp, round):
    for h in o.h:
        for eps in o.eps:
            for solver, krylov in variants(o):
                for ranks in o.ranks:
                    if ranks > 1 and solver == "mumps":
                        continue  # one rank only
                    out = os.path.join(tmp, re.sub(r"\W", "_", f"{h}-{eps}-{solver}-{krylov}-{ranks}"))
                    r = run(o.program, h, eps, solver, krylov, ranks, out, o.passes)
                    its = "" if r["iterations"] is None else str(r["iterations"])
                    name = f"{solver} ({krylov})" if solver == "petsc-iterative" else solver
                    print(f"| {round} | {h} | {eps} | {r['unknowns']} | {name} | {ranks} | {r['wall']:.2f} s | "
                          f"{r['fluid']:.2f} s | {r['assembly']:.2f} s | {r['mb']:.0f} MB | {its} |", flush=True)


def variants(o):
    """(solver, Krylov method) pairs: every method for the iterative solver, one for the others."""
    return [(s, k) for s in o.solvers for k in (o.krylov if s == "petsc-iterative" else o.krylov[:1])]


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--program", default="build/app/fsicontact")
    a.add_argument("--h", nargs="+", default=["0.02", "0.01", "0.005"])
    a.add_argument("--eps", nargs="+", default=["1e-3", "1e-5", "1e-7"])
    a.add_argument("--solvers", nargs="+", default=["mumps", "petsc-iterative"])
    a.add_argument("--krylov", nargs="+", default=["gmres"], choices=["gmres", "bicgstab"])
    a.add_argument("--ranks", nargs="+", type=int, default=[1])
    a.add_argument("--rounds", type=int, default=1)
    a.add_argument("--passes", type=int, default=1,
                   help="coupling passes (a run's later passes rebuild the preconditioner)")
    o = a.parse_args()
    print("| round | h | ε | unknowns | solver | ranks | wall | fluid solve | assembly | peak memory | Krylov iterations |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for round in range(1, o.rounds + 1):
            table(o, tmp, round)


if __name__ == "__main__":
    main()
