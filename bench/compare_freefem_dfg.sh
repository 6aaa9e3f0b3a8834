#!/usr/bin/env bash
# Speed and memory of fsicontact against FreeFem++ on the DFG benchmark 2D-1 (steady flow
# past a cylinder at Re = 20, Schäfer & Turek 1996; issue 29, "Speed"). For each
# mesh size (and mesher) it runs FreeFem++ on bench/freefem/dfg_2d1.edp (P1b/P1, Newton from rest,
# UMFPACK) and fsicontact on cases/dfg-2d1.toml, interleaved (F, f, F, f, ...), REPS times
# each, every run under /usr/bin/time -f '%e %M' (wall s, peak RSS kB), and prints a
# markdown table: triangles, median wall time, median peak memory, C_D, C_L, Δp of each tool
# and FreeFem++ / fsicontact ratios. Also writes DIR/compare_dfg.csv (every run).
#
#   bench/compare_freefem_dfg.sh [--reps 3] [--out DIR] [--sizes N:H[:MESHER],...] [--report-only]
#
#   --reps         runs of each tool at each size (default 3)
#   --out          output directory (default out/compare-freefem-dfg)
#   --sizes        pairs of FreeFem++ -n and fsicontact fluid.h giving the same number of
#                  triangles within ~1 %, each optionally with fsicontact's fluid.mesher as
#                  a third field (N:H:lattice; default the case's gmsh). Default
#                  100:0.0135,100:0.0128:lattice,202:0.0065,202:0.0061:lattice: FreeFem++
#                  25 918 and 104 978 triangles; fsicontact 25 760 and 105 544 (gmsh),
#                  26 099 and 106 267 (lattice)
#   --report-only  rebuild the table from the outputs already in DIR, run nothing
#
# fsicontact is run as
#   $FSICONTACT run cases/dfg-2d1.toml --set fluid.h=H --set fluid.h_near=H/4 --set fluid.mesher=MESHER --out DIR \
#       --set output.png=false --set output.vtu=false
# fluid.h_near (the band box around the cylinder and its wake; 0.005 in the case, with
# h = 0.02) follows h at the case's ratio 1/4, as FreeFem++'s cylinder (-cyl 4): h_near
# may not exceed h, so the case's 0.005 is refused below h = 0.005.
# C_D = 500 F_x, C_L = 500 F_y with (F_x, F_y) = summary.json's obstacles[0].force;
# Delta p = fluid_at[0].p - fluid_at[1].p (the case's output.fluid_probes).
#
# Environment: FSICONTACT (default build/fsicontact, else build/app/fsicontact),
# FREEFEM (default FreeFem++). Needs freefem++ and libfreefem++
# (scripts/install-deps.sh --with-freefem), time, python3. Run nothing else meanwhile:
# wall times are compared (both tools run on one core: serial UMFPACK / MUMPS, serial BLAS).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
if [[ -n ${FSICONTACT:-} ]]; then BIN=$FSICONTACT
elif [[ -x build/fsicontact ]]; then BIN=build/fsicontact
else BIN=build/app/fsicontact; fi
FREEFEM=${FREEFEM:-FreeFem++}
REPS=3 OUT=out/compare-freefem-dfg SIZES=100:0.0135,100:0.0128:lattice,202:0.0065,202:0.0061:lattice REPORT_ONLY=0
usage() { echo "usage: $0 [--reps 3] [--out DIR] [--sizes N:H,N:H] [--report-only]" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --reps) [[ $# -ge 2 ]] || usage; REPS=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; OUT=$2; shift 2 ;;
    --sizes) [[ $# -ge 2 ]] || usage; SIZES=$2; shift 2 ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h|--help) sed -n '2,/^[^#]/p' "$0" | sed '$d'; exit 0 ;;
    *) usage ;;
  esac
done
[[ $REPS =~ ^[1-9][0-9]*$ ]] || usage
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

if [[ $REPORT_ONLY -eq 0 ]]; then
  if ! command -v "$FREEFEM" > /dev/null; then
    echo "compare_freefem_dfg.sh: FreeFem++ is not installed ($FREEFEM not found)." >&2
    echo "  Install it with: scripts/install-deps.sh --with-freefem   (Debian packages freefem++ libfreefem++)" >&2
    exit 2
  fi
  [[ -x $BIN ]] || { echo "compare_freefem_dfg.sh: no fsicontact binary at $BIN: build first (make build) or set FSICONTACT" >&2; exit 2; }
  [[ -x /usr/bin/time ]] || { echo "compare_freefem_dfg.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
  command -v python3 > /dev/null || { echo "compare_freefem_dfg.sh: needs python3" >&2; exit 2; }
  BIN=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")
  EDP=$ROOT/bench/freefem/dfg_2d1.edp
  rm -f "$OUT"/*.time "$OUT"/*.log
  IFS=, read -r -a pairs <<< "$SIZES"
  for pair in "${pairs[@]}"; do
    IFS=: read -r n h mesher <<< "$pair"
    mesher=${mesher:-gmsh}
    hn=$(python3 -c "print(repr($h / 4))")
    for rep in $(seq 1 "$REPS"); do
      tag="n$n-h$h-$mesher-$rep"
      set +e
      (cd "$OUT" && /usr/bin/time -f '%e %M' -o "freefem-$tag.time" "$FREEFEM" -nw -v 0 "$EDP" -n "$n" \
        > "freefem-$tag.log" 2>&1)
      echo "FreeFem++ -n $n, run $rep: exit $?, $(cat "$OUT/freefem-$tag.time" | tail -1) (s kB); $(grep -h '^RESULT' "$OUT/freefem-$tag.log" | cut -c1-150)" >&2
      rm -rf "$OUT/fsicontact-$tag"
      /usr/bin/time -f '%e %M' -o "$OUT/fsicontact-$tag.time" "$BIN" run cases/dfg-2d1.toml \
        --set fluid.h="$h" --set fluid.h_near="$hn" --set fluid.mesher="$mesher" --out "$OUT/fsicontact-$tag" \
        --set output.png=false --set output.vtu=false > "$OUT/fsicontact-$tag.log" 2>&1
      echo "fsicontact h = $h ($mesher), run $rep: exit $?, $(cat "$OUT/fsicontact-$tag.time" | tail -1) (s kB); $(tail -c 300 "$OUT/fsicontact-$tag.log" | tr '\n' ' ' | cut -c1-150)" >&2
      set -e
    done
  done
fi

python3 - "$OUT" "$SIZES" <<'PY'
import csv, json, os, re, statistics, sys

out, sizes = sys.argv[1:]
REF_CD, REF_CL, REF_DP = 5.57953523384, 0.010618948146, 0.11752016697

def read_time(path):
    """(wall s, peak RSS MB) from the last line of /usr/bin/time -f '%e %M', or None."""
    try:
        last = open(path).read().split("\n")
        last = [l for l in last if l.strip()][-1].split()
        return float(last[0]), int(last[1]) / 1024
    except (OSError, IndexError, ValueError):
        return None

def read_freefem(path):
    res = {}
    try:
        for line in open(path):
            if line.startswith(("RESULT ", "TIMES ")):
                tag = line.split()[0].lower()
                for k, v in re.findall(r"(\w+)=(\S+)", line):
                    res[k if tag == "result" else "cpu_" + k] = float(v)
    except OSError:
        return None
    if "CD" not in res or res.get("converged") != 1:
        return None
    return {"triangles": int(res["triangles"]), "CD": res["CD"], "CL": res["CL"], "dp": res["dp"],
            "newton_steps": int(res["newton_steps"]), "internal_s": res.get("cpu_total"),
            "assembly_s": res.get("cpu_assembly"), "solve_s": res.get("cpu_factorization_and_solve")}

def read_fsicontact(d):
    try:
        j = json.load(open(os.path.join(d, "summary.json")))
        fx, fy = j["obstacles"][0]["force"]
        at = j.get("fluid_at") or []   # output.fluid_probes = [[0.15, 0.2], [0.25, 0.2]] (the case's)
        dp = at[0]["p"] - at[1]["p"] if len(at) >= 2 else None
        return {"triangles": j["mesh"]["fluid"]["triangles"], "CD": 500 * fx, "CL": 500 * fy, "dp": dp,
                "newton_steps": j.get("fluid", {}).get("newton", {}).get("steps"),
                "internal_s": j["timing_s"]["total"], "assembly_s": j.get("fluid", {}).get("assembly_s"),
                "solve_s": None}
    except (OSError, ValueError, KeyError, IndexError, TypeError):
        return None

rows, runs = [], []
for pair in sizes.split(","):
    n, h, *rest = pair.split(":")
    mesher = rest[0] if rest else "gmsh"
    row = {"n": n, "h": h, "mesher": mesher}
    for tool in ("freefem", "fsicontact"):
        walls, peaks, res = [], [], None
        rep = 1
        while True:
            tag = f"n{n}-h{h}-{mesher}-{rep}"
            t = read_time(os.path.join(out, f"{tool}-{tag}.time"))
            if t is None and not os.path.exists(os.path.join(out, f"{tool}-{tag}.time")):
                break
            r = read_freefem(os.path.join(out, f"{tool}-{tag}.log")) if tool == "freefem" \
                else read_fsicontact(os.path.join(out, f"{tool}-{tag}"))
            if t is not None and r is not None:
                walls.append(t[0]); peaks.append(t[1]); res = r
            runs.append({"tool": tool, "n": n, "h": h, "mesher": mesher, "rep": rep, "ok": t is not None and r is not None,
                         "wall_s": t[0] if t else "", "peak_MB": t[1] if t else "", **(r or {})})
            rep += 1
        row[tool] = None if res is None else {**res, "wall": statistics.median(walls),
                                              "peak": statistics.median(peaks), "runs": len(walls)}
    rows.append(row)

def g(x, fmt):
    return "-" if x is None else fmt.format(x)
def get(r, k):
    return None if r is None else r.get(k)
def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b

print("| fsicontact's mesher | triangles FreeFem++ / fsicontact | wall s FreeFem++ | wall s fsicontact | wall ratio "
      "| peak MB FreeFem++ | peak MB fsicontact | memory ratio | C_D FreeFem++ | C_D fsicontact "
      "| C_L FreeFem++ | C_L fsicontact | Δp FreeFem++ | Δp fsicontact | Newton steps FreeFem++ / fsicontact |")
print("|" + "---|" * 15)
for row in rows:
    F, f = row["freefem"], row["fsicontact"]
    print(f"| {row['mesher']} | {g(get(F, 'triangles'), '{}')} / {g(get(f, 'triangles'), '{}')} "
          f"| {g(get(F, 'wall'), '{:.2f}')} | {g(get(f, 'wall'), '{:.2f}')} "
          f"| {g(ratio(get(F, 'wall'), get(f, 'wall')), '{:.1f}×')} "
          f"| {g(get(F, 'peak'), '{:.0f}')} | {g(get(f, 'peak'), '{:.0f}')} "
          f"| {g(ratio(get(F, 'peak'), get(f, 'peak')), '{:.1f}×')} "
          f"| {g(get(F, 'CD'), '{:.5f}')} | {g(get(f, 'CD'), '{:.5f}')} "
          f"| {g(get(F, 'CL'), '{:.5f}')} | {g(get(f, 'CL'), '{:.5f}')} "
          f"| {g(get(F, 'dp'), '{:.5f}')} | {g(get(f, 'dp'), '{:.5f}')} "
          f"| {g(get(F, 'newton_steps'), '{}')} / {g(get(f, 'newton_steps'), '{}')} |")
print(f"| reference (Schäfer & Turek; John 2004) | | | | | | | | {REF_CD:.5f} | {REF_CD:.5f} "
      f"| {REF_CL:.5f} | {REF_CL:.5f} | {REF_DP:.5f} | {REF_DP:.5f} | |")
nr = {row[t]["runs"] for row in rows for t in ("freefem", "fsicontact") if row[t]}
sz = ", ".join(f"FreeFem++ -n {row['n']} / fsicontact fluid.h = {row['h']} ({row['mesher']})" for row in rows)
print(f"\nMedians of {'/'.join(str(x) for x in sorted(nr)) or 0} runs per tool and size, interleaved, "
      f"each a whole process under /usr/bin/time (wall clock; peak RSS); ratios are FreeFem++ / fsicontact. "
      f"Sizes: {sz} (h_near = h/4). C_D = 500 F_x, C_L = 500 F_y (fsicontact: summary.json's obstacles[0].force; "
      f"FreeFem++: the volume (residual) method); Δp = p(0.15, 0.2) − p(0.25, 0.2) (fsicontact: "
      f"fluid_at[0].p − fluid_at[1].p). FreeFem++: P1b/P1, Newton from rest "
      f"to a relative increment of 1e-10, UMFPACK; fsicontact: P1b/P1, Newton to a residual of 1e-10, MUMPS.")
print("FreeFem++ stops on the relative increment, which lags the residual by one step: its increment after "
      "step 6 is 1.04e-10 at -n 100, so it makes 7 solves where fsicontact's residual test stops after 5 "
      "(CPU time per step from the TIMES below: (assembly + factorisation and solve) / steps).")
for row in rows:
    F = row["freefem"]
    if F:
        print(f"FreeFem++ -n {row['n']}: CPU (clock()) "
              f"assembly {F['assembly_s']:.2f} s, factorisation and solve {F['solve_s']:.2f} s, "
              f"total {F['internal_s']:.2f} s.")

cols = ["tool", "n", "h", "mesher", "rep", "ok", "wall_s", "peak_MB", "triangles", "CD", "CL", "dp", "newton_steps",
        "internal_s", "assembly_s", "solve_s"]
with open(os.path.join(out, "compare_dfg.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=cols, extrasaction="ignore")
    w.writeheader()
    for r in runs:
        w.writerow({c: ("" if r.get(c) is None else r.get(c, "")) for c in cols})
print(f"\n(written {os.path.join(out, 'compare_dfg.csv')})", file=sys.stderr)
PY
