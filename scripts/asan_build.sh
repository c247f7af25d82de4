# Sourced by scripts/fuzz.sh and scripts/sanitize.sh: one clang++ build with
# AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's coverage
# instrumentation (-fsanitize=fuzzer-no-link) in build-asan/, shared by the
# fuzzers and the test suite so CI compiles the project once under the
# sanitizers. -O1 -g: fast enough to run the tests, with usable stacks; no
# benchmarks (they test speed, not correctness). Without MPI: Open MPI's
# runtime leaks by design (LSan would report it), and CI so builds and tests
# an MPI-less icpbench too.
source scripts/ccache.sh
asan_configure() {
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${ccache_args[@]}" \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -DNDEBUG" \
    -DICPBENCH_SANITIZE=ON -DICPBENCH_FUZZ=ON -DICPBENCH_BUILD_BENCHMARKS=OFF -DICPBENCH_MPI=OFF >/dev/null
}
# halt_on_error: UBSan stops at its first report (and fails what ran it).
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
