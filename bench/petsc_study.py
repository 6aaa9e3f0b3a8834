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
as BoomerAMG's aggressive coarsening, go through PETSC_OPTIONS as usual). --probe times,
before each round, what this machine's two cores give at that moment: a loop of
arithmetic in registers and a triad over 3 x 80 MB, each in one process and then in two
at once (the two's sum over the one), and each core's own memory latency (a random
chase through 128 MB) and triad bandwidth, the process held on that core. Two ranks wait
for the slower core, one rank runs on either: on memory-bound work the ceiling of their
speed-up is about 2 x the slower core's bandwidth over the faster's. Printed in a second
table at the end. And before each run, each core's throughput of vector multiply-adds
(16 independent chains, 1 s), a column of the first table: a core whose host core's
other hardware thread is busy loses most of it while its latency and bandwidth stay
(docs/performance.md, issue 32's twelfth part).

    bench/petsc_study.py [--program build/app/fsicontact] [--h 0.02 0.01 0.005]
                         [--eps 1e-3 1e-5 1e-7] [--solvers mumps petsc-iterative]
                         [--krylov gmres bicgstab] [--ranks 1 2] [--rounds 1] [--passes 1]
                         [--probe]
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import tempfile

PROBE = r"""
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
int main(int argc, char** argv) {
  if (argc > 1 && !strcmp(argv[1], "latency")) {  /* a random cycle through 128 MB */
    const size_t n = (size_t)1 << 24, loads = 5000000;
    size_t *p = malloc(n * sizeof *p), k = 0;
    if (!p) return 1;
    for (size_t i = 0; i < n; i++) p[i] = i;
    unsigned long long x = 88172645463325252ull;  /* Sattolo's shuffle: one cycle */
    for (size_t i = n - 1; i > 0; i--) {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      const size_t j = x % i, t = p[i];
      p[i] = p[j], p[j] = t;
    }
    for (size_t i = 0; i < loads / 5; i++) k = p[k];
    const double t0 = now();
    for (size_t i = 0; i < loads; i++) k = p[k];
    printf("%.6g\n", (now() - t0) / loads * 1e9 + (k == n ? 1 : 0));
    return 0;
  }
  if (argc > 1 && !strcmp(argv[1], "fma")) {  /* 16 independent vector chains, 1 s */
    typedef double v4 __attribute__((vector_size(32)));
    v4 a[16], m = {0.999999999, 0.999999999, 0.999999999, 0.999999999}, k = {1e-9, 1e-9, 1e-9, 1e-9};
    for (int i = 0; i < 16; i++) a[i] = (v4){1 + i * 1e-3, 1, 1, 1};
    double t0 = now(), t, s = 0;
    long n = 0;
    do {
      for (int r = 0; r < 100000; r++)
        for (int i = 0; i < 16; i++) a[i] = a[i] * m + k;
      n++;
    } while ((t = now() - t0) < 1.0);
    for (int i = 0; i < 16; i++) s += a[i][0];
    printf("%.6g\n", s > 0 ? n * 1e5 * 16 * 4 / t / 1e9 : 0);
    return 0;
  }
  if (argc > 1 && !strcmp(argv[1], "arithmetic")) {  /* four chains in registers, 2 s */
    double a = 1.0, b = 1.1, c = 1.2, d = 1.3, t0 = now(), t;
    long n = 0;
    do {
      for (int i = 0; i < 1000000; i++) a = a * 0.999999999 + 1e-9, b = b * 0.999999999 + 1e-9,
                                       c = c * 0.999999999 + 1e-9, d = d * 0.999999999 + 1e-9;
      n++;
    } while ((t = now() - t0) < 2.0);
    printf("%.6g\n", a + b + c + d > 0 ? n / t : 0);
    return 0;
  }
  const size_t n = 10000000;  /* the triad c = a + s b over 3 x 80 MB, 12 passes, the best */
  double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8), best = 1e30;
  if (!a || !b || !c) return 1;
  for (size_t i = 0; i < n; i++) a[i] = 1, b[i] = 2, c[i] = 0;
  for (int r = 0; r < 12; r++) {
    const double s = 3.0 + r * 1e-300, t0 = now();
    for (size_t i = 0; i < n; i++) c[i] = a[i] + s * b[i];
    const double t = now() - t0;
    if (t < best) best = t;
  }
  printf("%.6g\n", c[7] == 7 ? 3.0 * n * 8 / best / 1e9 : 0);
  return 0;
}
"""


def rate(binary, kind, k=1, core=None):
    """The sum of k processes' rates of kind, each held on core if given."""
    pin = None if core is None else (lambda: os.sched_setaffinity(0, {core}))
    ps = [subprocess.Popen([binary, kind], stdout=subprocess.PIPE, text=True, preexec_fn=pin) for _ in range(k)]
    return sum(float(p.communicate()[0]) for p in ps)


def two_cores():
    """The first two cores this process may run on."""
    return sorted(os.sched_getaffinity(0))[:2]


def cores_fma(binary):
    """Each of the two cores' multiply-adds, in GFMA/s, this moment."""
    return " / ".join(f"{rate(binary, 'fma', 1, c):.1f}" for c in two_cores())


def probe(binary):
    """This moment's (arithmetic, triad) of two processes over one, then each core's
    (latency in ns, triad in GB/s), the process held on it."""
    both = tuple(rate(binary, kind, 2) / rate(binary, kind, 1) for kind in ("arithmetic", "triad"))
    return both + tuple((rate(binary, "latency", 1, c), rate(binary, "triad", 1, c)) for c in two_cores())


def build_probe(tmp):
    cc = shutil.which("cc") or shutil.which("gcc")
    src, binary = os.path.join(tmp, "probe.c"), os.path.join(tmp, "probe")
    open(src, "w").write(PROBE)
    subprocess.run([cc, "-O2", "-march=native", src, "-o", binary], check=True)
    return binary


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
                    fma = f" {cores_fma(o.probe_binary)} |" if o.probe_binary else ""
                    r = run(o.program, h, eps, solver, krylov, ranks, out, o.passes)
                    its = "" if r["iterations"] is None else str(r["iterations"])
                    name = f"{solver} ({krylov})" if solver == "petsc-iterative" else solver
                    print(f"| {round} | {h} | {eps} | {r['unknowns']} | {name} | {ranks} | {r['wall']:.2f} s | "
                          f"{r['fluid']:.2f} s | {r['assembly']:.2f} s | {r['mb']:.0f} MB | {its} |{fma}", flush=True)


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
    a.add_argument("--probe", action="store_true",
                   help="time the machine's two cores: each core's multiply-adds before each run; "
                        "arithmetic, triads and latencies before each round")
    o = a.parse_args()
    print("| round | h | ε | unknowns | solver | ranks | wall | fluid solve | assembly | peak memory | Krylov iterations |"
          + (" cores' GFMA/s before |" if o.probe else ""))
    print("|---|---|---|---|---|---|---|---|---|---|---|" + ("---|" if o.probe else ""))
    with tempfile.TemporaryDirectory() as tmp:
        binary, probes = build_probe(tmp) if o.probe else None, []
        o.probe_binary = binary
        for round in range(1, o.rounds + 1):
            if binary:
                probes.append(probe(binary))
            table(o, tmp, round)
        if probes:
            print_probes(probes)


def print_probes(probes):
    print("\n| round | arithmetic: two at once / one | triad: two at once / one | "
          "core 0: latency, triad | core 1: latency, triad | 2 × slower / faster triad |\n|---|---|---|---|---|---|")
    for round, (arithmetic, triad, *cores) in enumerate(probes, 1):
        each = " | ".join(f"{ns:.0f} ns, {gbs:.1f} GB/s" for ns, gbs in cores)
        bw = [gbs for _, gbs in cores]
        ceiling = f"{2 * min(bw) / max(bw):.2f}×" if len(bw) == 2 else ""
        print(f"| {round} | {arithmetic:.2f}× | {triad:.2f}× | {each} | {ceiling} |")


if __name__ == "__main__":
    main()
