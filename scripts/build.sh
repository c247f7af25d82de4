#!/usr/bin/env bash
# Configures and builds icpbench (Release) into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${ccache_args[@]}" >/dev/null
cmake --build build -j"${ICPBENCH_JOBS:-2}"
