#!/bin/bash
# Whether a change makes the rectangle's step faster, on a host whose speed swings from one
# minute to the next: bench_mechanics rectangle of two builds at 1 thread each, side by side,
# one pinned to each core, then the cores swapped. Prints each run's end-state hash (equal
# hashes: the change kept the bits) and its two timings (1 thread, and "all" threads, which is
# 1 here). Compare the sums of a build's four timings. Takes about 5 minutes.
#   bench/paired_rectangle.sh OLD/bench/bench_mechanics NEW/bench/bench_mechanics
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BENCH_MECHANICS_A BENCH_MECHANICS_B" >&2
  exit 2
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in 1 2; do
  if [ "$round" = 1 ]; then cores=(0 1); else cores=(1 0); fi
  OMP_NUM_THREADS=1 taskset -c "${cores[0]}" "$1" rectangle >"$out/A.$round" 2>&1 &
  OMP_NUM_THREADS=1 taskset -c "${cores[1]}" "$2" rectangle >"$out/B.$round" 2>&1 &
  wait
  for build in A B; do
    echo "$build, round $round: $(grep -o 'state hash [0-9a-f]*): [0-9.]* s at 1 thread, [0-9.]* s' "$out/$build.$round")"
  done
done
