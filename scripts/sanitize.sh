#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer, in the
# instrumented clang++ build the fuzzers share (build-asan:
# scripts/asan_build.sh). `--ci` builds and runs CI's part of it (below);
# without it, everything.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
source scripts/asan_build.sh
asan_configure
# handle_segv=0: the fault-injection test (runner_test FaultsAreRecorded...)
# raises SIGSEGV in a worker and expects the harness to record "signal 11";
# ASan's own SEGV handler would turn it into an exit code. handle_abort=0 is
# ASan's default, kept explicit for the abort mode.
# exitcode=86: a sanitizer report in a forked worker makes it exit 86, which
# the harness records as a failed run ("worker exited with code 86") and the
# test expecting "ok" fails on (RunnerTest.ASanReportInAWorkerFailsItsRun).
# Leak checking stays on: the forked workers leave by _exit, which LSan
# never checks, so only the test processes and the icpbench commands the
# CLI tests start are checked.
export ASAN_OPTIONS="handle_segv=0:handle_abort=0:exitcode=86:strict_string_checks=1:detect_stack_use_after_return=1"
# Left out everywhere: the MPFR oracle suites (Oracle: 1e5 samples each, over
# 3 minutes under ASan; the Release suite runs them) and the simulator tests
# that pin doubles bit for bit under Release (FirstRowsForSeed1AreFixed,
# ShippedLogIsTheSimulatorsDrive of car-track, FirstDomainsForSeed1AreFixed
# of chain: -O1 contracts to FMA differently, so they differ without a
# report). ICPBENCH_ASAN_EXCLUDE="" runs them too.
exclude="${ICPBENCH_ASAN_EXCLUDE-Oracle|FirstRowsForSeed1AreFixed|ShippedLogIsTheSimulatorsDrive|FirstDomainsForSeed1AreFixed}"
if [ "${1:-}" = "--ci" ]; then
  # CI's part (docs/testing.md): the test programs of the
  # code that parses, indexes into buffers, allocates or forks (parsers,
  # tape, pavings, grids and images, store, runner, problems, the window
  # adapter, the particle filter, the accumulator), within CI's 30 minutes;
  # the interval arithmetic and the other algorithms' tests, the
  # suites that need the icpbench binary (process handling, CLI, paper), the
  # end-to-end ones (soundness, ordering, golden, lap, relaxed, estimators,
  # plugin) and the report, plots and papers run under the sanitizers with a
  # plain `bash scripts/sanitize.sh`.
  programs=(
    minibex_parser tape params paving accumulate image_contractor relaxed_intersection
    metrics results_store spec runner shard
    car_track marina_sonar chain line_intersection beacon_ranges minibex_file feature_log
    indoor_landmarks landmark_metrics association_metrics belief_association
    window_estimator particle_filter accumulator
  )
  cmake --build build-asan -j"${ICPBENCH_JOBS:-2}" --target "${programs[@]/%/_test}"
  regex="^($(IFS='|'; echo "${programs[*]}"))\."
  ctest --test-dir build-asan --output-on-failure --timeout 900 -j"${ICPBENCH_JOBS:-2}" -R "$regex" ${exclude:+-E "$exclude"}
else
  cmake --build build-asan -j"${ICPBENCH_JOBS:-2}"
  ctest --test-dir build-asan --output-on-failure --timeout 900 -j"${ICPBENCH_JOBS:-2}" ${exclude:+-E "$exclude"}
fi
