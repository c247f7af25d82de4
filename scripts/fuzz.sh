#!/usr/bin/env bash
# CI: builds the libFuzzer targets of fuzz/ with clang++ (the libraries too,
# with ASan + UBSan, in build-asan: scripts/asan_build.sh) and runs each for a bounded time from its
# seed corpus (fuzz/corpus/NAME). A crash, a hang (-timeout), an input using
# too much memory (-rss_limit_mb) or a sanitizer report fails the run and
# leaves the input in the printed artifact path. ICPBENCH_FUZZ_SECONDS sets
# the time per target (default 30: six targets, about 3 minutes in all).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
targets=(minibex spec car_track_log marina_log marina_map beacon_scene)
source scripts/asan_build.sh
asan_configure
# Only the fuzzers and the libraries they link.
cmake --build build-asan -j"${ICPBENCH_JOBS:-2}" --target "${targets[@]/%/_fuzzer}"
seconds=${ICPBENCH_FUZZ_SECONDS:-30}
# New inputs go to a scratch corpus, not into the repository's seeds.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for t in "${targets[@]}"; do
  mkdir -p "$work/$t"
  echo "icpbench: fuzzing $t for $seconds s"
  # timeout: libFuzzer's own -timeout once failed to stop a hung input
  # (CI stalled past its limit); this fails the target instead.
  if ! timeout --kill-after=10 $((seconds + 120)) "build-asan/fuzz/${t}_fuzzer" -max_total_time="$seconds" \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/$t-" \
      "$work/$t" "fuzz/corpus/$t" 2>"$work/$t.log"; then
    tail -n 60 "$work/$t.log"
    for a in "$work/$t"-*; do
      [ -e "$a" ] && { echo "icpbench: $t failed on $a:"; od -c "$a" | head -n 20; }
    done
    exit 1
  fi
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+.*DONE)" "$work/$t.log" || true
done
