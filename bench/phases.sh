#!/usr/bin/env bash
# Where the time of a whole coupled run goes (docs/performance.md, "The coupling",
# "What every run pays"): runs rows of the paper's Table 1 (cases/table1.csv; no PNG,
# no VTU unless --outputs) and, with --demo, `make demo`'s run (cases/paper-7.2.toml
# with its PNG and VTU outputs), each N times under /usr/bin/time -v, and prints per run
# the medians over the repetitions of: wall time and peak resident memory, and the
# phases of summary.json (timing_s, fluid.*) and history.csv.
#   bench/phases.sh [--rows 2,7,8,9] [--repeats N] [--demo] [--outputs] [--before BIN]
#                   [--out DIR] [--report-only]
# FSICONTACT names the binary (default build/app/fsicontact); --before another (an
# earlier build), run beside it on the same rows, its columns marked "before".
# Repetitions interleave the rows and the binaries (row a, row b, ..., then again), so
# a slow spell of the machine hits all of them.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${FSICONTACT:-build/app/fsicontact}
ROWS=2 REPEATS=5 DEMO=0 OUT=out/bench-phases REPORT_ONLY=0 OUTPUTS=false BEFORE=""
usage() { echo "usage: $0 [--rows 2,7,...] [--repeats N] [--demo] [--outputs] [--before BIN] [--out DIR] [--report-only]" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rows) [[ $# -ge 2 ]] || usage; ROWS=$2; shift 2 ;;
    --repeats) [[ $# -ge 2 ]] || usage; REPEATS=$2; shift 2 ;;
    --demo) DEMO=1; shift ;;
    --outputs) OUTPUTS=true; shift ;;
    --before) [[ $# -ge 2 ]] || usage; BEFORE=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; OUT=$2; shift 2 ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) usage ;;
  esac
done
mkdir -p "$OUT"

if [[ $REPORT_ONLY -eq 0 ]]; then
  [[ -x $BIN ]] || { echo "phases.sh: build first; no $BIN" >&2; exit 2; }
  [[ -z $BEFORE || -x $BEFORE ]] || { echo "phases.sh: no binary at --before $BEFORE" >&2; exit 2; }
  [[ -x /usr/bin/time ]] || { echo "phases.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
  mapfile -t table < <(grep -v '^#' cases/table1.csv | tail -n +2)
  for r in $(seq 1 "$REPEATS"); do
    if [[ $DEMO -eq 1 ]]; then
      /usr/bin/time -v -o "$OUT/demo-r$r.time" "$BIN" run cases/paper-7.2.toml -q --out "$OUT/demo-r$r" > /dev/null
    fi
    for n in ${ROWS//,/ }; do
      IFS=, read -r eps omega hF hS _ <<< "${table[$((n - 1))]}"
      for which in after before; do
        [[ $which == after ]] && bin=$BIN prefix=row || bin=$BEFORE prefix=before-row
        [[ -n $bin ]] || continue
        dir="$OUT/$prefix-$(printf %02d "$n")-r$r"
        set +e
        /usr/bin/time -v -o "$dir.time" "$bin" run cases/paper-7.2.toml -q \
          --set coupling.eps="$eps" --set coupling.omega="$omega" --set fluid.h="$hF" --set structure.h="$hS" \
          --set output.png=$OUTPUTS --set output.vtu=$OUTPUTS --out "$dir" > /dev/null 2> "$dir.err"
        echo "$prefix $n repeat $r: exit $?" >&2
        set -e
      done
    done
  done
fi

python3 - "$OUT" "$ROWS" "$DEMO" <<'PY'
import csv, glob, json, os, re, statistics, sys
out, rows, demo = sys.argv[1], sys.argv[2].split(","), sys.argv[3] == "1"

def time_v(path):
    text = open(path).read()
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024
    clock = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1).split(":")
    return sum(float(x) * 60 ** i for i, x in enumerate(reversed(clock))), peak

def one(base):
    wall, peak = time_v(base + ".time")
    j = json.load(open(os.path.join(base, "summary.json")))
    t, f = j["timing_s"], j["fluid"]
    hist = list(csv.DictReader(open(os.path.join(base, "history.csv"))))
    qp = sum(float(h["t_structure_s"]) for h in hist)
    fluid_iter = sum(float(h["t_fluid_s"]) for h in hist)
    sampled = sum(float(h["t_transfer_s"]) for h in hist)
    known = t["mesh"] + t["fluid"] + t["structure"] + t["transfer"] + t.get("output", 0)
    return {
        "wall": wall, "peak": peak, "total": t["total"], "mesh": t["mesh"],
        "fluid": t["fluid"], "fluid setup": t["fluid"] - fluid_iter,
        "assembly": f["assembly_s"], "factorization": f["factorization_s"], "solve": f["solve_s"],
        "fluid other": fluid_iter - f["assembly_s"] - f["factorization_s"] - f["solve_s"],
        "structure": t["structure"], "structure setup": t["structure"] - qp, "qp": qp,
        "transfer": t["transfer"], "chi": t.get("chi", 0), "force": sampled,
        "output": t.get("output", 0), "rest": t["total"] - known, "start/exit": wall - t["total"],
        "iterations": j["iterations"], "factorizations": f["factorizations"], "reused": f["reused_solutions"],
        "unknowns": f["unknowns"], "fluid_tri": j["mesh"]["fluid"]["triangles"],
        "structure_tri": j["mesh"]["structure"]["triangles"], "status": j["status"],
        "per_factorization": f["factorization_s"] / max(1, f["factorizations"]),
    }

runs = []
if demo:
    runs.append(("demo", "demo"))
for n in rows:
    runs.append((f"row {n}", f"row-{int(n):02d}"))
    runs.append((f"row {n} before", f"before-row-{int(n):02d}"))
med = {}
for name, prefix in runs:
    reps = []
    for base in sorted(glob.glob(os.path.join(out, prefix + "-r*.time"))):
        try:
            reps.append(one(base[:-5]))
        except (OSError, KeyError, ValueError, AttributeError):
            pass
    if not reps:
        continue
    m = {k: statistics.median(r[k] for r in reps) for k in reps[0] if not isinstance(reps[0][k], str)}
    m["status"] = ",".join(sorted({r["status"] for r in reps}))
    m["n"] = len(reps)
    m["spread"] = (min(r["wall"] for r in reps), max(r["wall"] for r in reps))
    med[name] = m

names = list(med)
print("| | " + " | ".join(names) + " |")
print("|---|" + "---|" * len(names))
def row(label, key, fmt="{:.2f}"):
    print(f"| {label} | " + " | ".join(fmt.format(med[n][key]) for n in names) + " |")
def row_pct(label, key):
    print(f"| {label} | " + " | ".join(f"{med[n][key]:.3f} s ({100 * med[n][key] / med[n]['total']:.1f} %)"
                                       for n in names) + " |")
row("runs (medians of)", "n", "{:.0f}")
print("| status | " + " | ".join(med[n]["status"] for n in names) + " |")
row("fluid triangles", "fluid_tri", "{:.0f}")
row("fluid unknowns", "unknowns", "{:.0f}")
row("structure triangles", "structure_tri", "{:.0f}")
row("fixed-point iterations", "iterations", "{:.0f}")
row("fluid factorisations", "factorizations", "{:.0f}")
row("fluid solves skipped (χ unchanged)", "reused", "{:.0f}")
print("| wall time (s), min–max | " + " | ".join(f"{med[n]['wall']:.2f} ({med[n]['spread'][0]:.2f}–{med[n]['spread'][1]:.2f})"
                                            for n in names) + " |")
row("peak memory (MB)", "peak", "{:.0f}")
row("timing_s.total (s)", "total", "{:.3f}")
row_pct("mesh (both meshes, built and checked)", "mesh")
row_pct("fluid", "fluid")
row_pct("  set-up (point locator, χ computer, pattern, element geometry)", "fluid setup")
row_pct("  assembly", "assembly")
row_pct("  analysis + factorisations", "factorization")
row_pct("  solves (incl. residual check, bubbles)", "solve")
row_pct("  rest", "fluid other")
row_pct("structure", "structure")
row_pct("  set-up (A_S, C_S, Cholesky, S)", "structure setup")
row_pct("  contact QPs", "qp")
row_pct("transfer", "transfer")
row_pct("  χ", "chi")
row_pct("  v_h, p_h at the deformed vertices + force (33)", "force")
row_pct("output (summary, history, case; PNG, VTU for the demo or --outputs)", "output")
row_pct("rest (final ‖v_h‖ over Ω_S^u, contact summary)", "rest")
row("process start/exit, outside timing_s (s)", "start/exit", "{:.3f}")
row("one analysis + factorisation, averaged (s)", "per_factorization", "{:.3f}")

# The whole run against the fluid unknowns (rows only, not the demo): least squares on log-log.
import math
pts = [(med[n]["unknowns"], med[n]) for n in names if n != "demo"]
if len({u for u, _ in pts}) >= 2:
    def fit(key, per_iteration=False):
        xs = [math.log(u) for u, _ in pts]
        ys = [math.log(m[key] / (m["iterations"] if per_iteration else 1)) for _, m in pts]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    print(f"\nagainst fluid unknowns ({len(pts)} rows): wall ∝ n^{fit('wall'):.2f}, "
          f"timing_s.total per iteration ∝ n^{fit('total', True):.2f}, "
          f"fluid per iteration ∝ n^{fit('fluid', True):.2f}, peak memory ∝ n^{fit('peak'):.2f}")
PY
