#!/usr/bin/env bash
# The fluid solve against the mesh size, on the paper's §7.2 box (docs/performance.md):
#  1. build/bench/fluid_bench for the given solvers at each hF: assembly, numeric
#     factorisation (analysis reused), solve, PenalisedStokes::solve() after a χ
#     change; medians of N repetitions, randomly interleaved;
#  2. the program itself, fluid alone (coupling.max_iterations=0), N times per hF
#     under /usr/bin/time -v: peak resident memory, wall time, and the fluid timings
#     of summary.json (its factorisation includes the one symbolic analysis);
#  3. a table per solver and the least-squares slope of log(time) against
#     log(unknowns) for factorisation and solve.
# Usage:
#   bench/fluid_scaling.sh [--repeats N] [--solvers "mumps-metis umfpack"]
#                          [--sizes "0.02 0.01 0.005 0.0025"] [--out DIR]
#                          [--skip-bench] [--skip-program]
# FLUID_BENCH and FSICONTACT name the binaries (default build/bench/fluid_bench,
# build/app/fsicontact). The program uses its default solver, whatever --solvers says.
set -euo pipefail
cd "$(dirname "$0")/.."
BENCH=${FLUID_BENCH:-build/bench/fluid_bench}
BIN=${FSICONTACT:-build/app/fsicontact}
REPEATS=5 SOLVERS="mumps-metis umfpack" SIZES="0.02 0.01 0.005 0.0025" OUT=out/bench-fluid
RUN_BENCH=1 RUN_PROGRAM=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --repeats) REPEATS=$2; shift 2 ;;
    --solvers) SOLVERS=$2; shift 2 ;;
    --sizes) SIZES=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --skip-bench) RUN_BENCH=0; shift ;;
    --skip-program) RUN_PROGRAM=0; shift ;;
    *) echo "usage: $0 [--repeats N] [--solvers \"a b\"] [--sizes \"h1 h2\"] [--out DIR] [--skip-bench] [--skip-program]" >&2
       exit 2 ;;
  esac
done
mkdir -p "$OUT"

if [[ $RUN_BENCH == 1 ]]; then
  [[ -x $BENCH ]] || { echo "fluid_scaling.sh: build first; no $BENCH" >&2; exit 2; }
  solvers_re=$(echo $SOLVERS | sed 's/ /|/g')
  sizes_re=$(echo $SIZES | sed 's/ /|/g; s/\./\\./g')
  "$BENCH" --benchmark_filter="^(assembly|(factorize|solve|stokes_solve)/($solvers_re))/hF:($sizes_re)\$" \
    --benchmark_repetitions="$REPEATS" --benchmark_enable_random_interleaving=true \
    --benchmark_report_aggregates_only=true --benchmark_out="$OUT/bench.json" --benchmark_out_format=json \
    > "$OUT/bench.txt"
fi

if [[ $RUN_PROGRAM == 1 ]]; then
  [[ -x $BIN ]] || { echo "fluid_scaling.sh: build first; no $BIN" >&2; exit 2; }
  command -v /usr/bin/time > /dev/null || { echo "fluid_scaling.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
  for r in $(seq 1 "$REPEATS"); do  # sizes interleaved within each repeat
    for h in $SIZES; do
      dir="$OUT/program-h$h-r$r"
      /usr/bin/time -v -o "$dir.time" "$BIN" run cases/paper-7.2.toml -q --set coupling.max_iterations=0 \
        --set fluid.h="$h" --set output.png=false --set output.vtu=false --out "$dir" > /dev/null
    done
  done
fi

python3 - "$OUT" "$SIZES" "$SOLVERS" "$REPEATS" <<'PY'
import glob, json, math, os, re, statistics, sys
out, sizes, solvers, repeats = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), int(sys.argv[4])

bench = {}  # (kind, solver or "", hF) -> (median ms, counters)
path = os.path.join(out, "bench.json")
if os.path.exists(path):
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        parts = b["run_name"].split("/")
        kind, h = parts[0], parts[-1].split(":")[1]
        solver = parts[1] if len(parts) == 3 else ""
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
        bench[(kind, solver, h)] = (b["real_time"] * scale, b)

