#!/usr/bin/env bash
# q-relaxed against the reference fixpoint it is tested against (IBEX's
# CtcFixPoint(CtcQInter) written plainly), on the 48 measurement sets of
# tests/q_relaxed_cases.h: runs bench/q_relaxed_benchmark.cc and prints, from
# the CPU time per solve, the median over the sets of the reference's time
# over q-relaxed's (the speed-up), its range, and each side's median time.
# Each benchmark runs 5 times, interleaved in random order, and its median
# is kept: this machine's speed drifts by up to 2x over minutes, which
# back-to-back runs of one side then the other turned into the ratio.
# The target (issue 35): a median speed-up of at least 10.
set -euo pipefail
cd "$(dirname "$0")/.."
ICPBENCH_JOBS=${ICPBENCH_JOBS:-1} bash scripts/build.sh >/dev/null
./build/bench/q_relaxed_benchmark --benchmark_min_time="${1:-0.05}" --benchmark_repetitions=5 \
  --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
  awk -F, 'NR > 1 && $1 ~ /_median"$/ {
      gsub(/"/, "", $1); sub(/_median$/, "", $1); split($1, name, "/")
      if (name[1] == "BM_QRelaxed") ours[name[2]] = $4; else reference[name[2]] = $4
    }
    function median(v, n,   i, j, t) {
      for (i = 2; i <= n; ++i) for (j = i; j > 1 && v[j - 1] > v[j]; --j) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
      return (n % 2) ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
    }
    END {
      n = 0
      for (k in ours) { ++n; r[n] = reference[k] / ours[k]; a[n] = ours[k]; b[n] = reference[k] }
      printf "sets: %d\nq-relaxed: median %.1f us per solve\nreference fixpoint: median %.1f us per solve\n", n, median(a, n), median(b, n)
      m = median(r, n)
      printf "speed-up (reference / q-relaxed), median over the sets: %.1f (from %.1f to %.1f)\n", m, r[1], r[n]
    }'
