#!/usr/bin/env bash
# Measures the results store's size and write rate for a sweep of many
# short runs: RUNS runs of STEPS car-track steps (HC4, w = 2, so the solver
# costs little and the store's writes dominate), with record: steps and with
# record: runs. Prints the median of REPS repetitions: bytes per step row
# (the store file over the step rows), step rows per second (over the whole
# `icpbench run`, solving included) and the wall time.
#   bash scripts/bench_store.sh [RUNS [STEPS [REPS [JOBS]]]]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-40}
steps=${2:-2000}
reps=${3:-3}
jobs=${4:-$(nproc)}
bin=${ICPBENCH:-build/icpbench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

for record in steps runs; do
  spec="$work/store_$record.yaml"
  cat >"$spec" <<YAML
record: $record
repetitions: $runs
algorithms: [hc4]
problems: [{name: car-track, params: {steps: $steps, w: 2}}]
YAML
  : >"$work/wall" ; : >"$work/bytes" ; : >"$work/rate"
  for ((i = 0; i < reps; ++i)); do
    out="$work/out_${record}_$i"
    start=$(date +%s%N)
    "$bin" run "$spec" --out "$out" --jobs "$jobs" >/dev/null 2>&1
    end=$(date +%s%N)
    wall=$(awk -v ns=$((end - start)) 'BEGIN {print ns / 1e9}')
    rows=$(sqlite3 "$out/results.sqlite" 'SELECT count(*) FROM steps')
    bytes=$(stat -c %s "$out/results.sqlite")
    echo "$wall" >>"$work/wall"
    if [ "$rows" -gt 0 ]; then
      awk -v b="$bytes" -v r="$rows" 'BEGIN {print b / r}' >>"$work/bytes"
      awk -v w="$wall" -v r="$rows" 'BEGIN {print r / w}' >>"$work/rate"
    else
      echo "$bytes" >>"$work/bytes"
    fi
  done
  if [ "$record" = steps ]; then
    printf 'record: steps: %d runs x %d steps, --jobs %d: %.1f bytes per step row, %.0f step rows/s, %.2f s (median of %d)\n' \
      "$runs" "$steps" "$jobs" "$(median <"$work/bytes")" "$(median <"$work/rate")" "$(median <"$work/wall")" "$reps"
  else
    printf 'record: runs:  %d runs x %d steps, --jobs %d: store %d bytes, %.2f s (median of %d)\n' \
      "$runs" "$steps" "$jobs" "$(median <"$work/bytes")" "$(median <"$work/wall")" "$reps"
  fi
done