program = {}  # hF -> lists of peak MB, wall s, fluid timings
for h in sizes:
    rows = []
    for r in range(1, repeats + 1):
        base = os.path.join(out, f"program-h{h}-r{r}")
        try:
            text = open(base + ".time").read()
            summary = json.load(open(os.path.join(base, "summary.json")))
        except OSError:
            continue
        peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024
        clock = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1).split(":")
        wall = sum(float(x) * 60 ** i for i, x in enumerate(reversed(clock)))
        f = summary["fluid"]
        rows.append((peak, wall, f["factorization_s"], f["solve_s"], f["unknowns"], f["solver"]))
    if rows:
        med = lambda i: statistics.median(r[i] for r in rows)
        program[h] = dict(peak=med(0), wall=med(1), factorization=med(2), solve=med(3), unknowns=rows[0][4],
                          solver=rows[0][5], runs=len(rows))

def cell(key, fmt="{:.1f}"):
    return fmt.format(bench[key][0]) if key in bench else "-"

if len(solvers) > 1:  # the candidates side by side, one table per hF
    for h in sizes:
        if not any(k[2] == h and k[1] for k in bench):
            continue
        print(f"\n### hF = {h} (fluid_bench medians of {repeats}, ms)\n")
        print("| solver | analysis (once) | factorisation | solve | PenalisedStokes::solve after a χ change | relative residual | difference to umfpack | factor entries | factor flops |")
        print("|---|---|---|---|---|---|---|---|---|")
        for solver in solvers:
            f, s = bench.get(("factorize", solver, h)), bench.get(("solve", solver, h))
            analysis = f"{1e3 * f[1]['analysis_s']:.1f}" if f else "-"
            residual = f"{s[1]['relative_residual']:.1e}" if s else "-"
            difference = f"{s[1]['difference_to_umfpack']:.1e}" if s else "-"
            entries = f"{f[1]['factor_entries'] / 1e6:.2f} M" if f and "factor_entries" in f[1] else "-"
            flops = f"{f[1]['factor_flops']:.2e}" if f and "factor_flops" in f[1] else "-"
            print(f"| {solver} | {analysis} | {cell(('factorize', solver, h))} | {cell(('solve', solver, h), '{:.2f}')} | "
                  f"{cell(('stokes_solve', solver, h))} | {residual} | {difference} | {entries} | {flops} |")

for solver in solvers:
    if not any(k[1] == solver for k in bench):
        continue
    print(f"\n### {solver} (fluid_bench medians of {repeats}, ms)\n")
    print("| hF | unknowns | nonzeros | assembly | analysis (once) | factorisation | solve | PenalisedStokes::solve after a χ change |")
    print("|---|---|---|---|---|---|---|---|")
    for h in sizes:
        f = bench.get(("factorize", solver, h))
        if not f:
            continue
        c = f[1]
        print(f"| {h} | {int(c['unknowns'])} | {int(c['nonzeros'])} | {cell(('assembly', '', h))} | "
              f"{1e3 * c['analysis_s']:.1f} | {cell(('factorize', solver, h))} | {cell(('solve', solver, h), '{:.2f}')} | "
              f"{cell(('stokes_solve', solver, h))} |")
    for kind in ("factorize", "solve", "stokes_solve"):
        pts = [(bench[(kind, solver, h)][1]["unknowns"], bench[(kind, solver, h)][0]) for h in sizes
               if (kind, solver, h) in bench]
        if len(pts) < 2:
            continue
        xs = [math.log(n) for n, _ in pts]
        ys = [math.log(t) for _, t in pts]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print(f"\n{kind}: time ∝ unknowns^{slope:.2f} (least squares on log–log, {len(pts)} sizes)", end="")
    print()

if program:
    solver = next(iter(program.values()))["solver"]
    print(f"\n### the program, fluid alone ({solver}; medians of up to {repeats} runs)\n")
    print("| hF | unknowns | peak memory (MB) | wall (s) | analysis + factorisation (s) | solve (s) |")
    print("|---|---|---|---|---|---|")
    for h, p in program.items():
        print(f"| {h} | {p['unknowns']} | {p['peak']:.0f} | {p['wall']:.2f} | {p['factorization']:.3f} | {p['solve']:.4f} |")
PY
