#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (`make fuzz`) for RUNS executions each, from
# the committed seeds in tests/fuzz/corpus/NAME/, and fails on any finding or on a target
# that the time guard stopped short of RUNS.
#   tests/fuzz/run_fuzz.sh BUILD_DIR RUNS MAX_SECONDS_PER_TARGET
# New inputs the fuzzer finds go to BUILD_DIR/corpus/NAME/ (the committed seeds are never
# written), findings to BUILD_DIR/findings/NAME/, each run's output to BUILD_DIR/fuzz_NAME.log.
set -uo pipefail
build=$1 runs=$2 max_time=$3
here=$(cd "$(dirname "$0")" && pwd)
status=0
for source in "$here"/fuzz_*.cpp; do
  name=$(basename "$source" .cpp)
  name=${name#fuzz_}
  seeds=$here/corpus/$name
  [ -d "$seeds" ] || { echo "fuzz_$name: no seed corpus $seeds" >&2; status=1; continue; }
  mkdir -p "$build/corpus/$name" "$build/findings/$name"
  dict=()
  [ -f "$here/$name.dict" ] && dict=(-dict="$here/$name.dict")
  log=$build/fuzz_$name.log
  # -timeout: one input may take 10 s at most (a hang); -rss_limit_mb: memory (also the
  # largest single allocation); -max_total_time: the guard on the whole run.
  nice "$build/fuzz_$name" -runs="$runs" -max_total_time="$max_time" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/findings/$name/" "${dict[@]}" \
    "$build/corpus/$name" "$seeds" > "$log" 2>&1
  code=$?
  executed=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  seconds=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\2/p' "$log" | tail -1)
  if [ "$code" -ne 0 ]; then
    echo "fuzz_$name: FINDING (exit $code); input in $build/findings/$name/, output in $log:"
    grep -E 'ERROR|runtime error|SUMMARY|Test unit written' "$log" | head -20 || tail -5 "$log"
    status=1
  elif [ -z "$executed" ] || [ "$executed" -lt "$runs" ]; then
    echo "fuzz_$name: the time guard ($max_time s) stopped it after ${executed:-0} of $runs runs; see $log"
    status=1
  else
    echo "fuzz_$name: $executed runs in $seconds s, no crash, hang, leak or sanitizer report"
  fi
done
exit $status
