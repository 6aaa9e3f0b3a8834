#!/usr/bin/env bash
# The body-fitted check (docs/validation.md, "Body-fitted check"): the no-contact
# variant of §7.2 (cases/nocontact-bodyfitted.toml) on the same refined levels with
# fluid.method = "body-fitted", the penalised method at fixed ε = 1e-5, and the
# penalised method with ε following h² (ε = 0.02857 at hF = 0.02: the Brinkman layer
# sqrt(μ_F ε) = hF/2 on every level); then per level the values, the differences
# penalised − body-fitted and the observed order of each difference between levels.
#   bench/bodyfit_check.sh [LEVELS] [--coupled-only|--alone-only] [--reuse]
# LEVELS (default 5: hF = 0.02 … 0.00125, hS = 1.5 hF; ~8 min on 2 cores, 2.4 GB). A sixth level
# (hF = 0.000625) costs 8 min and 10 GB for the body-fitted run alone: run it by hand
# with `fsicontact run` (the command is in docs/validation.md).
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${FSICONTACT:-build/app/fsicontact}
LEVELS=${1:-5}
CASE=cases/nocontact-bodyfitted.toml
COMMON=(--levels "$LEVELS" --set fluid.h=0.02 --set structure.h=0.03 --set output.png=false --set output.vtu=false -q)
reuse=false; modes=(coupled alone)
for a in "$@"; do
  case $a in --reuse) reuse=true ;; --coupled-only) modes=(coupled) ;; --alone-only) modes=(alone) ;; esac
done
for mode in "${modes[@]}"; do
  extra=(); [[ $mode == alone ]] && extra=(--set coupling.max_iterations=0)
  for variant in body-fitted penalised penalised-h2; do
    out="out/bodyfit-check/$mode-$variant"
    [[ $reuse == true && -f $out/convergence.csv ]] && continue
    case $variant in
      body-fitted) sets=(--set fluid.method=body-fitted) ;;
      penalised) sets=() ;;
      penalised-h2) sets=(--set coupling.eps=0.02857 --set coupling.eps_rule=h^2) ;;
    esac
    nice "$BIN" converge "$CASE" "${COMMON[@]}" "${extra[@]}" "${sets[@]}" --out "$out" > /dev/null
  done
  python3 - "$mode" <<'PY'
import csv, math, sys
mode = sys.argv[1]
def rows(v): return list(csv.DictReader(open(f"out/bodyfit-check/{mode}-{v}/convergence.csv")))
bf = rows("body-fitted")
qs = [("structure_load_y", 1, "N/m")] if mode == "alone" else \
     [("max_displacement", 1e3, "mm"), ("tip_displacement", 1e3, "mm"), ("structure_load_x", 1, "N/m"), ("structure_load_y", 1, "N/m")]
for variant in ("penalised", "penalised-h2"):
    pen = rows(variant)
    print(f"\n{mode}, {variant} − body-fitted")
    print("| level | hF | ε | " + " | ".join(f"{q} ({u}) pen / bf / diff / order" for q, _, u in qs) + " |")
    print("|" + "---|" * (3 + len(qs)))
    prev = {}
    for p, b in zip(pen, bf):
        cells = []
        for q, k, _ in qs:
            a, c = float(p[q]) * k, float(b[q]) * k
            d = a - c
            order = f"{math.log2(abs(prev[q] / d)):.2f}" if q in prev and d and prev[q] else "–"
            prev[q] = d
            cells.append(f"{a:.4f} / {c:.4f} / {d:+.4f} / {order}")
        print(f"| {p['level']} | {float(p['fluid_h']):g} | {float(p['eps']):.3g} | " + " | ".join(cells) + " |")
PY
done
