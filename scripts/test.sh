#!/usr/bin/env bash
# The test command of the README: installs what is missing, builds, runs
# every test with ctest (unit, oracle, property, CLI, benchmark dry runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure --timeout 900 -j"${ICPBENCH_JOBS:-2}"
