#!/usr/bin/env bash
# Runs every row of the paper's Table 1 (cases/table1.csv) twice, with fsicontact and
# with the FreeFem++ implementation of the same algorithm (bench/freefem/fsi_contact.edp,
# P1b/P1 + UMFPACK, IPOPT through ff-Ipopt, as the paper's author did), each under
# /usr/bin/time -v, and prints a markdown table: iterations k and ||v||/eps (paper / ours
# / FreeFem++), wall time, speed-up, peak memory and mesh sizes. Also writes DIR/compare.csv.
# Each fsicontact run is one process that meshes, solves and writes its PNG figures and
# VTU files, as a user's run does (--no-outputs: summary.json and history.csv only).
#
#   bench/compare_freefem.sh [--rows 1,2,...] [--out DIR] [--same-mesh] [--no-outputs] [--report-only]
#
#   --rows       only these rows (1-based, in the order of cases/table1.csv)
#   --out        output directory (default out/compare-freefem)
#   --same-mesh  also run fsicontact on the FreeFem++ meshes (bench/freefem/export_gmsh.edp
#                writes them as .msh): separates mesh effects from algorithmic differences,
#                and adds a second table
#   --report-only  rebuild the tables from the outputs already in DIR, run nothing
#
# Environment: FSICONTACT (default build/app/fsicontact), FREEFEM (default FreeFem++),
# FF_LOADPATH (default /usr/lib/freefem++, where Debian puts ff-Ipopt.so).
# Needs: freefem++ and libfreefem++ (scripts/install-deps.sh --with-freefem), time, python3.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BIN=${FSICONTACT:-build/app/fsicontact}
FREEFEM=${FREEFEM:-FreeFem++}
export FF_LOADPATH=${FF_LOADPATH:-/usr/lib/freefem++}
ROWS="" OUT=out/compare-freefem SAME_MESH=0 REPORT_ONLY=0 OUTPUTS=true
usage() { echo "usage: $0 [--rows 1,2,...] [--out DIR] [--same-mesh] [--no-outputs] [--report-only]" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rows) [[ $# -ge 2 ]] || usage; ROWS=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || usage; OUT=$2; shift 2 ;;
    --same-mesh) SAME_MESH=1; shift ;;
    --no-outputs) OUTPUTS=false; shift ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) usage ;;
  esac
done
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

