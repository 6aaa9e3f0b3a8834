#!/usr/bin/env bash
# This machine's memory bandwidth in one process and in two at once: the ceiling of
# the speed-up that two MPI ranks can bring to a sparse solve, whose products and
# smoothers are bandwidth-bound (docs/performance.md "PETSc", several ranks).
# A STREAM-like triad c = a + 3 b over three 320 MB arrays, ten times.
#   bench/memory_bandwidth.sh
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/triad.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
int main(void) {
  const size_t n = 40000000;
  double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8);
  if (!a || !b || !c) return 1;
  for (size_t i = 0; i < n; i++) a[i] = 1, b[i] = 2, c[i] = 0;
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (int r = 0; r < 10; r++)
    for (size_t i = 0; i < n; i++) c[i] = a[i] + 3.0 * b[i];
  clock_gettime(CLOCK_MONOTONIC, &t1);
  const double s = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
  printf("%.2f GB/s%s\n", 10.0 * 3 * n * 8 / s / 1e9, c[7] == 7 ? "" : " (wrong)");
  return 0;
}
C
cc -O2 "$work/triad.c" -o "$work/triad"
echo "one process:"
"$work/triad"
echo "two at once:"
"$work/triad" & "$work/triad"
wait
