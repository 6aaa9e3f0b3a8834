#!/usr/bin/env bash
# Runs rows of the paper's Table 1 (cases/table1.csv: each section.key column is a --set
# override of cases/paper-7.2.toml, paper.* columns are the paper's values) end to end,
# one process per run (no PNG, no VTU), each under /usr/bin/time -v, and prints a
# markdown table per row: eps, omega, hF, hS, k (ours and the paper's), converged, wall
# time, peak memory, and the phases of summary.json (timing_s, fluid.*), then a total
# line. Writes DIR/table1.md and DIR/table1.csv.
#   bench/table1.sh [--rows 1,2,9] [--scheme constant|aitken|iqn-ils] [--repeats N]
#                   [--out DIR] [--set section.key=value]... [--bin PATH]
#   --rows     1-based rows of cases/table1.csv (default all)
#   --scheme   coupling.scheme (default constant, the paper's)
#   --repeats  N runs per row, interleaved (row a, row b, ..., again); the table gives
#              medians (wall time, memory, phases) and the wall time's min-max
#   --out      output directory (default out/bench-table1); one DIR/row-NN-rR per run
#   --set      extra override for every run, after the row's (repeatable)
#   --bin      the program (default $FSICONTACT or build/app/fsicontact)
# A row that reaches the iteration limit (exit status 3) is a result, not a failure; any
# other non-zero exit is shown in the table and makes the script exit 1 at the end.
# `fsicontact sweep` (one process for all rows) is the faster way to get only the k's.
set -euo pipefail
HERE=$PWD
cd "$(dirname "$0")/.."
abspath() { case $1 in /*) echo "$1" ;; *) echo "$HERE/$1" ;; esac; }
BIN=${FSICONTACT:-build/app/fsicontact}
ROWS="" SCHEME=constant REPEATS=1 OUT=out/bench-table1 SETS=()
usage() {
  echo "usage: $0 [--rows 1,2,...] [--scheme constant|aitken|iqn-ils] [--repeats N] [--out DIR]" \
       "[--set key=value]... [--bin PATH]" >&2
  exit 2
}
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rows) [[ $# -ge 2 ]] || usage; ROWS=$2; shift 2 ;;
    --scheme) [[ $# -ge 2 ]] || usage; SCHEME=$2; shift 2 ;;
    --repeats) [[ $# -ge 2 ]] || usage; REPEATS=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; OUT=$(abspath "$2"); shift 2 ;;
    --set) [[ $# -ge 2 && $2 == *=* ]] || usage; SETS+=(--set "$2"); shift 2 ;;
    --bin) [[ $# -ge 2 ]] || usage; BIN=$(abspath "$2"); shift 2 ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) usage ;;
  esac
done
case $SCHEME in constant|aitken|iqn-ils) ;; *) echo "table1.sh: unknown scheme '$SCHEME'" >&2; usage ;; esac
[[ $REPEATS =~ ^[1-9][0-9]*$ ]] || { echo "table1.sh: --repeats needs a positive integer" >&2; usage; }

# The rows: a header of section.key / paper.* columns, then one line per row.
mapfile -t lines < <(grep -v -e '^#' -e '^[[:space:]]*$' cases/table1.csv)
IFS=, read -ra header <<< "${lines[0]}"
nrows=$((${#lines[@]} - 1))
[[ -n $ROWS ]] || ROWS=$(seq -s, 1 "$nrows")
for n in ${ROWS//,/ }; do
  [[ $n =~ ^[0-9]+$ ]] && ((n >= 1 && n <= nrows)) || { echo "table1.sh: no row '$n' (1..$nrows)" >&2; usage; }
done

[[ -x $BIN ]] || { echo "table1.sh: no fsicontact binary at $BIN: build first (make build), or --bin" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "table1.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
command -v python3 > /dev/null || { echo "table1.sh: needs python3" >&2; exit 2; }
mkdir -p "$OUT"

for r in $(seq 1 "$REPEATS"); do
  for n in ${ROWS//,/ }; do
    IFS=, read -ra vals <<< "${lines[$n]}"
    row_sets=()
    for i in "${!header[@]}"; do
      [[ ${header[$i]} == paper.* ]] || row_sets+=(--set "${header[$i]}=${vals[$i]}")
    done
    dir="$OUT/row-$(printf %02d "$n")-r$r"
    rm -rf "$dir"
    set +e
    /usr/bin/time -v -o "$dir.time" "$BIN" run cases/paper-7.2.toml -q "${row_sets[@]}" \
      --set coupling.scheme="$SCHEME" --set output.png=false --set output.vtu=false ${SETS[@]+"${SETS[@]}"} \
      --out "$dir" > "$dir.log" 2> "$dir.err"
    status=$?
    set -e
    echo "$status" > "$dir.exit"
    echo "row $n repeat $r/$REPEATS: exit $status ($(grep -o 'Elapsed.*' "$dir.time" | sed 's/.*: //') wall)" >&2
  done
done

python3 - "$OUT" "$ROWS" "$REPEATS" "$SCHEME" cases/table1.csv <<'PY'
import csv, json, os, re, statistics, sys
out, rows, repeats, scheme, table = sys.argv[1], [int(n) for n in sys.argv[2].split(",")], int(sys.argv[3]), sys.argv[4], sys.argv[5]
paper = list(csv.DictReader(l for l in open(table) if l.strip() and not l.startswith("#")))

def time_v(path):
    """wall seconds and peak RSS (MB) from /usr/bin/time -v."""
    text = open(path).read()
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024
    clock = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1).split(":")
    return sum(float(x) * 60 ** i for i, x in enumerate(reversed(clock))), peak

PHASES = [("mesh", "timing_s", "mesh"), ("fluid", "timing_s", "fluid"), ("structure", "timing_s", "structure"),
          ("transfer", "timing_s", "transfer"), ("chi", "timing_s", "chi"), ("output", "timing_s", "output"),
          ("factorization", "fluid", "factorization_s"), ("solve", "fluid", "solve_s"),
          ("assembly", "fluid", "assembly_s"), ("far_factorization", "fluid", "far_factorization_s"),
          ("expansion", "fluid", "expansion_s"), ("far_factorizations", "fluid", "far_field_factorizations")]

def one(base):
    r = {"exit": int(open(base + ".exit").read())}
    try:
        r["wall"], r["peak"] = time_v(base + ".time")
    except (OSError, AttributeError):
        pass
    try:
        j = json.load(open(os.path.join(base, "summary.json")))
    except (OSError, ValueError):
        return r
    p = j["parameters"]  # the values the run used, --set included
    r.update(eps=p["coupling"]["eps"], omega=p["coupling"]["omega"], hF=p["fluid"]["h"], hS=p["structure"]["h"],
             k=j.get("paper_k", j["iterations"] - 1), status=j["status"], warning="convergence_warning" in j)
    for name, section, key in PHASES:
        if key in j.get(section, {}):
            r[name] = j[section][key]
    return r

records = []
for n in rows:
    reps = [one(os.path.join(out, f"row-{n:02d}-r{r}")) for r in range(1, repeats + 1)]
    ok = [x for x in reps if "status" in x]
    rec = {"row": n, "paper_k": paper[n - 1].get("paper.k", ""), "runs": len(ok),
           "exits": sorted({x["exit"] for x in reps})}
    for key in ("eps", "omega", "hF", "hS"):
        rec[key] = ok[0][key] if ok else paper[n - 1].get({"eps": "coupling.eps", "omega": "coupling.omega",
                                                            "hF": "fluid.h", "hS": "structure.h"}[key], "")
    rec["k"] = ",".join(sorted({str(x["k"]) for x in ok})) if ok else None
    rec["status"] = ",".join(sorted({x["status"] + ("†" if x["warning"] else "") for x in ok})) if ok else None
    for key in ["wall", "peak"] + [p[0] for p in PHASES]:
        vals = [x[key] for x in reps if key in x]
        rec[key] = statistics.median(vals) if vals else None
    walls = [x["wall"] for x in reps if "wall" in x]
    rec["wall_min"], rec["wall_max"] = (min(walls), max(walls)) if walls else (None, None)
    records.append(rec)

def g(x, fmt="{:.3f}"):
    return "-" if x is None else fmt.format(x)
def converged(r):
    if r["status"] is None:
        return f"exit {','.join(map(str, r['exits']))}, no summary.json"
    s = {"converged": "yes"}.get(r["status"], r["status"]).replace("converged†", "yes†")
    bad = [e for e in r["exits"] if e not in (0, 3)]
    return s + (f" (exit {','.join(map(str, bad))})" if bad else "")
def wall(r):
    if repeats == 1 or r["wall"] is None:
        return g(r["wall"], "{:.2f}")
    return f"{r['wall']:.2f} ({r['wall_min']:.2f}–{r['wall_max']:.2f})"

cols = ["row", "ε", "ω", "hF", "hS", "k ours", "k paper", "converged", "wall s" + (", min–max" if repeats > 1 else ""),
        "peak MB", "mesh s", "fluid s", "structure s", "transfer s", "χ s", "output s", "factorization s",
        "solve s", "assembly s", "far factorization s", "expansion s", "far factorizations"]
md = [f"Table 1 rows, coupling.scheme = {scheme}, " + (f"medians of {repeats} runs" if repeats > 1 else "one run per row")
      + " (bench/table1.sh)\n", "| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
for r in records:
    phases = [g(r[p[0]], "{:.0f}" if p[0] == "far_factorizations" else "{:.3f}") for p in PHASES]
    md.append(f"| {r['row']} | {r['eps']:g} | {r['omega']:g} | {r['hF']:g} | {r['hS']:g} | {r['k'] or '-'} | {r['paper_k']} "
              f"| {converged(r)} | {wall(r)} | {g(r['peak'], '{:.0f}')} | " + " | ".join(phases) + " |")
def total(key):
    vals = [r[key] for r in records if r[key] is not None]
    return sum(vals) if vals else None
md.append(f"| **total** | | | | | | | | **{g(total('wall'), '{:.2f}')}** | | "
          + " | ".join(g(total(p[0]), "{:.0f}" if p[0] == "far_factorizations" else "{:.3f}") for p in PHASES) + " |")
md.append("\nk = iterations − 1 (the paper's counter). converged: yes, or summary.json's status (\"iteration limit\": "
          "exit status 3, max_iterations reached); † = stopped below tol but flagged as a chance dip "
          "(convergence_warning). Wall time and peak memory (max RSS) from /usr/bin/time -v, phases from "
          "summary.json (timing_s, and fluid.*_s); \"-\": a key this build does not write. Total: sums over the rows.")
text = "\n".join(md) + "\n"
print(text, end="")
open(os.path.join(out, "table1.md"), "w").write(text)

fields = ["row", "eps", "omega", "hF", "hS", "k", "paper_k", "status", "exits", "runs", "wall", "wall_min", "wall_max",
          "peak"] + [p[0] for p in PHASES]
with open(os.path.join(out, "table1.csv"), "w", newline="") as fh:
    w = csv.writer(fh)
    w.writerow([{"wall": "wall_s", "wall_min": "wall_min_s", "wall_max": "wall_max_s", "peak": "peak_MB"}.get(f, f)
                + ("_s" if f in [p[0] for p in PHASES[:-1]] else "") for f in fields])
    for r in records:
        w.writerow(["" if r[f] is None else ";".join(map(str, r[f])) if isinstance(r[f], list) else r[f] for f in fields])
print(f"(written {out}/table1.md, {out}/table1.csv)", file=sys.stderr)
sys.exit(1 if any(e not in (0, 3) for r in records for e in r["exits"]) else 0)
PY