if [[ $REPORT_ONLY -eq 0 ]]; then
  if ! command -v "$FREEFEM" > /dev/null; then
    echo "compare_freefem.sh: FreeFem++ is not installed ($FREEFEM not found)." >&2
    echo "  Install it with: scripts/install-deps.sh --with-freefem   (Debian packages freefem++ libfreefem++)" >&2
    exit 2
  fi
  if [[ ! -e $FF_LOADPATH/ff-Ipopt.so ]]; then
    echo "compare_freefem.sh: no ff-Ipopt.so in FF_LOADPATH=$FF_LOADPATH (Debian's libfreefem++ puts it in /usr/lib/freefem++)." >&2
    echo "  Install it with: scripts/install-deps.sh --with-freefem" >&2
    exit 2
  fi
  [[ -x $BIN ]] || { echo "compare_freefem.sh: no fsicontact binary at $BIN: build first (make build) or set FSICONTACT" >&2; exit 2; }
  [[ -x /usr/bin/time ]] || { echo "compare_freefem.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
  command -v python3 > /dev/null || { echo "compare_freefem.sh: needs python3" >&2; exit 2; }
  BIN=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")
  EDP=$ROOT/bench/freefem/fsi_contact.edp

  n=0
  while IFS=, read -r eps omega hF hS _; do
    n=$((n + 1))
    if [[ -n $ROWS ]] && [[ ",$ROWS," != *",$n,"* ]]; then continue; fi
    nn=$(printf %02d "$n")
    echo "row $n: eps=$eps omega=$omega hF=$hF hS=$hS" >&2
    set +e
    # (a) ours
    /usr/bin/time -v -o "$OUT/ours-row-$nn.time" "$BIN" run cases/paper-7.2.toml -q \
      --set coupling.eps="$eps" --set coupling.omega="$omega" --set fluid.h="$hF" --set structure.h="$hS" \
      --set output.png=$OUTPUTS --set output.vtu=$OUTPUTS --out "$OUT/ours-row-$nn" \
      > "$OUT/ours-row-$nn.log" 2>&1
    echo "  ours: exit $? ($(tail -c 300 "$OUT/ours-row-$nn.log" | tr '\n' ' ' | cut -c1-160))" >&2
    # (b) FreeFem++ (run inside OUT: IPOPT reads an ipopt.opt from the working directory)
    (cd "$OUT" && /usr/bin/time -v -o "freefem-row-$nn.time" "$FREEFEM" -nw -v 0 "$EDP" \
      -eps "$eps" -omega "$omega" -hF "$hF" -hS "$hS" -tol 1e-4 -maxit 100 -verbose 1 > "freefem-row-$nn.log" 2>&1)
    echo "  FreeFem++: exit $? ($(grep -h '^RESULT' "$OUT/freefem-row-$nn.log" | cut -c1-160))" >&2
    # (c) ours on the FreeFem++ meshes
    if [[ $SAME_MESH -eq 1 ]]; then
      mkdir -p "$OUT/meshes"
      (cd "$OUT" && "$FREEFEM" -nw -v 0 "$ROOT/bench/freefem/export_gmsh.edp" -hF "$hF" -hS "$hS" \
        -out "meshes/row-$nn" > "meshes/row-$nn.log" 2>&1)
      /usr/bin/time -v -o "$OUT/ours-ffmesh-row-$nn.time" "$BIN" run cases/paper-7.2.toml -q \
        --set coupling.eps="$eps" --set coupling.omega="$omega" \
        --set fluid.mesh="$OUT/meshes/row-$nn-fluid.msh" --set structure.mesh="$OUT/meshes/row-$nn-structure.msh" \
        --set output.png=false --set output.vtu=false --out "$OUT/ours-ffmesh-row-$nn" \
        > "$OUT/ours-ffmesh-row-$nn.log" 2>&1
      echo "  ours on the FreeFem++ meshes: exit $?" >&2
    fi
    set -e
  done < <(grep -v '^#' cases/table1.csv | tail -n +2)
fi

python3 - "$OUT" "$ROOT/cases/table1.csv" "$ROWS" <<'PY'
import csv, json, os, re, sys

out, table, rows_arg = sys.argv[1:]
wanted = {int(r) for r in rows_arg.split(",") if r.strip()} if rows_arg else None

def read_time(path):
    """wall seconds and peak RSS (MB) from /usr/bin/time -v, or (None, None)."""
    wall = peak = None
    try:
        for line in open(path):
            if "Elapsed (wall clock)" in line:
                parts = [float(p) for p in line.rsplit(": ", 1)[1].strip().split(":")]
                wall = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
            elif "Maximum resident set size" in line:
                peak = int(line.rsplit(": ", 1)[1]) / 1024
    except OSError:
        pass
    return wall, peak

def read_ours(d):
    try:
        j = json.load(open(os.path.join(d, "summary.json")))
    except (OSError, ValueError):
        return None
    return {"iterations": j["iterations"], "increment": j.get("final_increment_l2"),
            "vnorm": j["fluid_velocity_l2_in_structure"],
            "v_over_eps": j["fluid_velocity_l2_in_structure_over_eps"],
            "max_displacement": j["max_displacement"], "converged": bool(j["converged"]),
            "fluid_triangles": j["mesh"]["fluid"]["triangles"],
            "structure_triangles": j["mesh"]["structure"]["triangles"],
            "contact_nodes": j.get("contact", {}).get("active_nodes"),
            "warning": "convergence_warning" in j}

def read_freefem(path):
    res = {}
    try:
        for line in open(path):
            if line.startswith(("RESULT ", "TIMES ", "CONTACT ")):
                tag = line.split()[0].lower()
                for k, v in re.findall(r"(\w+)=(\S+)", line):
                    res[k if tag == "result" else tag + "_" + k] = float(v)
    except OSError:
        return None
    if "iterations" not in res:
        return None
    return {"iterations": int(res["iterations"]), "increment": res["increment"], "vnorm": res["vnorm"],
            "v_over_eps": res["vnorm_over_eps"], "vnorm_fine": res.get("vnorm_fine"),
            "max_displacement": res["max_displacement"], "converged": res["converged"] == 1,
            "fluid_triangles": int(res["fluid_triangles"]), "structure_triangles": int(res["structure_triangles"]),
            "contact_nodes": int(res["contact_active"]), "t_fluid": res.get("times_fluid"),
            "t_structure": res.get("times_structure"), "ipopt_failures": res.get("contact_ipopt_failures")}

lines = [l for l in open(table) if not l.startswith("#")]
rows = list(csv.DictReader(lines))
records = []
for n, row in enumerate(rows, 1):
    if wanted is not None and n not in wanted:
        continue
    nn = f"{n:02d}"
    rec = {"row": n, "eps": row["coupling.eps"], "omega": row["coupling.omega"], "hF": row["fluid.h"],
           "hS": row["structure.h"], "paper_k": int(row["paper.k"]), "paper_v_over_eps": float(row["paper.v_over_eps"]),
           "ours": read_ours(os.path.join(out, f"ours-row-{nn}")),
           "ff": read_freefem(os.path.join(out, f"freefem-row-{nn}.log")),
           "same": read_ours(os.path.join(out, f"ours-ffmesh-row-{nn}"))}
    rec["ours_wall"], rec["ours_peak"] = read_time(os.path.join(out, f"ours-row-{nn}.time"))
    rec["ff_wall"], rec["ff_peak"] = read_time(os.path.join(out, f"freefem-row-{nn}.time"))
    rec["same_wall"], rec["same_peak"] = read_time(os.path.join(out, f"ours-ffmesh-row-{nn}.time"))
    if rec["ours"] is None and rec["ff"] is None:
        continue
    records.append(rec)

def k(r):  # the paper's counter: iterations - 1; '*' = iteration limit; '†' = stop flagged as a chance dip
    if r is None:
        return "-"
    return f"{r['iterations'] - 1}{'' if r['converged'] else '*'}{'†' if r.get('warning') else ''}"
def g(x, fmt="{:.4g}"):
    return "-" if x is None else fmt.format(x)
def get(r, key):
    return None if r is None else r.get(key)
def vff(r):  # FreeFem++'s ||v||/eps: int2d's default rule, (converged quadrature)
    f = r["ff"]
    if f is None:
        return "-"
    fine = f.get("vnorm_fine")
    return f"{f['v_over_eps']:.1f}" + ("" if fine is None else f" ({fine / float(r['eps']):.1f})")

print("| row | ε | ω | hF | hS | k paper | k ours | k FreeFem++ | ‖v‖/ε paper | ‖v‖/ε ours | ‖v‖/ε FreeFem++ "
      "| max \\|u\\| m ours / FF | wall s ours | wall s FreeFem++ | speed-up | peak MB ours | peak MB FreeFem++ "
      "| fluid triangles ours / FF | structure triangles ours / FF |")
print("|" + "---|" * 19)
for r in records:
    o, f = r["ours"], r["ff"]
    speed = r["ff_wall"] / r["ours_wall"] if r["ours_wall"] and r["ff_wall"] else None
    print(f"| {r['row']} | {r['eps']} | {r['omega']} | {r['hF']} | {r['hS']} | {r['paper_k']} | {k(o)} | {k(f)} "
          f"| {r['paper_v_over_eps']:.6g} | {g(get(o, 'v_over_eps'), '{:.1f}')} | {vff(r)} "
          f"| {g(get(o, 'max_displacement'), '{:.4f}')} / {g(get(f, 'max_displacement'), '{:.4f}')} "
          f"| {g(r['ours_wall'], '{:.2f}')} | {g(r['ff_wall'], '{:.2f}')} | {g(speed, '{:.1f}×')} "
          f"| {g(r['ours_peak'], '{:.0f}')} | {g(r['ff_peak'], '{:.0f}')} "
          f"| {g(get(o, 'fluid_triangles'), '{}')} / {g(get(f, 'fluid_triangles'), '{}')} "
          f"| {g(get(o, 'structure_triangles'), '{}')} / {g(get(f, 'structure_triangles'), '{}')} |")
print("\nk = iterations − 1 (the paper's counter); * = stopped at the iteration limit (100 passes), not converged; "
      "† = fsicontact stopped below tol but flagged the stop as a chance dip (convergence_warning in summary.json). "
      "‖v‖/ε FreeFem++: with int2d's default 7-point rule on the deformed structure mesh (what the paper's "
      "FreeFem++ script would compute), in parentheses with a converged quadrature (each triangle split in 64, "
      "15-point rule); v_h is not smooth there, so the quadrature matters.")

if any(r["same"] for r in records):
    print("\nSame meshes (fsicontact run on the FreeFem++ meshes, exported with bench/freefem/export_gmsh.edp):\n")
    print("| row | k ours | k FreeFem++ | last increment ours | last increment FreeFem++ | ‖v‖/ε ours "
          "| ‖v‖/ε FreeFem++ (7-pt rule) | ‖v‖/ε FreeFem++ (converged quadrature) | max displacement ours "
          "| max displacement FreeFem++ | contact nodes ours / FF | wall s ours | wall s FreeFem++ | speed-up |")
    print("|" + "---|" * 14)
    for r in records:
        s, f = r["same"], r["ff"]
        fine = get(f, "vnorm_fine")
        speed = r["ff_wall"] / r["same_wall"] if r["same_wall"] and r["ff_wall"] else None
        print(f"| {r['row']} | {k(s)} | {k(f)} | {g(get(s, 'increment'))} | {g(get(f, 'increment'))} "
              f"| {g(get(s, 'v_over_eps'), '{:.1f}')} | {g(get(f, 'v_over_eps'), '{:.1f}')} "
              f"| {g(None if fine is None else fine / float(r['eps']), '{:.1f}')} "
              f"| {g(get(s, 'max_displacement'), '{:.5f}')} | {g(get(f, 'max_displacement'), '{:.5f}')} "
              f"| {g(get(s, 'contact_nodes'), '{}')} / {g(get(f, 'contact_nodes'), '{}')} "
              f"| {g(r['same_wall'], '{:.2f}')} | {g(r['ff_wall'], '{:.2f}')} | {g(speed, '{:.1f}×')} |")

fields = ["row", "eps", "omega", "hF", "hS", "paper_k", "paper_v_over_eps"]
cols = ["iterations", "converged", "increment", "vnorm", "v_over_eps", "max_displacement", "contact_nodes",
        "fluid_triangles", "structure_triangles"]
header = fields + [f"ours_{c}" for c in cols] + ["ours_wall_s", "ours_peak_MB"] \
    + [f"freefem_{c}" for c in cols + ["vnorm_fine", "t_fluid", "t_structure", "ipopt_failures"]] \
    + ["freefem_wall_s", "freefem_peak_MB", "speedup"] \
    + [f"ours_ffmesh_{c}" for c in cols] + ["ours_ffmesh_wall_s", "ours_ffmesh_peak_MB"]
with open(os.path.join(out, "compare.csv"), "w", newline="") as fh:
    w = csv.writer(fh)
    w.writerow(header)
    for r in records:
        o, f, s = r["ours"] or {}, r["ff"] or {}, r["same"] or {}
        speed = r["ff_wall"] / r["ours_wall"] if r["ours_wall"] and r["ff_wall"] else ""
        w.writerow([r[x] for x in fields] + [o.get(c, "") for c in cols] + [r["ours_wall"], r["ours_peak"]]
                   + [f.get(c, "") for c in cols + ["vnorm_fine", "t_fluid", "t_structure", "ipopt_failures"]]
                   + [r["ff_wall"], r["ff_peak"], speed] + [s.get(c, "") for c in cols]
                   + [r["same_wall"] or "", r["same_peak"] or ""])
print(f"\n(written {os.path.join(out, 'compare.csv')})", file=sys.stderr)
PY
