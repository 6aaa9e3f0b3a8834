#!/usr/bin/env bash
# Which lines and branches of src/ and app/ only the studies run (tests/CMakeLists.txt's
# FSICONTACT_STUDIES, ctest label "study"): the instrumented build runs the suite without
# them, so anything listed here would go unchecked by the sanitizers. Builds the suite
# with clang's source coverage in BUILD (default build-coverage), runs ctest -L unit and
# ctest -L study with separate profiles, and prints what the second covers and the first
# does not. Prints "only the studies: 0 lines, 0 branch outcomes" when none.
#   scripts/study-coverage.sh [BUILD]        (about 8 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=$(realpath -m "${1:-build-coverage}")
tool() { command -v "$1" || command -v "$1-14" || { echo "study-coverage: $1 not found (Debian llvm-14)" >&2; exit 2; }; }
profdata=$(tool llvm-profdata)
cov=$(tool llvm-cov)

if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S . -B "$build" $(command -v ninja > /dev/null && echo -G Ninja) -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=Coverage -DFSICONTACT_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="-O1 -fprofile-instr-generate -fcoverage-mapping" \
    -DCMAKE_EXE_LINKER_FLAGS=-fprofile-instr-generate -DCMAKE_MODULE_LINKER_FLAGS=-fprofile-instr-generate > /dev/null
fi
cmake --build "$build" -j "$(nproc)"

for label in unit study; do
  rm -rf "$build/profiles-$label"
  mkdir -p "$build/profiles-$label"
  # %4m: each binary's profile merged online into four files (600 processes otherwise).
  (cd "$build" && LLVM_PROFILE_FILE="$build/profiles-$label/p-%4m.profraw" \
    ctest -j "$(nproc)" -L "$label" > "ctest-$label.log") || { echo "study-coverage: ctest -L $label failed ($build/ctest-$label.log)" >&2; exit 1; }
  "$profdata" merge -o "$build/$label.profdata" "$build/profiles-$label"/*.profraw
  "$cov" export -format=lcov -instr-profile="$build/$label.profdata" "$build/tests/fsicontact_tests" \
    -object "$build/app/fsicontact" -object "$build/lib/fsicontact/libfsicontact_gmsh.so" > "$build/$label.lcov" 2> /dev/null
done

# lcov: SF:<file>, DA:<line>,<count>, BRDA:<line>,<block>,<branch>,<count or ->.
awk -v root="$root/" '
  FNR == 1 { pass++ }
  /^SF:/ { file = substr($0, 4); ours = index(file, root "src/") == 1 || index(file, root "app/") == 1; sub(root, "", file) }
  !ours { next }
  /^DA:/ { split(substr($0, 4), f, ","); key = file ":" f[1]; if (f[2] > 0) hit[pass, "line", key] = 1; lines[key] = 1 }
  /^BRDA:/ { split(substr($0, 6), f, ","); key = file ":" f[1] " block " f[2] " branch " f[3]
             if (f[4] != "-" && f[4] > 0) hit[pass, "branch", key] = 1; branches[key] = 1 }
  END {
    for (k in lines) if (hit[2, "line", k] && !hit[1, "line", k]) { print "  line   " k; nl++ }
    for (k in branches) if (hit[2, "branch", k] && !hit[1, "branch", k]) { print "  branch " k; nb++ }
    printf "only the studies: %d lines, %d branch outcomes\n", nl, nb
    exit (nl + nb > 0)
  }' "$build/unit.lcov" "$build/study.lcov"
