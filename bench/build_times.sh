#!/usr/bin/env bash
# The build's time from scratch under each combination of its speed-ups
# (docs/performance.md, "Build and test budgets"): for each configuration, a fresh
# Release build directory, then the program (fsicontact and its Gmsh plugin: what
# make demo builds) and the tests (what make test adds), each timed; the table goes to
# stdout. ccache is switched off for the measurement.
#   bench/build_times.sh [--out DIR] [--jobs N] [CONFIG ...]
# CONFIG: plain, pch, unity, unity+pch (default: all four). About 20 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=out/build-times JOBS=$(nproc)
configs=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --out) OUT=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    plain|pch|unity|unity+pch) configs+=("$1"); shift ;;
    *) sed -n '2,8p' "$0" >&2; exit 2 ;;
  esac
done
((${#configs[@]})) || configs=(plain pch unity unity+pch)
generator=$(command -v ninja > /dev/null && echo "-G Ninja" || true)

seconds() { local t0=$(date +%s.%N); "$@" > /dev/null; awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }'; }

printf '| configuration | program (s) | tests (s) |\n|---|---|---|\n'
for c in "${configs[@]}"; do
  unity=OFF pch=OFF
  [[ $c == *unity* ]] && unity=ON
  [[ $c == *pch* ]] && pch=ON
  dir=$OUT/$c
  rm -rf "$dir"
  cmake -S . -B "$dir" $generator -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$unity \
    -DFSICONTACT_PCH=$pch -DCMAKE_CXX_COMPILER_LAUNCHER= -DFSICONTACT_BUILD_BENCH=OFF > /dev/null
  program=$(seconds cmake --build "$dir" -j "$JOBS" --target fsicontact)
  tests=$(seconds cmake --build "$dir" -j "$JOBS" --target fsicontact_tests)
  printf '| %s | %.0f | %.0f |\n' "$c" "$program" "$tests"
done
