#!/usr/bin/env bash
# Runs the paper's Table 1 rows end to end, one process per row, and prints per row:
# iterations, wall time, peak memory (/usr/bin/time -v) and time per phase from
# summary.json. Usage:
#   bench/table1.sh [--rows 1,2,9] [--set section.key=value ...] [--out DIR]
# e.g. bench/table1.sh --set coupling.scheme=aitken
# Each row is a separate process so its peak memory is its own; `fsicontact sweep`
# (one process, meshes and set-ups shared) is the faster way to run them all.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${FSICONTACT:-build/app/fsicontact}
ROWS="" OUT=out/bench-table1 SETS=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rows) ROWS=$2; shift 2 ;;
    --set) SETS+=(--set "$2"); shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "usage: $0 [--rows 1,2,...] [--set key=value]... [--out DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $BIN ]] || { echo "table1.sh: build first (make build); no $BIN" >&2; exit 2; }
command -v /usr/bin/time > /dev/null || { echo "table1.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
mkdir -p "$OUT"
printf "%4s %7s %6s %7s %7s %5s %4s %9s %8s %8s %8s %8s %8s %8s\n" row eps omega hF hS k paper wall_s peak_MB mesh_s fluid_s struct_s xfer_s status
total=0
n=0
tail -n +2 <(grep -v '^#' cases/table1.csv) | while IFS=, read -r eps omega hF hS pk pinc pv pve; do
  n=$((n + 1))
  if [[ -n $ROWS ]] && [[ ",$ROWS," != *",$n,"* ]]; then continue; fi
  dir="$OUT/row-$(printf %02d "$n")"
  set +e
  /usr/bin/time -v -o "$dir.time" "$BIN" run cases/paper-7.2.toml -q \
    --set coupling.eps="$eps" --set coupling.omega="$omega" --set fluid.h="$hF" --set structure.h="$hS" \
    --set output.png=false --set output.vtu=false "${SETS[@]}" --out "$dir" > /dev/null 2> "$dir.err"
  status=$?
  set -e
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {split($2, t, ":"); s = t[length(t)]; m = (length(t) > 1) ? t[length(t) - 1] : 0; h = (length(t) > 2) ? t[1] : 0; print h * 3600 + m * 60 + s}' "$dir.time")
  peak=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$dir.time")
  python3 - "$dir/summary.json" "$n" "$eps" "$omega" "$hF" "$hS" "$pk" "$wall" "$peak" "$status" <<'PY'
import json, sys
path, n, eps, omega, hF, hS, pk, wall, peak, status = sys.argv[1:]
try:
    j = json.load(open(path)); t = j["timing_s"]
    k = j["iterations"] - 1
    print(f"{n:>4} {eps:>7} {omega:>6} {hF:>7} {hS:>7} {k:>5} {pk:>4} {float(wall):9.2f} {peak:>8} "
          f"{t['mesh']:8.3f} {t['fluid']:8.3f} {t['structure']:8.3f} {t['transfer']:8.3f} {j.get('status', status):>8}")
except (OSError, KeyError, ValueError):
    print(f"{n:>4} {eps:>7} {omega:>6} {hF:>7} {hS:>7} {'-':>5} {pk:>4} {float(wall):9.2f} {peak:>8} exit status {status}")
PY
done
