#!/bin/bash
# Whether a change makes the rectangle's step faster, on a host whose speed swings from one
# minute to the next: bench_mechanics rectangle of two builds at 1 thread each, side by side,
# one pinned to each core, then the cores swapped. Prints each run's two timings (1 thread,
# and "all" threads, which is 1 here) and end-state hash, then each build's sum of its four
# timings and whether the two ended in the same bits (a change meant to keep them must).
# Exits 1 when a run fails. Takes about 5 minutes.
#   bench/paired_rectangle.sh OLD/bench/bench_mechanics NEW/bench/bench_mechanics
set -euo pipefail
if [ $# -ne 2 ] || [ ! -x "$1" ] || [ ! -x "$2" ]; then
  echo "usage: $0 BENCH_MECHANICS_A BENCH_MECHANICS_B (two executables)" >&2
  exit 2
fi
out=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$out"' EXIT
line='state hash \([0-9a-f]*\)): \([0-9.]*\) s at 1 thread, \([0-9.]*\) s'
for round in 1 2; do
  if [ "$round" = 1 ]; then cores=(0 1); else cores=(1 0); fi
  OMP_NUM_THREADS=1 taskset -c "${cores[0]}" "$1" rectangle >"$out/A.$round" 2>&1 &
  pid_a=$!
  OMP_NUM_THREADS=1 taskset -c "${cores[1]}" "$2" rectangle >"$out/B.$round" 2>&1 &
  pid_b=$!
  for build in A B; do
    pid=pid_$(echo "$build" | tr AB ab)
    if ! wait "${!pid}" || ! grep -q "state hash" "$out/$build.$round"; then
      echo "$0: build $build, round $round failed:" >&2
      cat "$out/$build.$round" >&2
      exit 1
    fi
    sed -n "s/.*$line.*/$build, round $round: \2 s, \3 s, state hash \1/p" "$out/$build.$round" | tee -a "$out/summary"
  done
done
awk '{ sum[$1] += $4 + $6; hash[$1] = hash[$1] " " $10 }
     END { printf "A: %.2f s, B: %.2f s, B / A = %.3f; end states %s\n", sum["A,"], sum["B,"], sum["B,"] / sum["A,"],
                  (hash["A,"] == hash["B,"] ? "the same bits" : "different") }' "$out/summary"
