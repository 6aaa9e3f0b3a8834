#!/usr/bin/env bash
# Iterations per Table 1 row for each relaxation scheme and χ rule: runs
# `fsicontact sweep` for constant / aitken / iqn-ils with the barycentre χ (the paper's)
# and aitken / iqn-ils with the area-fraction χ, then prints one table (k = the paper's
# counter, iterations − 1; "-" = not converged within 100 iterations; "†" = stopped on
# a chance dip below tol of increments that never settled, see docs/validation.md).
#   bench/schemes.sh [--reuse]     (--reuse: only print, from existing out/table1-*)
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${FSICONTACT:-build/app/fsicontact}
configs=("constant barycentre" "aitken barycentre" "iqn-ils barycentre" "aitken area-fraction" "iqn-ils area-fraction")
for cfg in "${configs[@]}"; do
  read -r scheme chi <<< "$cfg"
  out="out/table1-$scheme-$chi"
  if [[ "${1:-}" != "--reuse" || ! -f $out/table.csv ]]; then
    "$BIN" sweep cases/paper-7.2.toml cases/table1.csv --set coupling.scheme="$scheme" \
      --set fluid.chi="$chi" --out "$out" -q > /dev/null
  fi
done
python3 - "${configs[@]}" <<'PY'
import csv, json, sys
configs = [c.split() for c in sys.argv[1:]]
tables = [list(csv.DictReader(open(f"out/table1-{s}-{c}/table.csv"))) for s, c in configs]
def k(r):  # "-": not converged; "†": stopped on a chance dip below tol (unsettled)
    if r["status"] == "converged": return r["k"].split(".")[0]
    if r["status"].startswith("converged, unsettled"): return r["k"].split(".")[0] + " †"
    return "-"
head = ["row", "eps", "omega", "hF", "hS", "paper k"] + [f"{s} ({'bary' if c == 'barycentre' else 'area'})" for s, c in configs]
print("| " + " | ".join(head) + " |")
print("|" + "---|" * len(head))
for i, r in enumerate(tables[0]):
    cells = [r["row"], r["eps"], r["omega"], r["hF"], r["hS"], r["paper_k"]] + [k(t[i]) for t in tables]
    print("| " + " | ".join(cells) + " |")
for (s, c), t in zip(configs, tables):
    ks = [int(r["k"].split(".")[0]) for r in t if r["status"] == "converged"]
    wall = sum(float(r["wall_s"]) for r in t)
    print(f"\n{s}, {c}: {len(ks)}/{len(t)} rows converged, k at most {max(ks)}, mean {sum(ks)/len(ks):.1f}; sweep wall time {wall:.1f} s", end="")
    if s == "iqn-ils":  # updates that left the feasible set and were projected back (one QP each)
        proj = [json.load(open(f"out/table1-{s}-{c}/row-{int(r['row']):02d}/summary.json"))["relaxation"]["projections"] for r in t]
        print(f"; projections per row {proj}", end="")
print()
PY
