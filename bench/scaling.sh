#!/usr/bin/env bash
# A whole coupled run against the fluid mesh size: Table 1 row 2 (eps 1e-5, omega 0.1,
# hS 0.015) at each hF, at most N fixed-point iterations (a run that reaches the limit
# exits with status 3: a result), one process per size under /usr/bin/time -v (no PNG,
# no VTU). Records per size: fluid unknowns and triangles, iterations, wall time, peak
# memory, mesh time, time per iteration = (timing_s.total - timing_s.mesh -
# fluid.far_factorization_s if present) / iterations, and fluid time per iteration =
# timing_s.fluid / iterations. Writes DIR/scaling.csv, DIR/scaling.md with the
# least-squares exponents (log time per iteration and log peak memory against log
# unknowns), and DIR/scaling.png (drawn by build/bench/scaling_plot).
#   bench/scaling.sh [--sizes "0.02 0.01 0.005 0.0025 0.00125"] [--iterations N] [--out DIR]
#                    [--set section.key=value]... [--bin PATH] [--plot-bin PATH] [--report-only]
#   --sizes        hF values, run coarse to fine (default the five above)
#   --iterations   coupling.max_iterations (default 10: the finest runs stay bounded)
#   --out          output directory (default out/bench-scaling); DIR/h<hF> per run
#   --set          extra override for every run (repeatable)
#   --bin          the program (default $FSICONTACT or build/app/fsicontact)
#   --plot-bin     the plotter (default build/bench/scaling_plot)
#   --report-only  rebuild the CSV, tables and PNG from the runs already in DIR
# Before each size, its peak memory is estimated and compared with MemAvailable
# (/proc/meminfo); a size that would not fit is skipped, with the finer ones. Estimate:
# unknowns ~ previous size's x (h_prev / h)^2 (first size: 1.42 / hF^2); memory extrapolated
# linearly in the unknowns through the two previous sizes (one previous: the same MB per
# unknown; none: 3 KB per unknown), plus 25 %.
set -euo pipefail
HERE=$PWD
cd "$(dirname "$0")/.."
abspath() { case $1 in /*) echo "$1" ;; *) echo "$HERE/$1" ;; esac; }
BIN=${FSICONTACT:-build/app/fsicontact}
PLOT=build/bench/scaling_plot
SIZES="0.02 0.01 0.005 0.0025 0.00125" ITERATIONS=10 OUT=out/bench-scaling REPORT_ONLY=0 SETS=()
usage() {
  echo "usage: $0 [--sizes \"h1 h2 ...\"] [--iterations N] [--out DIR] [--set key=value]... [--bin PATH]" \
       "[--plot-bin PATH] [--report-only]" >&2
  exit 2
}
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sizes) [[ $# -ge 2 ]] || usage; SIZES=$2; shift 2 ;;
    --iterations) [[ $# -ge 2 ]] || usage; ITERATIONS=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; OUT=$(abspath "$2"); shift 2 ;;
    --set) [[ $# -ge 2 && $2 == *=* ]] || usage; SETS+=(--set "$2"); shift 2 ;;
    --bin) [[ $# -ge 2 ]] || usage; BIN=$(abspath "$2"); shift 2 ;;
    --plot-bin) [[ $# -ge 2 ]] || usage; PLOT=$(abspath "$2"); shift 2 ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) usage ;;
  esac
done
[[ $ITERATIONS =~ ^[1-9][0-9]*$ ]] || { echo "scaling.sh: --iterations needs a positive integer" >&2; usage; }
# Coarse to fine, whatever order was given: each size's memory estimate uses the previous.
SIZES=$(for h in $SIZES; do
  [[ $h =~ ^[0-9]*\.?[0-9]+([eE]-?[0-9]+)?$ ]] && awk -v h="$h" 'BEGIN { exit !(h > 0) }' || {
    echo "scaling.sh: bad size '$h'" >&2; exit 1; }
  echo "$h"
done | sort -g -r -u | tr '\n' ' ') || usage
[[ -n ${SIZES// /} ]] || usage

[[ -x $PLOT ]] || { echo "scaling.sh: no plotter at $PLOT: build first (make build), or --plot-bin" >&2; exit 2; }
command -v python3 > /dev/null || { echo "scaling.sh: needs python3" >&2; exit 2; }
mkdir -p "$OUT"

peak_kb() { awk -F': ' '/Maximum resident set size/ { print $2 }' "$1"; }
unknowns_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["fluid"]["unknowns"])' "$1"; }

if [[ $REPORT_ONLY -eq 0 ]]; then
  [[ -x $BIN ]] || { echo "scaling.sh: no fsicontact binary at $BIN: build first (make build), or --bin" >&2; exit 2; }
  [[ -x /usr/bin/time ]] || { echo "scaling.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
  rm -f "$OUT"/h*.skipped
  prev_h="" prev_n="" prev_mb="" prev2_n="" prev2_mb="" skip=""
  for h in $SIZES; do
    dir="$OUT/h$h"
    # Memory check: estimated unknowns, memory linear in the unknowns through the previous sizes.
    est_unknowns=$(awk -v h="$h" -v ph="$prev_h" -v pn="$prev_n" \
      'BEGIN { printf "%.0f", (pn != "") ? pn * (ph / h) ^ 2 : 1.42 / h ^ 2 }')
    need_mb=$(awk -v n="$est_unknowns" -v n1="$prev_n" -v m1="$prev_mb" -v n2="$prev2_n" -v m2="$prev2_mb" 'BEGIN {
      if (n2 != "" && n1 > n2 && m1 > m2) m = m1 + (m1 - m2) / (n1 - n2) * (n - n1)
      else if (n1 != "") m = m1 * n / n1
      else m = 3 * n / 1024
      printf "%.0f", 1.25 * m }')
    avail_mb=$(awk '/^MemAvailable:/ { printf "%.0f", $2 / 1024 }' /proc/meminfo)
    if [[ -z $skip ]] && ((need_mb > avail_mb)); then
      skip="estimated peak $need_mb MB (~$est_unknowns unknowns, +25 %) > MemAvailable $avail_mb MB"
    fi
    if [[ -n $skip ]]; then
      echo "hF=$h: skipped: $skip" >&2
      echo "$skip" > "$dir.skipped"
      continue
    fi
    echo "hF=$h: ~$est_unknowns unknowns, estimated peak $need_mb MB (MemAvailable $avail_mb MB)" >&2
    rm -rf "$dir"
    set +e
    /usr/bin/time -v -o "$dir.time" "$BIN" run cases/paper-7.2.toml -q --set coupling.eps=1e-5 \
      --set coupling.omega=0.1 --set structure.h=0.015 --set fluid.h="$h" \
      --set coupling.max_iterations="$ITERATIONS" --set output.png=false --set output.vtu=false \
      ${SETS[@]+"${SETS[@]}"} --out "$dir" > "$dir.log" 2> "$dir.err"
    status=$?
    set -e
    echo "$status" > "$dir.exit"
    echo "  exit $status ($(grep -o 'Elapsed.*' "$dir.time" | sed 's/.*: //') wall, $(($(peak_kb "$dir.time") / 1024)) MB)" >&2
    if [[ -f $dir/summary.json ]]; then
      prev2_n=$prev_n prev2_mb=$prev_mb prev_h=$h prev_n=$(unknowns_of "$dir/summary.json")
      prev_mb=$(($(peak_kb "$dir.time") / 1024))
    fi
  done
fi

python3 - "$OUT" "$SIZES" <<'PY'
import csv, json, math, os, re, sys
out, sizes = sys.argv[1], sys.argv[2].split()

def time_v(path):
    """wall seconds and peak RSS (MB) from /usr/bin/time -v."""
    text = open(path).read()
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024
    clock = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1).split(":")
    return sum(float(x) * 60 ** i for i, x in enumerate(reversed(clock))), peak

records, notes = [], []
for h in sizes:
    base = os.path.join(out, f"h{h}")
    if os.path.exists(base + ".skipped"):
        notes.append(f"hF = {h}: skipped, {open(base + '.skipped').read().strip()}")
        continue
    try:
        j = json.load(open(os.path.join(base, "summary.json")))
        wall, peak = time_v(base + ".time")
        status = int(open(base + ".exit").read())
    except (OSError, ValueError, AttributeError):
        notes.append(f"hF = {h}: no result (see {base}.err)")
        continue
    t, f, it = j["timing_s"], j["fluid"], j["iterations"]
    far = f.get("far_factorization_s")
    records.append({
        "hF": h, "unknowns": f["unknowns"], "fluid_triangles": j["mesh"]["fluid"]["triangles"],
        "structure_triangles": j["mesh"]["structure"]["triangles"], "iterations": it, "status": j["status"],
        "exit": status, "wall_s": wall, "peak_MB": peak, "total_s": t["total"], "mesh_s": t["mesh"],
        "fluid_s": t["fluid"], "far_factorization_s": "" if far is None else far,
        "time_per_iteration_s": (t["total"] - t["mesh"] - (far or 0)) / it,
        "fluid_per_iteration_s": t["fluid"] / it})

if not records:
    sys.exit("scaling.sh: no run to report in " + out)
with open(os.path.join(out, "scaling.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(records[0]))
    w.writeheader()
    w.writerows(records)

def slope(key):  # least squares, log(key) against log(unknowns)
    pts = [(math.log(r["unknowns"]), math.log(r[key])) for r in records if r[key] > 0]
    if len({x for x, _ in pts}) < 2:
        return None
    mx, my = sum(x for x, _ in pts) / len(pts), sum(y for _, y in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)

md = ["Whole coupled run against the fluid mesh: Table 1 row 2 (eps 1e-5, omega 0.1, hS 0.015), "
      f"at most {max(r['iterations'] for r in records)} iterations seen (bench/scaling.sh)\n",
      "| hF | fluid unknowns | fluid triangles | iterations | status | wall s | peak MB | mesh s "
      "| far-field set-up s | time per iteration s | fluid per iteration s |", "|" + "---|" * 11]
for r in records:
    far = "-" if r["far_factorization_s"] == "" else f"{r['far_factorization_s']:.3f}"
    md.append(f"| {r['hF']} | {r['unknowns']} | {r['fluid_triangles']} | {r['iterations']} | {r['status']} "
              f"| {r['wall_s']:.2f} | {r['peak_MB']:.0f} | {r['mesh_s']:.3f} | {far} "
              f"| {r['time_per_iteration_s']:.4f} | {r['fluid_per_iteration_s']:.4f} |")
fits = {k: slope(k) for k in ("time_per_iteration_s", "fluid_per_iteration_s", "peak_MB", "wall_s")}
def e(k):
    return "? (needs 2 sizes)" if fits[k] is None else f"{fits[k]:.2f}"
summary = (f"Least-squares exponents against fluid unknowns N ({len(records)} sizes): "
           f"time per iteration ∝ N^{e('time_per_iteration_s')}, fluid time per iteration ∝ N^{e('fluid_per_iteration_s')}, "
           f"peak memory ∝ N^{e('peak_MB')}, wall time ∝ N^{e('wall_s')}.")
md += ["", summary, "", "time per iteration = (timing_s.total − timing_s.mesh − fluid.far_factorization_s) / iterations; "
       "fluid per iteration = timing_s.fluid / iterations; status \"iteration limit\" (exit 3) is expected with a "
       "small coupling.max_iterations. scaling.png: bench/scaling_plot."] + [f"- {n}" for n in notes]
text = "\n".join(md) + "\n"
print(text, end="")
open(os.path.join(out, "scaling.md"), "w").write(text)
PY

if (($(wc -l < "$OUT/scaling.csv") >= 3)); then
  "$PLOT" "$OUT/scaling.csv" "$OUT/scaling.png"
  echo "(written $OUT/scaling.csv, scaling.md, scaling.png)" >&2
else
  rm -f "$OUT/scaling.png"
  echo "(written $OUT/scaling.csv, scaling.md; no scaling.png: a fit and a plot need 2 sizes)" >&2
fi
