#!/usr/bin/env bash
# Wall time per time step of fsicontact against FreeFem++ on the DFG benchmark 2D-2
# (vortex shedding at Re = 100; issue 30, "Speed"): the same algorithm step for step,
# mini element, BDF2 (BDF1 first), Newton's method in every step to 1e-10, from rest,
# at about 8 800 triangles and dt = 0.005. FreeFem++ runs bench/freefem/dfg_2d2.edp
# (-n 58: 8 840 triangles, UMFPACK), fsicontact cases/dfg-2d2.toml with fluid.h = 0.025,
# fluid.h_near = 0.0075 (8 914 triangles, MUMPS), each STEPS steps, interleaved
# (F, f, F, f, ...) REPS times, under /usr/bin/time (wall s, peak RSS kB). Prints a
# markdown table: wall time per step (the whole process over STEPS: meshing and the
# first analysis included), Newton steps per time step, peak memory, and the ratio.
#
#   bench/compare_freefem_dfg2d2.sh [--reps 3] [--steps 10] [--out DIR]
#
# Environment: FSICONTACT (default build/app/fsicontact), FREEFEM (default FreeFem++).
# Needs freefem++ (scripts/install-deps.sh --with-freefem). Run nothing else meanwhile.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${FSICONTACT:-build/app/fsicontact}
FREEFEM=${FREEFEM:-FreeFem++}
REPS=3 STEPS=10 OUT=out/compare-freefem-dfg2d2
while [[ $# -gt 0 ]]; do
  case "$1" in
    --reps) REPS=$2; shift 2 ;;
    --steps) STEPS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "usage: $0 [--reps 3] [--steps 10] [--out DIR]" >&2; exit 2 ;;
  esac
done
command -v "$FREEFEM" > /dev/null || { echo "$0: FreeFem++ is not installed" >&2; exit 2; }
mkdir -p "$OUT"
csv=$OUT/compare_dfg2d2.csv
echo "tool,rep,wall_s,rss_kb,triangles,newton_steps" > "$csv"
t_end=$(python3 -c "print($STEPS * 0.005)")
for rep in $(seq 1 "$REPS"); do
  /usr/bin/time -f '%e %M' -o "$OUT/ff.time" "$FREEFEM" -nw -v 0 bench/freefem/dfg_2d2.edp -n 58 -dt 0.005 \
    -steps "$STEPS" > "$OUT/ff.out" 2>&1
  read -r wall rss < "$OUT/ff.time"
  tri=$(grep -o 'triangles=[0-9]*' "$OUT/ff.out" | cut -d= -f2)
  newton=$(grep -o 'newton_steps=[0-9]*' "$OUT/ff.out" | cut -d= -f2)
  echo "freefem,$rep,$wall,$rss,$tri,$newton" >> "$csv"
  /usr/bin/time -f '%e %M' -o "$OUT/fc.time" "$BIN" run cases/dfg-2d2.toml --set fluid.h=0.025 --set fluid.h_near=0.0075 \
    --set time.dt=0.005 --set "time.t_end=$t_end" --set output.png=false --set output.vtu=false -q --out "$OUT/fsicontact" \
    > /dev/null
  read -r wall rss < "$OUT/fc.time"
  read -r tri newton < <(python3 -c "
import json; s = json.load(open('$OUT/fsicontact/summary.json'))
print(s['mesh']['fluid']['triangles'], s['fluid']['newton']['steps'])")
  echo "fsicontact,$rep,$wall,$rss,$tri,$newton" >> "$csv"
done
python3 - "$csv" "$STEPS" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
steps = int(sys.argv[2])
med = {}
print("| tool | triangles | wall per step (median of %d) | Newton steps per step | peak memory |" % (len(rows) // 2))
print("|---|---|---|---|---|")
for tool in ("freefem", "fsicontact"):
    r = [x for x in rows if x["tool"] == tool]
    wall = statistics.median(float(x["wall_s"]) for x in r) / steps
    med[tool] = wall
    print("| %s | %s | %.3f s | %.1f | %.0f MB |" % (tool, r[0]["triangles"], wall, float(r[0]["newton_steps"]) / steps,
                                                    statistics.median(float(x["rss_kb"]) for x in r) / 1024))
print("\nFreeFem++ / fsicontact, wall per step: %.1fx" % (med["freefem"] / med["fsicontact"]))
PY
