#!/usr/bin/env bash
# This machine's memory bandwidth in one process and in two at once: the ceiling of
# the speed-up that two MPI ranks can bring to a sparse solve, whose products and
# smoothers are bandwidth-bound (docs/performance.md "PETSc", several ranks), and the
# cost of a page's first touch, which every new allocation pays (docs/performance.md,
# "Huge pages, and the set-up on two ranks").
# A STREAM-like triad c = a + 3 b over three 320 MB arrays: the first pass over c
# (whose pages the kernel maps as it is first written) timed alone, then the median of
# 20 passes over memory already mapped. Until issue 32's eighth part this script timed
# the first pass with the others, 10 in all, and called the sum bandwidth: 7.4 GB/s,
# and 1.68x for two processes, where the bandwidth is 3-4 times that and scales 1.9x.
#   bench/memory_bandwidth.sh
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/triad.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
static int by_value(const void* x, const void* y) {
  const double a = *(const double*)x, b = *(const double*)y;
  return (a > b) - (a < b);
}
int main(void) {
  const size_t n = 40000000;
  enum { passes = 20 };
  double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8), t[passes];
  if (!a || !b || !c) return 1;
  for (size_t i = 0; i < n; i++) a[i] = 1, b[i] = 2;
  double t0 = now();
  for (size_t i = 0; i < n; i++) c[i] = a[i] + 3.0 * b[i];
  const double first = now() - t0;
  for (int r = 0; r < passes; r++) {
    t0 = now();
    const double s = 3.0 + r * 1e-300;  /* each pass differs: none is optimised away */
    for (size_t i = 0; i < n; i++) c[i] = a[i] + s * b[i];
    t[r] = now() - t0;
  }
  qsort(t, passes, sizeof t[0], by_value);
  printf("%.1f GB/s; the first pass, c's pages mapped as it goes, %.2f s (%.2f ms a MiB)%s\n",
         3.0 * n * 8 / t[passes / 2] / 1e9, first, first / (n * 8 / 1048576.0) * 1e3,
         c[7] == 7 ? "" : " (wrong)");
  return 0;
}
C
cc -O2 "$work/triad.c" -o "$work/triad"
echo "one process:"
"$work/triad"
echo "two at once:"
"$work/triad" & "$work/triad"
wait
