#!/usr/bin/env bash
# Measures the harness's parallel speedup on this machine (a CPU-bound sweep
# with --jobs 1 and --jobs N, N = cores) and the µs per CSP of every
# algorithm at w = 20 (Google Benchmark). Prints a summary for the README.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
jobs=${ICPBENCH_JOBS:-$(nproc)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() {  # run JOBS OUT -> wall milliseconds
  local start end
  start=$(date +%s%N)
  ./build/icpbench run specs/speedup.yaml --out "$2" --jobs "$1" >/dev/null 2>&1
  end=$(date +%s%N)
  echo $(( (end - start) / 1000000 ))
}
t1=$(run 1 "$work/j1")
tn=$(run "$jobs" "$work/jn")
echo "harness speedup: 1 job ${t1} ms, ${jobs} jobs ${tn} ms, speedup $((t1 * 100 / tn / 100)).$(printf '%02d' $((t1 * 100 / tn % 100)))x"

echo "µs per CSP at w = 20 (car-track-shaped window, CPU time):"
./build/bench/algorithms_benchmark --benchmark_filter='w:20$' \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>/dev/null |
  awk '/_median/ {printf "  %-22s %10.1f us\n", $1, $4}'
